// arnoldweb: the kernels' parameter blocks on the host. The device header
// lib/device/aw_param_blocks.h is read twice, with `real` = double and float,
// so host and kernels share one definition of every field; make_plan fills
// the double block and a float kernel gets it converted element by element
// (every member of a block has one type, so a block is an array of it).
// Below the physics and the planner: a model fills its slots of the real
// block, the planner the rest.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "arnoldweb/precision.hpp"
#include "aw_params.h"

namespace arnoldweb::detail {

namespace kernel_double {
using real = double;
using aw_i64 = std::int64_t;
using aw_u32 = std::uint32_t;
#undef AW_PARAM_BLOCKS_H
#include "aw_param_blocks.h"
}  // namespace kernel_double

namespace kernel_float {
using real = float;
using aw_i64 = std::int64_t;
using aw_u32 = std::uint32_t;
#undef AW_PARAM_BLOCKS_H
#include "aw_param_blocks.h"
}  // namespace kernel_float
#undef AW_PARAM_BLOCKS_H  // a device core compiled later in the same file reads it again

using RealParams = kernel_double::aw_rparams;
using IntParams = kernel_double::aw_iparams;

// The layouts are arrays: no padding, and the float block is the double one halved.
static_assert(sizeof(RealParams) % sizeof(double) == 0, "aw_rparams holds reals only");
static_assert(sizeof(RealParams) == 2 * sizeof(kernel_float::aw_rparams), "aw_rparams: float layout");
static_assert(offsetof(RealParams, model) == 2 * offsetof(kernel_float::aw_rparams, model), "aw_rparams: offsets");
static_assert(sizeof(IntParams) % sizeof(std::int64_t) == 0, "aw_iparams holds 64-bit integers only");
static_assert(sizeof(IntParams) == sizeof(kernel_float::aw_iparams), "aw_iparams: one layout");

struct KernelParams {
  RealParams reals{};  // zero-initialised
  IntParams ints{};

  // The real block for a kernel computing in `precision`, as bytes.
  std::vector<unsigned char> real_bytes(Precision precision) const;
  std::size_t real_count() const { return sizeof(RealParams) / sizeof(double); }
};

}  // namespace arnoldweb::detail
