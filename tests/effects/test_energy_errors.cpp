// observe.energy_errors (energy_errors.h5; docs/outputs.md): every trajectory's
// largest |E(t) - E(0)| over the energy samples, on every device present
// (ctest parity.cpu, .opencl, .cuda):
//  - each record is the value the energy histogram counted for its trajectory:
//    the histogram rebuilt from the records is the run's, bin for bin; the
//    binned trajectories' largest is the run's max|dE|;
//  - the same bits on every device, in chunks and in time slices;
//  - the key alone brings the energy samples it reads; without it, no record;
//  - over a grid (ctest output): energy_errors.h5 of the grid's shape and
//    energy_error.png.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "aw_params.h"
#include "h5_test_file.hpp"
#include "output/pictures.hpp"
#include "run_outputs.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

// 2000 trajectories x 400 steps of the default scene's method at a step large enough for errors to spread.
Scene errors_scene(const std::vector<std::string>& sets = {}) {
  return awtest::scene_from(R"(
    [model]
    energy = 15
    [ensemble]
    trajectories = 2000
    seed = 11
    [integrator]
    method = "sbab3c"
    step = 0.025
    [run]
    average = 5
    duration = 10
    [observe]
    velocity_map = { nside = 8 }
    energy_error = { every = 0.5 }
    final_states = true
    energy_errors = true
  )", sets, "<energy_errors>");
}

// The energy histogram's bin of e (AW_EHIST_* of aw_params.h), written here from its definition:
// bin 0 below 2^-64, the last from 2^16 on (and NaN), else 4 bins per octave.
std::size_t bin_of(double e) {
  if (!(e < 65536.0)) return AW_EHIST_BINS - 1;
  if (e < std::ldexp(1.0, -64)) return 0;
  int ex = 0;
  const double m = std::frexp(e, &ex);
  return static_cast<std::size_t>(1 + (ex - 1 - AW_EHIST_MIN_EXP) * AW_EHIST_BINS_PER_OCTAVE +
                                  static_cast<int>((m - 0.5) * 8.0));
}

}  // namespace

TEST_SUITE("parity") {
  TEST_CASE("observe.energy_errors: each trajectory's max|dE|, the run's histogram and maximum rebuilt from them") {
    for (const auto& device : awtest::devices_under_test()) {
      CAPTURE(device.id);
      const Result r = awtest::run_on(device.id, make_plan(errors_scene()));
      const Records* rec = r.records_of("energy_errors");
      REQUIRE(rec != nullptr);
      REQUIRE(rec->reals_per == 1);
      REQUIRE(rec->count() == 2000);
      const std::vector<std::int64_t>& fin = r.ints("final_states");
      std::vector<std::uint64_t> hist(AW_EHIST_BINS, 0);
      double largest = 0;
      std::size_t binned = 0;
      for (std::size_t i = 0; i < rec->count(); ++i) {
        const double e = rec->reals[i];
        ++hist[bin_of(e)];
        if (fin[i * AW_STATE_INTS + 3] != AW_STATUS_OK) continue;
        ++binned;
        REQUIRE(std::isfinite(e));
        CHECK(e >= 0);
        largest = std::max(largest, e);
      }
      CHECK(binned == r.binned);
      CHECK(hist == r.energy.log_hist);
      CHECK(largest == r.energy.max);
      CHECK(largest > 1e-9);  // a step this large: errors of all sizes, no zeros
    }
  }

  TEST_CASE("observe.energy_errors: the same bits on every device, in chunks and in time slices") {
    const std::string reference = digest_records(awtest::run_on("cpu", make_plan(errors_scene())), "energy_errors");
    REQUIRE_FALSE(reference.empty());
    for (const auto& device : awtest::devices_under_test()) {
      CAPTURE(device.id);
      for (const char* set : {"ensemble.trajectories=2000", "ensemble.chunk=96", "run.slice=2.5"}) {
        CAPTURE(set);
        CHECK(digest_records(awtest::run_on(device.id, make_plan(errors_scene({set}))), "energy_errors") == reference);
      }
    }
  }

  TEST_CASE("observe.energy_errors: the key brings the energy samples it reads; without it no record") {
    const Plan alone = make_plan(errors_scene({"observe.energy_error=false"}));
    CHECK((alone.kernel.features & AW_F_ENERGY) != 0);
    CHECK((alone.kernel.features & AW_F_ENERGY_ERRORS) != 0);
    const Plan without = make_plan(errors_scene({"observe.energy_errors=false"}));
    CHECK((without.kernel.features & AW_F_ENERGY_ERRORS) == 0);
    CHECK(awtest::run_on("cpu", without).records_of("energy_errors") == nullptr);
  }
}

TEST_SUITE("output") {
  TEST_CASE("observe.energy_errors over a grid: energy_errors.h5 of the grid's shape, and energy_error.png") {
    const std::string dir = awtest::temp_dir("energy_errors");
    std::ofstream(dir + "/scene.toml") << "[ensemble]\ninitial = \"grid\"\n"
                                          "grid = { kind = \"lonlat\", resolution = [16, 12] }\n"
                                          "[integrator]\nstep = 0.025\n[run]\naverage = 5\nduration = 5\n"
                                          "device = \"cpu\"\n[observe]\nenergy_errors = true\n";
    REQUIRE(awtest::run_cli({"run", dir + "/scene.toml", "--quiet", "--out", dir + "/out"}) == 0);
    for (const char* dataset : {"max_energy_error", "log10_max_energy_error"}) {
      std::vector<hsize_t> dims;
      awtest::read_doubles(dir + "/out/energy_errors.h5", dataset, &dims);
      CHECK(dims == std::vector<hsize_t>{12, 16});
    }
    const nlohmann::json summary = awtest::summary_of(dir + "/out");
    CHECK_FALSE(summary["digests"]["energy_errors"].get<std::string>().empty());
    const auto& files = summary["files"];
    CHECK(std::find(files.begin(), files.end(), "energy_errors.h5") != files.end());
    if (arnoldweb::detail::pictures_available())
      CHECK(std::find(files.begin(), files.end(), "energy_error.png") != files.end());
  }
}
