// arnoldweb: the effect table. One row per optional effect of the kernels:
// its name (in summary.json and `check`), its feature bit (declared in its
// device header lib/device/effects/aw_fx_<name>.h, gathered for aw_params.h)
// and whether a scene asks for it. The planner compiles exactly the effects a
// scene asks for into its kernel.
// Adding an effect: its device header (lib/device/effects/: bit, hooks) and a
// row here (or its output row's key, which adds the row).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "arnoldweb/scene.hpp"

namespace arnoldweb::detail {

struct EffectRow {
  std::string name;
  std::uint32_t bit = 0;
  // null: only test code sets the bit, or the planner, or a switch of the output table
  bool (*asked)(const Scene& scene) = nullptr;
};

const std::vector<EffectRow>& effects();

// The feature mask of the effects `scene` asks for, with the bits its output
// switches ask for (switch_features, looked up before planning: lookups.hpp).
std::uint32_t features_of(const Scene& scene, std::uint32_t switch_bits);

}  // namespace arnoldweb::detail
