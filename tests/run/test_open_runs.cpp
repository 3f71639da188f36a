// Open runs (docs/scenes.md, "Open runs"), on every device present (ctest
// entries open-runs.cpu, open-runs.opencl, open-runs.cuda):
//  - time slices (run.slice) give the unsliced run's bits: map, states,
//    indicators, counters, energy statistics, whatever effects are on;
//  - a run of 2T is a run of T continued for T from its final states, bit for
//    bit: the final states, and the map of the second window;
//  - a sliced run stopped between slices and resumed from its checkpoint gives
//    the uninterrupted digests.
#include <doctest/doctest.h>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include <fstream>
#include <nlohmann/json.hpp>

#include "arnoldweb/checkpoint.hpp"
#include "arnoldweb/output.hpp"
#include "run_outputs.hpp"
#include "aw_params.h"
#include "support.hpp"

using namespace arnoldweb;

namespace {

// 2000 trajectories, 4 T in windows of 2 T, energy every 0.5 T; `sets` change it.
Scene open_scene(const std::vector<std::string>& sets = {}) {
  return awtest::scene_from(R"(
    [model]
    energy = 15
    [ensemble]
    trajectories = 2000
    seed = 77
    [integrator]
    method = "yoshida6a"
    step = 0.01
    [run]
    average = 2
    duration = 4
    [observe]
    velocity_map = { nside = 16 }
    energy_error = { every = 0.5 }
    initial_states = true
    final_states = true
  )", sets, "<open-runs>");
}

void check_same_run(const Result& a, const Result& b) {
  CHECK(digest_map(a) == digest_map(b));
  for (const std::string& name : output_names()) {
    CAPTURE(name);
    CHECK(digest_records(a, name) == digest_records(b, name));
  }
  CHECK(a.binned == b.binned);
  CHECK(a.flagged() == b.flagged());
  CHECK(a.left_region == b.left_region);
  CHECK(a.energy.max == b.energy.max);
  CHECK(a.energy.mean == b.energy.mean);
  CHECK(a.energy.log_hist == b.energy.log_hist);
  CHECK(a.frames == b.frames);
  CHECK(a.zoom == b.zoom);
}

// The final states of a result as the states a run starts from.
std::shared_ptr<StateSet> final_states_of(const Result& r, double time) {
  auto s = std::make_shared<StateSet>();
  const auto& reals = r.reals("final_states");
  const auto& ints = r.ints("final_states");
  s->source = "final states";
  s->count = r.completed;
  for (std::uint64_t t = 0; t < s->count; ++t) {
    for (int c = 0; c < 3; ++c) {
      s->position_turns.push_back(reals[t * AW_STATE_REALS + c]);
      s->momentum.push_back(reals[t * AW_STATE_REALS + 3 + c]);
      s->winding.push_back(ints[t * AW_STATE_INTS + c]);
    }
    s->status.push_back(ints[t * AW_STATE_INTS + 3]);
  }
  s->has_time = true;
  s->time = time;
  return s;
}

}  // namespace

