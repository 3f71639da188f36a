// arnoldweb explorer: the scene of a zoom a page asks for: the run's scene as run (same model,
// energy, method, step, averaging, seed, ...), its trajectories drawn in the region the page
// selected (ensemble.initial = "cap" or "box"), as many as the page chose, into its own output
// directory, without the run's panels; its map as fine as the page asks (a small region wants a
// finer map than the whole sphere's). Read back through the scene reader, so a zoom's scene
// is checked as any scene file is.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>

#include "arnoldweb/scene.hpp"

namespace arnoldweb::explorer {

// What a request got wrong (answered 400 with the message).
class BadRequest : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The region of a request body ({kind: "cap", center: [lon, lat], radius} or
// {kind: "box", lon: [a, b], lat: [c, d]}, degrees) as scene overrides; BadRequest naming the
// field otherwise.
std::vector<std::string> region_overrides(const nlohmann::json& region);

// The zoom's scene: `source` with the region, `trajectories`, the map's nside (0: the source's)
// and output.dir = out_dir. SceneError when the scene reader refuses it (a radius out of range,
// an nside that is not a power of two, ...).
Scene zoom_scene(const Scene& source, const nlohmann::json& region, std::uint64_t trajectories, int nside,
                 const std::string& out_dir);

}  // namespace arnoldweb::explorer
