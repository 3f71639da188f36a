// Two trajectories per work-item (AW_ITEMS = 2: what CUDA's -DAW_CUDA_PAIR=1
// compiles, kernels_cu/ensemble.cu), run here by the device core as scalar
// C++: every trajectory gets the same bits as with one per work-item (the
// scalar core), an odd count leaving the last pair half empty.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>

#include "arnoldweb/plan.hpp"
#include "aw_cpp_std.h"
#include "scalar_core.hpp"
#include "scalar_core_fold.hpp"
#include "support.hpp"

namespace core_items {
#define AW_ITEMS 2
#include "aw_ensemble.h"
#undef AW_ITEMS
}  // namespace core_items

#include "plan/plan_params.hpp"

using namespace arnoldweb;

TEST_SUITE("core") {
  TEST_CASE("two trajectories per work-item (AW_ITEMS = 2, CUDA's AW_CUDA_PAIR) give every trajectory the bits of one") {
    const Plan plan = make_plan(awtest::scene_from(R"(
      [model]
      energy = 15
      [ensemble]
      trajectories = 1001
      seed = 7
      [integrator]
      step = 0.01
      [run]
      average = 1  # 100 steps, a window
      duration = 2
      [observe]
      velocity_map = { nside = 8 }
      energy_error = { every = 0.5 }
      initial_states = true
      final_states = true
      trajectories = { ids = [0, 999, 1000], every = 0.5 }
    )", {}, "<items>"));
    const Result ref = awtest::run_scalar_core(plan);
    REQUIRE(ref.reals("final_states").size() == 1001 * AW_STATE_REALS);
    REQUIRE(ref.binned > 900);
    // a work-item per even trajectory, holding it and the next; the odd ones' calls do nothing
    auto pair = [](core_items::aw_config cfg, core_items::aw_lanes l, std::int64_t first, std::int64_t end,
                   const core_items::aw_rparams* rp, const core_items::aw_iparams* ip, core_items::aw_outputs out,
                   double* emax, double* esum) {
      *emax = *esum = 0;
      if (l.first % 2 == 0) core_items::aw_ensemble_item(cfg, l, first, end, rp, ip, out, emax, esum);
    };
    const auto* rp = reinterpret_cast<const core_items::aw_rparams*>(&detail::params(plan).reals);
    const auto* ip = reinterpret_cast<const core_items::aw_iparams*>(&detail::params(plan).ints);
    const Result r = awtest::scalar_detail::run<double, core_items::aw_rparams, core_items::aw_iparams,
                                                core_items::aw_outputs, core_items::aw_lanes, core_items::aw_config>(
        plan, rp, ip, pair);
    for (const char* kind : {"initial_states", "final_states", "trajectories"}) {
      CAPTURE(kind);
      CHECK(awtest::first_difference(r.reals(kind), ref.reals(kind)) == -1);
      CHECK(awtest::first_difference(r.ints(kind), ref.ints(kind)) == -1);
    }
    CHECK(r.map == ref.map);
    CHECK(r.binned == ref.binned);
    CHECK(r.flagged() == ref.flagged());
    CHECK(r.energy.max == ref.energy.max);
    CHECK(r.energy.log_hist == ref.energy.log_hist);
    // the sum of a pair's max|dE| is added to the others as one: equal to rounding
    CHECK(std::fabs(r.energy.mean - ref.energy.mean) <= 1e-12 * ref.energy.mean);
  }
}
