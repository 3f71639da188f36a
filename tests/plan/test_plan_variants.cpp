// The planner's variants of a plan (plan.hpp): with_step and with_trajectories
// give exactly the plan that planning the scene with that step or that number
// of trajectories gives (the accuracy pilot relies on it), and the output
// table's record layout follows the effects asked for.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "aw_params.h"
#include "physics/model_table.hpp"
#include "output_table/output_table.hpp"
#include "plan/plan_params.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

void check_same_plan(const Plan& a, const Plan& b) {
  CHECK(a.step == b.step);
  CHECK(a.steps_per_segment == b.steps_per_segment);
  CHECK(a.segments_per_window == b.segments_per_window);
  CHECK(a.windows == b.windows);
  CHECK(a.steps_per_trajectory == b.steps_per_trajectory);
  CHECK(a.trajectory_steps == b.trajectory_steps);
  CHECK(a.force_evaluations == b.force_evaluations);
  CHECK(a.guard.value == b.guard.value);
  CHECK(a.guard.safe_step == b.guard.safe_step);
  CHECK(a.guard.quantity == b.guard.quantity);
  CHECK(a.warnings == b.warnings);
  CHECK(a.kernel == b.kernel);
  const std::string ta = a.scene.to_toml(), tb = b.scene.to_toml();  // the values, not the provenance comments
  CHECK(ta.substr(ta.find("[model]")) == tb.substr(tb.find("[model]")));
  const detail::KernelParams &pa = detail::params(a), &pb = detail::params(b);
  CHECK(std::memcmp(&pa.reals, &pb.reals, sizeof pa.reals) == 0);
  CHECK(std::memcmp(&pa.ints, &pb.ints, sizeof pa.ints) == 0);
}

}  // namespace

TEST_SUITE("plan") {
  TEST_CASE("with_step and with_trajectories give the plans of the scene planned with that step or number") {
    for (const detail::ModelDescriptor& m : detail::models()) {
      if (!m.host) continue;  // the built-ins (the expression kind is a scene's own row)
      CAPTURE(m.name);
      const std::vector<std::string> sets = {awtest::set("model.kind", m.name), "model.energy=1.5",
                                             "integrator.method=\"pefrl\"", "integrator.allow_unsafe_step=true",
                                             "run.average=2", "run.duration=4", "observe.energy_error.every=1",
                                             "observe.final_states=true", "observe.fli=true"};
      const Plan base = make_plan(awtest::scene_from("", sets));
      for (double step : {0.05, 0.01, 1.0 / 128}) {
        std::vector<std::string> at = sets;
        at.push_back(awtest::set("integrator.step", step));
        check_same_plan(with_step(base, step), make_plan(awtest::scene_from("", at)));
      }
      std::vector<std::string> more = sets;
      more.push_back("ensemble.trajectories=12345");
      check_same_plan(with_trajectories(base, 12345), make_plan(awtest::scene_from("", more)));
    }
  }

  TEST_CASE("with_step refuses a step that does not divide the schedule, naming the key") {
    const Plan base = make_plan(awtest::scene_from("", {"run.average=1", "run.duration=1"}));
    CHECK_THROWS_AS(with_step(base, 0.3), SceneError);
  }

  TEST_CASE("the records: the output table's rows the effects ask for, laid out one after the other") {
    const Plan plain = make_plan(awtest::scene_from(""));
    CHECK(detail::params(plain).ints.rec_reals == 0);
    CHECK(detail::params(plain).ints.rec_ints == 0);
    const Plan all = make_plan(awtest::scene_from(
        "", {"observe.initial_states=true", "observe.final_states=true", "observe.fli=true"}));
    const detail::IntParams& ip = detail::params(all).ints;
    std::int64_t reals = 0, ints = 0;
    for (const detail::RecordOutput& row : detail::record_outputs()) {
      CAPTURE(row.name);
      CHECK((row.internal() || !row.datasets.empty()));
      if (!(all.kernel.features & row.feature)) continue;
      CHECK(ip.rec_col_r[row.slot] == reals);
      CHECK(ip.rec_col_i[row.slot] == ints);
      CHECK(ip.rec_width_r[row.slot] == row.reals(ip));
      CHECK(ip.rec_width_i[row.slot] == row.ints(ip));
      reals += row.reals(ip);
      ints += row.ints(ip);
      for (const detail::RecordDataset& d : row.datasets)  // every dataset within its row's columns
        CHECK(d.first + (d.count < 0 ? 0 : d.count) <= (d.integers ? row.ints(ip) : row.reals(ip)));
    }
    CHECK(ip.rec_reals == reals);
    CHECK(ip.rec_ints == ints);
    CHECK(reals > 0);
    // every name is an output of the table, and the table's slots are distinct
    std::vector<int> slots;
    for (const detail::RecordOutput& row : detail::record_outputs()) {
      CHECK(std::find(slots.begin(), slots.end(), row.slot) == slots.end());
      CHECK(row.slot < AW_OUT_SLOTS);
      slots.push_back(row.slot);
    }
    std::size_t reported = 0;
    for (const detail::RecordOutput& row : detail::record_outputs()) reported += row.internal() ? 0 : 1;
    CHECK(output_names().size() == reported);
  }

  TEST_CASE("output_fields names an output's real columns in column order (Python's record dtype)") {
    const std::vector<std::string> ind = output_fields("indicators");
    REQUIRE(ind.size() == static_cast<std::size_t>(AW_IND_REALS));
    CHECK(ind[AW_IND_FLI] == "fli");
    CHECK(ind[AW_IND_MEGNO] == "megno");
    CHECK(ind[AW_IND_MEGNO_LYAPUNOV] == "megno_lyapunov");
    CHECK(ind[AW_IND_LYAPUNOV] == "lyapunov");
    // an output whose real datasets span several columns is not named column by column
    CHECK(output_fields("final_states").empty());
    CHECK_THROWS_AS(output_fields("no_such_output"), std::invalid_argument);
  }
}

