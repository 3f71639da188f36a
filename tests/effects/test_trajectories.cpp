// observe.trajectories (trajectories.h5; docs/outputs.md) on every device
// present (ctest entries trajectories.cpu, .opencl, .cuda):
//  - the first sample of a picked trajectory is its initial state and the last
//    its final state, bit for bit (states.h5 of the same run), in double and in
//    float; its energy error is zero at t = 0 and within the run's largest;
//  - the same bits on every device, in chunks of any size, in time slices, and
//    in a run of the picked trajectory alone (what `arnoldweb orbit` runs);
//  - bad values refused, naming the key;
//  - `arnoldweb orbit SCENE --id N` (ctest trajectories.cli): the digest of ids = [N] in the run of all.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <map>
#include <string>
#include <vector>

#include "arnoldweb/errors.hpp"
#include "aw_params.h"
#include "output/pictures.hpp"
#include "run_outputs.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

const std::vector<std::int64_t> kIds = {0, 17, 2047, 2999};
constexpr std::size_t kSamples = 9;  // t = 0, 1, ..., 8

// 3000 trajectories x 480 steps of the default scene's method and step (scenes/default.toml), four of
// them picked.
Scene picked_scene(const std::vector<std::string>& sets = {}) {
  return awtest::scene_from(R"(
    [model]
    energy = 15
    [ensemble]
    trajectories = 3000
    seed = 7
    [integrator]
    method = "sbab3c"
    step = 0.016666666666666666
    [run]
    average = 4
    duration = 8
    [observe]
    velocity_map = { nside = 8 }
    energy_error = { every = 0.5 }
    initial_states = true
    final_states = true
    trajectories = { ids = [2999, 0, 17, 2047], every = 1.0 }
  )", sets, "<trajectories>");
}

std::string digest_of(const std::string& device, const Scene& s) {
  return digest_records(awtest::run_on(device, make_plan(s)), "trajectories");
}

SceneError plan_error(const std::vector<std::string>& sets) {
  try {
    make_plan(picked_scene(sets));
  } catch (const SceneError& e) {
    return e;
  }
  FAIL("no SceneError for " << sets.front());
  return SceneError("", 0, 0, "", "");
}

}  // namespace

TEST_SUITE("trajectories") {
  TEST_CASE("first sample the initial state, last the final state, bit for bit; a small energy error") {
    for (const auto& device : awtest::devices_under_test())
      for (const char* precision : {"double", "float"}) {
        CAPTURE(device.id);
        CAPTURE(precision);
        const Result r = awtest::run_on(device.id, make_plan(picked_scene({std::string("integrator.precision=") + precision})));
        const Records* rec = r.records_of("trajectories");
        REQUIRE(rec != nullptr);
        REQUIRE(rec->reals_per == AW_PICK_REALS);
        REQUIRE(rec->ints_per == AW_PICK_INTS);
        REQUIRE(rec->count() == kIds.size() * kSamples);
        const std::vector<double>& init = r.reals("initial_states");
        const std::vector<double>& fin = r.reals("final_states");
        const std::vector<std::int64_t>& wind = r.ints("final_states");
        double largest = 0;
        for (std::size_t k = 0; k < kIds.size(); ++k) {
          const auto id = static_cast<std::size_t>(kIds[k]);
          CAPTURE(id);
          const double* first = &rec->reals[k * kSamples * AW_PICK_REALS];
          const double* last = &rec->reals[(k * kSamples + kSamples - 1) * AW_PICK_REALS];
          const std::int64_t* last_w = &rec->ints[(k * kSamples + kSamples - 1) * AW_PICK_INTS];
          for (std::size_t c = 0; c < AW_STATE_REALS; ++c) {
            CHECK(first[c] == init[id * AW_STATE_REALS + c]);
            CHECK(last[c] == fin[id * AW_STATE_REALS + c]);
          }
          for (std::size_t c = 0; c < 3; ++c) CHECK(last_w[c] == wind[id * AW_STATE_INTS + c]);
          CHECK(first[6] == 0.0);
          for (std::size_t q = 1; q < kSamples; ++q)
            largest = std::max(largest, std::fabs(rec->reals[(k * kSamples + q) * AW_PICK_REALS + 6]));
        }
        // the samples are among the energy's (every 0.5 T): within its largest error over the run
        CHECK(largest > 0);
        CHECK(largest <= r.energy.max);
        MESSAGE(std::string(precision) << ": largest |E(t) - E(0)| of the picked trajectories " << largest);
        // scenes/default.toml: max |dE| 1.6e-4 over 1.5 million trajectories of 50 T
        CHECK(largest < (std::string(precision) == "double" ? 1.6e-4 : 1e-3));
      }
  }

  TEST_CASE("the same bits on every device, in chunks, in time slices and for a trajectory alone") {
    const std::string reference = digest_of("cpu", picked_scene());
    REQUIRE_FALSE(reference.empty());
    for (const auto& device : awtest::devices_under_test()) {
      CAPTURE(device.id);
      CHECK(digest_of(device.id, picked_scene()) == reference);
      CHECK(digest_of(device.id, picked_scene({"ensemble.chunk=64"})) == reference);
      CHECK(digest_of(device.id, picked_scene({"run.slice=2"})) == reference);
    }
    // trajectory 17 alone, as `arnoldweb orbit` runs it: its rows of the run of all
    const Result all = awtest::run_on("cpu", make_plan(picked_scene()));
    const Plan one_plan = make_plan(picked_scene({"observe.trajectories={ ids = [17], every = 1.0 }"}));
    for (const auto& device : awtest::devices_under_test()) {
      CAPTURE(device.id);
      std::unique_ptr<Backend> backend = open_backend(device.id);
      const Result one = run_range(one_plan, *backend, 17, 1);
      CHECK(one.completed == 1);
      const Records* rec = one.records_of("trajectories");
      REQUIRE(rec != nullptr);
      const std::vector<double>& a = all.reals("trajectories");
      const std::vector<double> row17(a.begin() + kSamples * AW_PICK_REALS, a.begin() + 2 * kSamples * AW_PICK_REALS);
      CHECK(rec->reals == row17);
    }
  }

  TEST_CASE("bad values refused, naming the key and the allowed range") {
    SceneError e = plan_error({"observe.trajectories={ ids = [3000], every = 1.0 }"});
    CHECK(e.key() == "observe.trajectories.ids");
    CHECK(std::string(e.what()).find("ids 0 to 2999") != std::string::npos);
    e = plan_error({"observe.trajectories={ count = 3001, every = 1.0 }"});
    CHECK(e.key() == "observe.trajectories.count");
    e = plan_error({"observe.trajectories={ ids = [1], count = 2, every = 1.0 }"});
    CHECK(e.key() == "observe.trajectories.count");
    e = plan_error({"observe.trajectories={ ids = [1], every = 3.0 }"});  // does not divide 8 T
    CHECK(e.key() == "observe.trajectories.every");
    e = plan_error({"observe.trajectories={ ids = [1], every = 0.25 }"});  // finer than the 0.5 T segment
    CHECK(e.key() == "observe.trajectories.every");
    CHECK(std::string(e.what()).find("multiple of the shortest sample interval") != std::string::npos);
    // 1024 trajectories x 1025 samples: over the bound on the states kept
    e = plan_error({"integrator.step=0.01", "run.duration=20.48", "run.average=20.48", "observe.energy_error.every=0.02",
                    "observe.trajectories={ count = 1024, every = 0.02 }"});
    CHECK(e.key() == "observe.trajectories.every");
    CHECK(std::string(e.what()).find("at most 1048576") != std::string::npos);
    // read errors: more than 1024 ids, a repeated id, a negative one, a fraction
    for (const char* ids : {"[1, 1]", "[-1]", "[1.5]", "[]"}) {
      CAPTURE(ids);
      try {
        picked_scene({std::string("observe.trajectories={ ids = ") + ids + ", every = 1.0 }"});
        FAIL("accepted");
      } catch (const SceneError& err) {
        CHECK(err.key() == "observe.trajectories.ids");
      }
    }
    std::string many = "[0";
    for (int i = 1; i <= 1024; ++i) many += ", " + std::to_string(i);
    CHECK_THROWS_AS(picked_scene({"observe.trajectories={ ids = " + many + "], every = 1.0 }"}), SceneError);
  }
}

