// A researcher's own initial states (issue 25, item 1, the file half): the
// documented HDF5 schema (docs/outputs.md, "State files") read into wrapped
// turns and winding counts, the /final group of a states.h5 written by a run
// read as it is with the same bits, arrays with the same rules, and every bad
// file a StateError (exit 2) naming the file, the dataset and the row; the
// scene keys ensemble.initial = "file" and ensemble.file. Files are made here
// with the HDF5 C API.
#include <doctest/doctest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

#include "arnoldweb/arnoldweb.hpp"
#include "aw_params.h"
#include "h5_test_file.hpp"
#include "support.hpp"

using namespace arnoldweb;
namespace fs = std::filesystem;

namespace {

const std::string kScene =
    "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 3000\nseed = 5\n[integrator]\nstep = 0.02\n"
    "[run]\naverage = 1.0\nduration = 1.0\n[observe]\nvelocity_map = { nside = 8 }\nfinal_states = true\n"
    "[output]\nimages = false\n";

using TestFile = awtest::H5TestFile;

// The final states of a short run of kScene: valid states at E = 15 (their energy is E to the
// run's energy error), as records and as a states.h5.
struct RunStates {
  Plan plan;
  Result result;
  std::vector<double> u, p;  // 3 per state
  std::vector<std::int64_t> w;
};

const RunStates& run_states() {
  static const RunStates r = [] {
    RunStates s;
    s.plan = make_plan(awtest::scene_from(kScene));
    auto dev = open_backend("cpu");
    s.result = run(s.plan, *dev);
    const std::size_t n = s.result.completed;
    for (std::size_t t = 0; t < n; ++t)
      for (int k = 0; k < 3; ++k) {
        s.u.push_back(s.result.reals("final_states")[t * AW_STATE_REALS + k]);
        s.p.push_back(s.result.reals("final_states")[t * AW_STATE_REALS + 3 + k]);
        s.w.push_back(s.result.ints("final_states")[t * AW_STATE_INTS + k]);
      }
    return s;
  }();
  return r;
}

// A file of the documented schema from the run's states: /position_turns, /winding, /momentum.
std::string good_file(const std::string& dir, const std::string& name = "good.h5") {
  const RunStates& r = run_states();
  const std::string path = dir + "/" + name;
  TestFile f(path);
  f.reals("position_turns", r.u);
  f.ints("winding", r.w);
  f.reals("momentum", r.p);
  return path;
}

// What read_state_file (or check_states) throws for `path`; fails the test when it throws nothing.
StateError error_of(const std::string& path, bool check = false) {
  try {
    StateSet s = read_state_file(path);
    if (check) check_states(s, awtest::scene_from(kScene));
  } catch (const StateError& e) {
    return e;
  }
  FAIL("no StateError for " << path);
  return StateError("", "", -1, "");
}

}  // namespace