TEST_SUITE("plan") {
  // NVIDIA's OpenCL stopped kernels that reached past 2^31 bytes of the series
  // buffer (estimates.cpp): its launches keep the series below that, even where
  // ensemble.chunk asks for more; CUDA and other devices keep their budget.
  TEST_CASE("largest_chunk: the frequency series of a launch on NVIDIA's OpenCL stay below 2^31 bytes") {
    const std::string toml = R"(
      [ensemble]
      trajectories = 1500000
      [integrator]
      method = "yoshida6a"
      step = 0.02
      [run]
      duration = 50
      average = 50
      [observe]
      frequencies = { samples = 512, every = 0.04 }
    )";
    DeviceInfo gpu;
    gpu.backend = "opencl";
    gpu.name = "NVIDIA H200";
    gpu.vendor = "NVIDIA Corporation";
    gpu.memory = 140ull << 30;
    gpu.max_allocation = 35ull << 30;
    DeviceInfo cuda = gpu;
    cuda.backend = "cuda";
    for (const std::vector<std::string>& sets : {std::vector<std::string>{}, {"ensemble.chunk=200000"}}) {
      CAPTURE(sets.size());
      const Plan plan = make_plan(awtest::scene_from(toml, sets, "<chunk>"));
      const double series = static_cast<double>(detail::params(plan).ints.series_reals) * 8;
      const std::uint64_t m = largest_chunk(plan, gpu);
      CHECK(m > 30000);
      // the buffer holds whole blocks of AW_SERIES_BLOCK trajectories
      CHECK(static_cast<double>((m + AW_SERIES_BLOCK - 1) / AW_SERIES_BLOCK * AW_SERIES_BLOCK) * series < 2147483648.0);
      CHECK(largest_chunk(plan, cuda) > 100000);
    }
  }

  // A launch counts a pixel's windows in 32 bits: trajectories x windows binned per launch below
  // 2^32. A time-sliced launch bins one slice's windows, not the run's: Figure 4 at 10^7 T
  // (10^6 windows) in slices of 10240 T is one launch of its 32,768 trajectories per slice, where
  // the bound over the whole run cut it into launches of 4000 (a GPU a fraction full; issue 41).
  TEST_CASE("largest_chunk: a time slice's windows bound a sliced launch, the run's an unsliced one") {
    const std::string toml = R"(
      [ensemble]
      trajectories = 32768
      [integrator]
      method = "yoshida6a"
      step = 0.01
      [run]
      average = 10
      duration = 10000000
      [observe]
      energy_error = { every = 10 }
      final_states = true
    )";
    const Plan whole = make_plan(awtest::scene_from(toml, {}, "<fig4>"));
    CHECK(whole.windows == 1000000);
    CHECK(largest_chunk(whole) == 4000);
    const Plan sliced = make_plan(awtest::scene_from(toml, {"run.slice=10240"}, "<fig4>"));
    REQUIRE(sliced.slices == 977);
    CHECK(largest_chunk(sliced) == 32768);
    // long slices of many trajectories: the slice's windows, and one begun in the slice before
    const Plan many = make_plan(awtest::scene_from(toml, {"ensemble.trajectories=8000000", "run.slice=81920"}, "<fig4>"));
    CHECK(largest_chunk(many) == 4000000000ull / 8193);
    // a slice shorter than a window bins at most one window per launch
    const Plan thin = make_plan(awtest::scene_from(toml, {"run.slice=20", "run.average=100", "run.duration=200000"}, "<fig4>"));
    CHECK(largest_chunk(thin) == 32768);
  }
}