TEST_SUITE("open-runs") {
  TEST_CASE("time slices give the bits of the run in one piece, whatever the effects") {
    const std::vector<std::vector<std::string>> variants = {
        {},
        {"observe.max_energy_error=1e-6", "observe.confine={ center = [45, 0], width = 100 }",
         "observe.frames.times=[0, 2, 4]", "observe.zoom={ width = 30, resolution = 32 }"},
        {"observe.fli=true", "observe.megno=true", "observe.lyapunov=true"},
        {"integrator.precision=\"float\""},
    };
    for (const auto& device : awtest::devices_under_test()) {
      for (const auto& sets : variants) {
        CAPTURE(device.id);
        CAPTURE(sets.size());
        const Plan whole = make_plan(open_scene(sets));
        const Result ref = awtest::run_on(device.id, whole);
        REQUIRE(ref.binned > 0);
        for (const char* slice : {"0.5", "1.5", "2", "3.5"}) {
          CAPTURE(slice);
          std::vector<std::string> s = sets;
          s.push_back(std::string("run.slice=") + slice);
          const Plan sliced = make_plan(open_scene(s));
          CHECK(sliced.slices > 1);
          check_same_run(awtest::run_on(device.id, sliced), ref);
        }
      }
    }
  }

  TEST_CASE("run.slice must end where the energy is sampled") {
    CHECK_THROWS_WITH_AS(make_plan(open_scene({"run.slice=0.3"})), doctest::Contains("run.slice"), SceneError);
    CHECK(make_plan(open_scene({"run.slice=4"})).slices == 1);  // a slice as long as the run: none
  }

  TEST_CASE("2T is T continued for T from its final states: the final states and the second window's map") {
    for (const auto& device : awtest::devices_under_test()) {
      CAPTURE(device.id);
      for (const std::string precision : {"double", "float"}) {
        CAPTURE(precision);
        const std::string p = "integrator.precision=\"" + precision + "\"";
        const Result both = awtest::run_on(device.id, make_plan(open_scene({p})));
        const Result first = awtest::run_on(device.id, make_plan(open_scene({p, "run.duration=2"})));
        Scene cont = open_scene({p, "run.duration=2"});
        cont.initial = "file";
        Plan plan = make_plan(cont);
        plan.states = final_states_of(first, 2);
        const Result second = awtest::run_on(device.id, plan);
        CHECK(awtest::first_difference(second.reals("final_states"), both.reals("final_states")) == -1);
        CHECK(second.ints("final_states") == both.ints("final_states"));
        // the continued run starts where the first ended
        REQUIRE(second.reals("initial_states").size() == first.reals("final_states").size());
        for (std::uint64_t t = 0; t < first.completed; ++t)
          for (int c = 0; c < AW_STATE_REALS; ++c)
            CHECK(second.reals("initial_states")[t * AW_STATE_REALS + c] ==
                  first.reals("final_states")[t * AW_STATE_REALS + c]);
        // windows are counted: the map of 2T is the first window's plus the second's
        REQUIRE(both.map.size() == first.map.size());
        for (std::size_t i = 0; i < both.map.size(); ++i) CHECK(both.map[i] == first.map[i] + second.map[i]);
        CHECK(second.binned == first.binned);
      }
    }
  }

  TEST_CASE("a state flagged before stays flagged: it is neither integrated into the map nor counted as binned") {
    const auto& device = awtest::devices_under_test().front();
    const Result first = awtest::run_on(device.id, make_plan(open_scene({"run.duration=2"})));
    auto states = final_states_of(first, 2);
    states->status[5] = AW_STATUS_ENERGY;
    Scene cont = open_scene({"run.duration=2"});
    cont.initial = "file";
    Plan plan = make_plan(cont);
    plan.states = states;
    const Result r = awtest::run_on(device.id, plan);
    CHECK(r.binned == first.binned - 1);
    CHECK(r.flagged_energy == 1);
    CHECK(r.ints("final_states")[5 * AW_STATE_INTS + 3] == AW_STATUS_ENERGY);
  }

  TEST_CASE("a plan that starts from states without any, or with another number, is refused") {
    Scene s = open_scene();
    s.initial = "file";
    Plan plan = make_plan(s);
    CHECK_THROWS_WITH_AS(awtest::run_on("cpu", plan), doctest::Contains("ensemble.initial"), SceneError);
    auto few = std::make_shared<StateSet>();
    few->count = 3;
    few->position_turns.assign(9, 0.0);
    few->momentum.assign(9, 1.0);
    plan.states = few;
    CHECK_THROWS_WITH_AS(awtest::run_on("cpu", plan), doctest::Contains("3 states"), SceneError);
  }

  TEST_CASE("a sliced run stopped between slices resumes from its checkpoint to the uninterrupted bits") {
    const auto& device = awtest::devices_under_test().front();
    CAPTURE(device.id);
    const std::vector<std::string> sets = {"run.slice=0.5", "observe.fli=true", "ensemble.chunk=512"};
    const Job job = plan_job(open_scene(sets));
    auto backend = open_backend(device.id);
    const JobResult ref = run_job(job, *backend);
    REQUIRE(ref.results.size() == 1);
    // stop after a few launches (block-slices), keep the checkpoint, resume from it
    class Sink final : public CheckpointSink {
     public:
      void save(const std::string& image) override { last = image; }
      std::string last;
    } sink;
    class StopAfter final : public Progress {
     public:
      StopAfter(std::atomic<bool>& stop, int after) : stop_(stop), after_(after) {}
      void update(std::uint64_t, std::uint64_t, double) override {
        if (--after_ <= 0) stop_ = true;
      }
      void finish(std::uint64_t, std::uint64_t, double) override {}

     private:
      std::atomic<bool>& stop_;
      int after_;
    };
    for (int after : {1, 5, 17}) {
      CAPTURE(after);
      std::atomic<bool> stop{false};
      StopAfter progress(stop, after);
      Checkpointing cp;
      cp.sink = &sink;
      cp.every_seconds = 0;
      RunOptions o;
      o.stop = &stop;
      o.progress = &progress;
      o.checkpoint = &cp;
      const JobResult part = run_job(job, *backend, o);
      REQUIRE(part.interrupted);
      REQUIRE(!sink.last.empty());
      Checkpointing again;
      again.sink = &sink;
      again.every_seconds = 0;
      again.resume = sink.last;
      RunOptions o2;
      o2.checkpoint = &again;
      const JobResult rest = run_job(job, *backend, o2);
      REQUIRE(rest.results.size() == 1);
      CHECK_FALSE(rest.interrupted);
      check_same_run(rest.results[0], ref.results[0]);
    }
  }
}