TEST_SUITE("states") {
  TEST_CASE("the /final group of a states.h5 written by a run is read as it is: the run's bits") {
    const RunStates& r = run_states();
    const std::string dir = awtest::temp_dir("states-final");
    const std::string path = dir + "/states.h5";
    write_records_hdf5(path, "states.h5", r.plan, r.result);
    StateSet s = read_state_file(path);
    CHECK(s.group == "/final");
    CHECK(s.source == path + ":/final");
    REQUIRE(s.count == r.result.completed);
    CHECK(awtest::first_difference(s.position_turns, r.u) == -1);
    CHECK(awtest::first_difference(s.winding, r.w) == -1);
    CHECK(awtest::first_difference(s.momentum, r.p) == -1);
    CHECK(s.status == std::vector<std::int64_t>(s.count, 0));
    // the run's /final records when its states were taken: the end of the run
    CHECK(s.has_time);
    CHECK(s.time == r.plan.scene.duration);
    check_states(s, r.plan.scene);
    REQUIRE(s.energy.size() == s.count);
    // each state's energy is its own: E to the run's energy error
    const double e = r.plan.scene.energy;
    CHECK(s.energy_min <= s.energy_max);
    CHECK(std::fabs(s.energy_min - e) <= r.result.energy.max * (1 + 1e-9) + 1e-12);
    CHECK(std::fabs(s.energy_max - e) <= r.result.energy.max * (1 + 1e-9) + 1e-12);
    CHECK(s.energy_max - s.energy_min > 0);
    // a states.h5 with initial states only has no /final: said so
    TestFile only_initial(dir + "/initial-only.h5");
    only_initial.group("/initial");
    only_initial.reals("/initial/momentum", r.p);
    only_initial.close();
    CHECK(std::string(error_of(dir + "/initial-only.h5").what()).find("no momentum dataset") != std::string::npos);
  }

  TEST_CASE("the documented schema: radians or turns, with or without winding counts, float32, a time") {
    const RunStates& r = run_states();
    const std::string dir = awtest::temp_dir("states-schema");
    // wrapped turns with winding counts: exactly the run's states
    StateSet a = read_state_file(good_file(dir));
    CHECK(a.group == "/");
    CHECK(a.source == dir + "/good.h5");
    CHECK(awtest::first_difference(a.position_turns, r.u) == -1);
    CHECK(awtest::first_difference(a.winding, r.w) == -1);
    check_states(a, r.plan.scene);
    // unwrapped positions in turns and in radians, split into whole and wrapped turns
    std::vector<double> turns, radians;
    for (std::size_t i = 0; i < r.u.size(); ++i) {
      turns.push_back(static_cast<double>(r.w[i]) + r.u[i]);
      radians.push_back(2 * M_PI * (static_cast<double>(r.w[i]) + r.u[i]));
    }
    for (const std::string units : {"turns", "radians"}) {
      CAPTURE(units);
      const std::string path = dir + "/" + units + ".h5";
      {
        TestFile f(path);
        f.reals("position", units == "turns" ? turns : radians);
        f.text("/position", "units", units);
        f.reals("momentum", r.p, H5T_IEEE_F32LE);  // float32 is read too
        f.number("/", "time", 12.5);
      }
      StateSet s = read_state_file(path);
      REQUIRE(s.count == r.result.completed);
      CHECK(s.has_time);
      CHECK(s.time == 12.5);
      double worst = 0;
      for (std::size_t i = 0; i < s.position_turns.size(); ++i) {
        CHECK(std::fabs(s.position_turns[i]) <= 0.5);
        worst = std::max(worst, std::fabs((s.position_turns[i] + static_cast<double>(s.winding[i])) -
                                          (r.u[i] + static_cast<double>(r.w[i]))));
        CHECK(s.momentum[i] == static_cast<double>(static_cast<float>(r.p[i])));
      }
      CHECK(worst < 1e-12);
      check_states(s, r.plan.scene);  // float32 momenta are within the tolerance
    }
    // exact splits: 3.25 turns is 3 + 0.25; -7.5 rounds to even (-8 + 0.5)
    {
      TestFile f(dir + "/split.h5");
      f.reals("position", {3.25, -7.5, 0.0});
      f.text("/position", "units", "turns");
      f.reals("momentum", {1.0, 2.0, 3.0});
    }
    const StateSet split = read_state_file(dir + "/split.h5");
    CHECK(split.position_turns == std::vector<double>{0.25, 0.5, 0.0});
    CHECK(split.winding == std::vector<std::int64_t>{3, -8, 0});
  }

  TEST_CASE("flagged rows of a states.h5 (status != 0) are kept as they are, not checked") {
    const RunStates& r = run_states();
    const std::string dir = awtest::temp_dir("states-status");
    std::vector<double> p = r.p;
    p[3 * 4] = std::numeric_limits<double>::quiet_NaN();  // row 4 went non-finite
    std::vector<std::int64_t> status(r.result.completed, 0);
    status[4] = 1;
    {
      TestFile f(dir + "/s.h5");
      f.group("/final");
      f.reals("/final/position_turns", r.u);
      f.ints("/final/winding", r.w);
      f.reals("/final/momentum", p);
      f.ints("/final/status", status, false);
    }
    StateSet s = read_state_file(dir + "/s.h5");
    CHECK(s.status[4] == 1);
    CHECK(std::isnan(s.momentum[12]));
    check_states(s, r.plan.scene);
    CHECK(std::isnan(s.energy[4]));
    CHECK(std::isfinite(s.energy[3]));
  }

  TEST_CASE("bad files: exit 2, and the message names the file, the dataset and the row") {
    const RunStates& r = run_states();
    const std::string dir = awtest::temp_dir("states-bad");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    struct Case {
      std::string name;
      std::function<void(TestFile&)> write;
      std::string dataset;
      std::int64_t row;
      std::string says;
      bool energy = false;  // found by check_states
    };
    auto with = [&](std::function<void(std::vector<double>& u, std::vector<double>& p)> change) {
      return [&r, change](TestFile& f) {
        std::vector<double> u = r.u, p = r.p;
        change(u, p);
        f.reals("position_turns", u);
        f.ints("winding", r.w);
        f.reals("momentum", p);
      };
    };
    const std::vector<Case> cases = {
        {"nan-momentum", with([&](auto&, auto& p) { p[3 * 5 + 1] = nan; }), "/momentum", 5, "is not finite"},
        {"inf-position", with([](auto& u, auto&) { u[3 * 2] = HUGE_VAL; }), "/position_turns", 2, "is not finite"},
        {"wrapped-out-of-range", with([](auto& u, auto&) { u[3 * 1 + 2] = 0.7; }), "/position_turns", 1,
         "is out of range: with /winding"},
        {"far-energy", with([](auto&, auto& p) { p[3 * 4] *= 1.2, p[3 * 4 + 1] *= 1.2, p[3 * 4 + 2] *= 1.2; }), "", 4, "is far from model.energy = 15", true},
        {"momentum-shape",
         [&](TestFile& f) {
           f.reals("position_turns", r.u);
           f.dataset<double>("momentum", std::vector<double>(2 * r.result.completed, 0.5), {r.result.completed, 2},
                             H5T_IEEE_F64LE);
         },
         "/momentum", -1, "has the shape (3000, 2); it must be (N, 3)"},
        {"row-counts",
         [&](TestFile& f) {
           f.reals("position_turns", std::vector<double>(r.u.begin(), r.u.end() - 3));
           f.reals("momentum", r.p);
         },
         "/position_turns", -1, "has 2999 rows and /momentum 3000"},
        {"no-units",
         [&](TestFile& f) {
           f.reals("position", r.u);
           f.reals("momentum", r.p);
         },
         "/position", -1, "needs the attribute units"},
        {"degrees",
         [&](TestFile& f) {
           f.reals("position", r.u);
           f.text("/position", "units", "degrees");
           f.reals("momentum", r.p);
         },
         "/position", -1, "it must be \"radians\" or \"turns\""},
        {"integer-momentum",
         [&](TestFile& f) {
           f.reals("position_turns", r.u);
           f.ints("momentum", std::vector<std::int64_t>(r.p.size(), 1));
         },
         "/momentum", -1, "must hold floating-point numbers"},
        {"real-winding",
         [&](TestFile& f) {
           f.reals("position_turns", r.u);
           f.reals("winding", std::vector<double>(r.u.size(), 1.0));
           f.reals("momentum", r.p);
         },
         "/winding", -1, "must hold integers"},
        {"huge-position",
         [&](TestFile& f) {
           std::vector<double> x = r.u;
           x[3 * 7] = 1e300;
           f.reals("position", x);
           f.text("/position", "units", "turns");
           f.reals("momentum", r.p);
         },
         "/position", 7, "is out of range: at most 2^52 turns"},
        {"negative-time",
         [&](TestFile& f) {
           f.reals("position_turns", r.u);
           f.reals("momentum", r.p);
           f.number("/", "time", -1);
         },
         "/", -1, "the attribute time is -1"},
        {"status-7",
         [&](TestFile& f) {
           f.reals("position_turns", r.u);
           f.reals("momentum", r.p);
           std::vector<std::int64_t> st(r.result.completed, 0);
           st[9] = 7;
           f.ints("status", st, false);
         },
         "/status", 9, "status 7 is none of"},
        {"empty",
         [&](TestFile& f) {
           f.dataset<double>("position_turns", {}, {0, 3}, H5T_IEEE_F64LE);
           f.dataset<double>("momentum", {}, {0, 3}, H5T_IEEE_F64LE);
         },
         "/momentum", -1, "holds no states"},
        {"no-position", [&](TestFile& f) { f.reals("momentum", r.p); }, "/position", -1, "missing"},
    };
    for (const Case& c : cases) {
      CAPTURE(c.name);
      const std::string path = dir + "/" + c.name + ".h5";
      {
        TestFile f(path);
        c.write(f);
      }
      const StateError e = error_of(path, c.energy);
      CAPTURE(e.what());
      CHECK(e.exit_code() == 2);
      CHECK(e.source() == path);
      CHECK(e.dataset() == c.dataset);
      CHECK(e.row() == c.row);
      CHECK(std::string(e.what()).find(c.says) != std::string::npos);
      CHECK(std::string(e.what()).rfind(path + ": ", 0) == 0);
      if (c.row >= 0) CHECK(std::string(e.what()).find("row " + std::to_string(c.row) + ":") != std::string::npos);
    }
    // not a file of states at all
    std::ofstream(dir + "/text.h5") << "not HDF5";
    CHECK(std::string(error_of(dir + "/text.h5").what()).find("not an HDF5 file") != std::string::npos);
    CHECK(std::string(error_of(dir + "/missing.h5").what()).find("no such file") != std::string::npos);
  }

  TEST_CASE("arrays (Python's initial=(X, P)) follow the same rules") {
    const RunStates& r = run_states();
    std::vector<double> x;
    for (std::size_t i = 0; i < r.u.size(); ++i) x.push_back(2 * M_PI * (static_cast<double>(r.w[i]) + r.u[i]));
    const std::size_t n = r.result.completed;
    StateSet s = states_from_arrays(x.data(), n, 3, r.p.data(), n, 3, PositionUnits::Radians, "initial");
    CHECK(s.count == n);
    CHECK(s.source == "initial");
    check_states(s, r.plan.scene);
    auto says = [](auto&& f, const std::string& text) {
      try {
        f();
      } catch (const StateError& e) {
        CAPTURE(e.what());
        CHECK(std::string(e.what()).find(text) != std::string::npos);
        return;
      }
      FAIL("no StateError");
    };
    says([&] { states_from_arrays(x.data(), n, 3, r.p.data(), n / 3, 9, PositionUnits::Radians, "initial"); },
         "initial: P: has the shape (1000, 9); it must be (N, 3)");
    says([&] { states_from_arrays(x.data(), n - 1, 3, r.p.data(), n, 3, PositionUnits::Radians, "initial"); },
         "initial: P: has 3000 rows and X 2999");
    std::vector<double> bad = x;
    bad[3 * 11 + 2] = std::numeric_limits<double>::infinity();
    says([&] { states_from_arrays(bad.data(), n, 3, r.p.data(), n, 3, PositionUnits::Radians, "initial"); },
         "initial: X, row 11: the position");
    std::vector<double> slow = r.p;
    for (double& v : slow) v *= 0.5;
    says(
        [&] {
          StateSet t = states_from_arrays(x.data(), n, 3, slow.data(), n, 3, PositionUnits::Radians, "initial");
          check_states(t, r.plan.scene);
        },
        "initial: row 0: the state's energy");
    // the same arrays in turns are other positions: far from E for most states
    says(
        [&] {
          StateSet t = states_from_arrays(x.data(), n, 3, r.p.data(), n, 3, PositionUnits::Turns, "initial");
          check_states(t, r.plan.scene);
        },
        "is far from model.energy");
  }

  TEST_CASE("scene keys: ensemble.file names an existing file, goes with ensemble.initial = \"file\", and is read before planning") {
    const std::string dir = awtest::temp_dir("states-keys");
    const std::string file = good_file(dir);
    const Scene ok = awtest::scene_from(kScene, {"ensemble.initial=file", awtest::set("ensemble.file", file)});
    CHECK(ok.initial == "file");
    CHECK(ok.initial_file == file);
    CHECK(ok.to_toml().find("file = \"" + file + "\"") != std::string::npos);
    CHECK_THROWS_WITH_AS(awtest::scene_from(kScene, {awtest::set("ensemble.file", dir + "/none.h5")}),
                         doctest::Contains("(no such file)"), SceneError);
    CHECK_THROWS_WITH_AS(awtest::scene_from(kScene, {awtest::set("ensemble.file", dir)}),
                         doctest::Contains("(it is a directory)"), SceneError);
    CHECK_THROWS_WITH_AS(plan_job(awtest::scene_from(kScene, {"ensemble.initial=file"})),
                         doctest::Contains("\"file\" needs ensemble.file"), SceneError);
    CHECK_THROWS_WITH_AS(make_plan(awtest::scene_from(kScene, {awtest::set("ensemble.file", file)})),
                         doctest::Contains("is read only with ensemble.initial = \"file\""), SceneError);
    // read and checked before planning (read_plan_inputs), planned one trajectory per state
    const auto plan_with_inputs = [](const Scene& scene) { return make_plan(scene, read_plan_inputs(scene)); };
    CHECK_FALSE(make_plan(ok).states);  // planning itself reads no file
    const Plan planned = plan_with_inputs(ok);
    REQUIRE(planned.states);
    CHECK(planned.states->count == 3000);
    CHECK(planned.scene.trajectories == 3000);
    CHECK_THROWS_WITH_AS(plan_with_inputs(awtest::scene_from(kScene, {"ensemble.initial=file", awtest::set("ensemble.file", file),
                                                               "ensemble.trajectories=12"})),
                         doctest::Contains("leave ensemble.trajectories out or set it to 3000"), SceneError);
    // `arnoldweb check` names a bad row, exit 2, and writes nothing
    const std::string scene = dir + "/scene.toml";
    std::ofstream(scene) << kScene;
    {
      const RunStates& r = run_states();
      std::vector<double> p = r.p;
      p[3 * 6 + 2] = std::numeric_limits<double>::quiet_NaN();
      TestFile f(dir + "/bad.h5");
      f.reals("position_turns", r.u);
      f.reals("momentum", p);
    }
    std::string text;
    CHECK(awtest::run_cli({"check", scene, "--out", dir + "/out", "--set", "ensemble.initial=file", "--set",
                           "ensemble.file=" + dir + "/bad.h5"},
                          &text) == 2);
    CHECK(text.find(dir + "/bad.h5: /momentum, row 6: the momentum") != std::string::npos);
    CHECK_FALSE(fs::exists(dir + "/out"));
  }
}