TEST_SUITE("trajectories-cli") {
  TEST_CASE("arnoldweb orbit SCENE --id N: the bits of observe.trajectories ids = [N] in the whole run") {
    const std::string dir = awtest::temp_dir("orbit");
    const std::string scene = dir + "/scene.toml";
    std::ofstream(scene) << "[ensemble]\ntrajectories = 1500\nseed = 5\n[integrator]\nstep = 0.01\n"
                            "[run]\naverage = 2\nduration = 4\ndevice = \"cpu\"\n"
                            "[observe]\nvelocity_map = { nside = 8 }\nenergy_error = { every = 0.5 }\n"
                            "[output]\nimages = false\n";
    REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--out", dir + "/all", "--set",
                             "observe.trajectories={ ids = [1234], every = 1.0 }"}) == 0);
    REQUIRE(awtest::run_cli({"orbit", scene, "--id", "1234", "--every", "1", "--quiet", "--out", dir + "/one"}) == 0);
    const nlohmann::json all = awtest::summary_of(dir + "/all"), one = awtest::summary_of(dir + "/one");
    CHECK_FALSE(all["digests"]["trajectories"].get<std::string>().empty());
    CHECK(one["digests"]["trajectories"] == all["digests"]["trajectories"]);
    CHECK(one["completed"] == 1);
    // a trajectory outside the ensemble, an interval that does not divide the run: exit 2, nothing written
    std::string out;
    CHECK(awtest::run_cli({"orbit", scene, "--id", "1500", "--quiet", "--out", dir + "/outside"}, &out) == 2);
    CHECK(out.find("--id 0 to 1499") != std::string::npos);
    CHECK(awtest::run_cli({"orbit", scene, "--id", "3", "--every", "3", "--quiet", "--out", dir + "/every"}, &out) == 2);
    CHECK(out.find("observe.trajectories.every") != std::string::npos);
    // with pictures (where the plugin opens): trajectories.png, the orbit in action space and its |dE|
    if (arnoldweb::detail::pictures_available()) {
      REQUIRE(awtest::run_cli({"orbit", scene, "--id", "7", "--quiet", "--out", dir + "/drawn", "--set", "output.images=true"}) == 0);
      const nlohmann::json drawn = awtest::summary_of(dir + "/drawn");
      CHECK(std::find(drawn["files"].begin(), drawn["files"].end(), "trajectories.png") != drawn["files"].end());
    }
    CHECK_FALSE(std::ifstream(dir + "/outside/summary.json"));
    CHECK_FALSE(std::ifstream(dir + "/every/summary.json"));
  }
}