TEST_SUITE("open-runs-cli") {
  TEST_CASE("arnoldweb continue OUT --for T: 2T is T continued for T (final states, maps, time), and bad input is refused") {
    const std::string dir = awtest::temp_dir("continue");
    const std::string scene = dir + "/scene.toml";
    std::ofstream(scene) << "[ensemble]\ntrajectories = 1500\nseed = 5\n[integrator]\nstep = 0.01\n"
                            "[run]\naverage = 2\nduration = 4\ndevice = \"cpu\"\n"
                            "[observe]\nvelocity_map = { nside = 8 }\nenergy_error = { every = 1 }\nfinal_states = true\n"
                            "[output]\nimages = false\n";
    REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--out", dir + "/both"}) == 0);
    REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--out", dir + "/first", "--set", "run.duration=2"}) == 0);
    std::string out;
    REQUIRE(awtest::run_cli({"continue", dir + "/first", "--for", "2", "--quiet"}, &out) == 0);
    const std::string second = dir + "/first-to-4";
    const nlohmann::json both = awtest::summary_of(dir + "/both"), cont = awtest::summary_of(second);
    CHECK(cont["digests"]["final_states"] == both["digests"]["final_states"]);
    CHECK(cont["time"]["start"] == 2.0);
    CHECK(cont["time"]["end"] == 4.0);
    CHECK(cont["scene"]["ensemble"]["initial"] == "file");
    const SavedMaps a = read_saved_maps(dir + "/both"), b = read_saved_maps(dir + "/first"), c = read_saved_maps(second);
    REQUIRE(a.map.size() == b.map.size());
    REQUIRE(c.map.size() == a.map.size());
    for (std::size_t i = 0; i < a.map.size(); ++i) CHECK(a.map[i] == b.map[i] + c.map[i]);
    // a run without final states, a duration of 0, a directory that is no run: exit 2 (a missing or
    // damaged input, as for render and compare: docs/reliability.md), nothing written
    REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--out", dir + "/nostates", "--set", "observe.final_states=false"}) == 0);
    CHECK(awtest::run_cli({"continue", dir + "/nostates", "--for", "2", "--quiet"}, &out) == 2);
    CHECK(out.find("observe.final_states") != std::string::npos);
    CHECK(awtest::run_cli({"continue", dir + "/first", "--for", "0", "--quiet", "--out", dir + "/zero"}, &out) == 2);
    CHECK(awtest::run_cli({"continue", dir, "--for", "2", "--quiet", "--out", dir + "/none"}, &out) == 2);
    CHECK_FALSE(std::ifstream(dir + "/zero/summary.json"));
    CHECK_FALSE(std::ifstream(dir + "/none/summary.json"));
  }
}
