// arnoldweb tests: the scene layer (TOML scenes, --set overrides, to_toml,
// the key table and its documentation).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "support.hpp"

using arnoldweb::MathMode;
using arnoldweb::Precision;
using arnoldweb::Scene;
using arnoldweb::SceneError;

namespace {

Scene parse(const std::string& toml, const std::vector<std::string>& sets = {}) {
  return awtest::scene_from(toml, sets);
}

// The SceneError that parsing `toml` throws (fails the test if none).
SceneError error_of(const std::string& toml, const std::vector<std::string>& sets = {}) {
  try {
    parse(toml, sets);
  } catch (const SceneError& e) {
    return e;
  }
  FAIL("no SceneError for:\n" << toml);
  return SceneError("", 0, 0, "", "");
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Every setting of two scenes is the same (not the provenance).
void check_same(const Scene& a, const Scene& b) {
  CHECK(a.energy == b.energy);
  CHECK(a.trajectories == b.trajectories);
  CHECK(a.seed == b.seed);
  CHECK(a.initial == b.initial);
  CHECK(a.chunk == b.chunk);
  CHECK(a.method == b.method);
  CHECK(a.step_auto == b.step_auto);
  if (!a.step_auto) CHECK(a.step == b.step);
  CHECK(a.tolerance == b.tolerance);
  CHECK(a.precision == b.precision);
  CHECK(a.math == b.math);
  CHECK(a.allow_unsafe_step == b.allow_unsafe_step);
  CHECK(a.average == b.average);
  CHECK(a.duration == b.duration);
  CHECK(a.device == b.device);
  CHECK(a.velocity_map == b.velocity_map);
  if (a.velocity_map) CHECK(a.nside == b.nside);
  CHECK(a.energy_error == b.energy_error);
  if (a.energy_error) CHECK(a.energy_every == b.energy_every);
  CHECK(a.max_energy_error == b.max_energy_error);
  CHECK(a.initial_states == b.initial_states);
  CHECK(a.final_states == b.final_states);
  CHECK(a.output_dir == b.output_dir);
  CHECK(a.images == b.images);
  CHECK(a.cap_center == b.cap_center);
  CHECK(a.cap_radius == b.cap_radius);
  CHECK(a.box_lon == b.box_lon);
  CHECK(a.box_lat == b.box_lat);
  CHECK(a.gaussian_mean == b.gaussian_mean);
  CHECK(a.gaussian_sigma == b.gaussian_sigma);
  CHECK(a.zoom == b.zoom);
  if (a.zoom) {
    CHECK(a.zoom_center == b.zoom_center);
    CHECK(a.zoom_width == b.zoom_width);
    CHECK(a.zoom_resolution == b.zoom_resolution);
  }
  CHECK(a.confine == b.confine);
  if (a.confine) {
    CHECK(a.confine_center == b.confine_center);
    CHECK(a.confine_width == b.confine_width);
  }
  CHECK(a.frame_times == b.frame_times);
  for (const arnoldweb::SceneKey& k : arnoldweb::scene_keys())  // the output table's table keys, as written or by default
    CHECK_MESSAGE(a.output_value(k.key) == b.output_value(k.key), k.key);
  // chaos indicators and grids
  CHECK(a.switches == b.switches);
  CHECK(a.output_value("observe.tangent_initial") == b.output_value("observe.tangent_initial"));
  CHECK(a.grid_kind == b.grid_kind);
  CHECK(a.grid_nside == b.grid_nside);
  CHECK(a.grid_resolution == b.grid_resolution);
  CHECK(a.grid_range1 == b.grid_range1);
  CHECK(a.grid_range2 == b.grid_range2);
  CHECK(a.grid_axes == b.grid_axes);
  CHECK(a.grid_fixed == b.grid_fixed);
  CHECK(a.grid_position == b.grid_position);
  REQUIRE(a.panels.size() == b.panels.size());
  for (std::size_t i = 0; i < a.panels.size(); ++i) {
    CHECK(a.panels[i].name == b.panels[i].name);
    CHECK(a.panels[i].title == b.panels[i].title);
    CHECK(a.panels[i].sets == b.panels[i].sets);
  }
}

// One bad value: the key it names, where, and parts of the message.
struct Bad {
  std::string toml;
  std::string key;
  int line, column;
  std::vector<std::string> says;
};

// Keys set to values other than their defaults (what "every key is read"
// checks); full_scene() adds every other key of the table at its default.
const char* kFullSceneFixed =
    "[model]\n"
    "energy = 400.5\n"
    "kind = \"fourier\"\n"
    "potential = \"eps*cos(x)\"\n"
    "parameters = { eps = 0.5 }\n"
    "[ensemble]\n"
    "trajectories = 10_000_000_000_000\n"
    "seed = 42\n"
    "initial = \"shell\"\n"
    "chunk = 65536\n"
    "[integrator]\n"
    "method = \"leapfrog\"\n"
    "step = 0.003125\n"
    "tolerance = 1e-10\n"
    "precision = \"float\"\n"
    "math = \"native\"\n"
    "allow_unsafe_step = true\n"
    "[run]\n"
    "average = 12.5\n"
    "duration = 1e4\n"
    "slice = 1000\n"
    "device = \"opencl:1\"\n"
    "checkpoint_every = \"10 min\"\n"
    "[observe]\n"
    "velocity_map = { nside = 8192 }\n"
    "energy_error = { every = 0.25 }\n"
    "max_energy_error = 3e-7\n"
    "initial_states = true\n"
    "final_states = true\n"
    "fli = true\n"
    "megno = true\n"
    "lyapunov = true\n"
    "tangent_initial = [1, 0, 0, 0, 0, 2]\n"
    "[output]\n"
    "dir = \"runs/E400 \\\"x\\\"\"\n"
    "images = false\n"
    "formats = [\"hdf5\", \"fits\"]\n"
    "[ensemble.cap]\n"
    "center = [10, -20.5]\n"
    "radius = 3.5\n"
    "[ensemble.box]\n"
    "lon = [-10.0, 20.0]\n"
    "lat = [60, 70]\n"
    "[ensemble.gaussian]\n"
    "mean = [3.873, 3.873]\n"
    "sigma = [0.01, 0.02]\n"
    "[observe.zoom]\n"
    "center = [45, 35.26]\n"
    "width = 8.0\n"
    "resolution = 1024\n"
    "[observe.confine]\n"
    "center = [45, 35.26]\n"
    "width = 8.5\n"
    "[observe.frames]\n"
    "times = [0, 100, 1e3, 1e4]\n"
    "[observe.frequencies]\n"
    "samples = 1024\n"
    "every = 0.05\n"
    "window = 2\n"
    "[observe.diffusion]\n"
    "every = 20.0\n"
    "along = [1, 2, 0]\n"
    "across = [2, -1, 0]\n"
    "fit_from = 100\n"
    "average = 10.0\n"
    "average_every = 0.5\n"
    "[observe.trajectories]\n"
    "ids = [17, 5]\n"
    "count = 3\n"
    "every = 2.5\n"
    "[ensemble.grid]\n"
    "kind = \"plane\"\n"
    "nside = 32\n"
    "resolution = [128, 256]\n"
    "range1 = [-1, 2]\n"
    "range2 = [-0.25, 1.75]\n"
    "axes = [1, 2]\n"
    "fixed = 0.5\n"
    "position = [0.1, 0.2, 0.3]\n"
    "[[panel]]\n"
    "name = \"b\"\n"
    "title = \"zoom (b)\"\n"
    "set = [\"ensemble.initial=cap\"]\n";

// kFullSceneFixed with every other key of the key table written at its default, in
// its table (a new key, a new model's parameters come in by themselves). A key
// without a default must be in kFullSceneFixed, or the test of every key fails on it.
std::string full_scene() {
  std::string text = kFullSceneFixed;
  const Scene fixed = parse(text);
  for (const auto& k : arnoldweb::scene_keys()) {
    if (fixed.where.count(k.key) || k.default_value == "(not set)") continue;
    const std::size_t dot = k.key.rfind('.');
    const std::string table = k.key.substr(0, dot), line = k.key.substr(dot + 1) + " = " + k.default_value;
    const std::string header = "[" + table + "]\n";
    const std::string parent = table.substr(table.rfind('.') + 1) + " = { ";  // an inline table
    std::size_t at = text.find(header);
    if (at != std::string::npos) {
      text.insert(at + header.size(), line + "\n");
    } else if (fixed.where.count(table) && (at = text.find(parent)) != std::string::npos) {
      text.insert(at + parent.size(), line + ", ");
    } else {
      text += header + line + "\n";
    }
  }
  return text;
}

// The line (1-based) of the first line of `text` that starts with `start`.
int line_of(const std::string& text, const std::string& start) {
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.rfind(start, 0) == 0) return n;
  FAIL("no line starts with " << start);
  return 0;
}

}  // namespace

TEST_SUITE("scene") {
  TEST_CASE("an empty scene is all defaults") {
    const Scene s = parse("");
    const Scene d;
    check_same(s, d);
    CHECK(s.energy == 15.0);
    CHECK(s.trajectories == 100000);
    CHECK(s.method == "yoshida6a");
    CHECK(s.step == 0.01);
    CHECK_FALSE(s.step_auto);
    CHECK(s.velocity_map);
    CHECK(s.nside == 64);
    CHECK_FALSE(s.max_energy_error.has_value());
    CHECK(s.file == "<test>");
    CHECK(s.where.empty());
    CHECK(s.pos("model.energy").line == 0);
    CHECK(s.origin("model.energy") == "default");
  }

  TEST_CASE("a direction key of the output table (observe.tangent_initial): its default, as written, in output_values") {
    const Scene d = parse("");
    CHECK(d.output_values.count("observe.tangent_initial") == 0);
    CHECK(d.output_value("observe.tangent_initial") == std::vector<double>{0.3, -0.7, 0.5, 0.2, 0.6, -0.1});
    const Scene s = parse("[observe]\ntangent_initial = [0, 0, 3, 0, 0, 4]\n");
    CHECK(s.output_values.at("observe.tangent_initial") == std::vector<double>{0, 0, 3, 0, 0, 4});
    CHECK(s.output_value("observe.tangent_initial") == std::vector<double>{0, 0, 3, 0, 0, 4});
    CHECK(s.pos("observe.tangent_initial").line == 2);
  }

  TEST_CASE("every key is read, with its position") {
    const std::string text = full_scene();
    const Scene s = parse(text);
    CHECK(s.energy == 400.5);
    CHECK(s.model_potential == "eps*cos(x)");
    CHECK(s.model_parameters == std::vector<std::pair<std::string, double>>{{"eps", 0.5}});
    CHECK(s.model_kind == "fourier");
    for (const auto& k : arnoldweb::scene_keys())  // the model parameters: written at their defaults
      if (s.model_values.count(k.key)) CHECK(s.to_toml().find(k.key.substr(6) + " = " + k.default_value) != std::string::npos);
    CHECK(s.trajectories == 10'000'000'000'000ull);
    CHECK(s.seed == 42);
    CHECK(s.initial == "shell");
    CHECK(s.chunk == 65536);
    CHECK(s.method == "leapfrog");
    CHECK(s.step == 0.003125);
    CHECK_FALSE(s.step_auto);
    CHECK(s.tolerance == 1e-10);
    CHECK(s.precision == Precision::Float);
    CHECK(s.math == MathMode::Native);
    CHECK(s.allow_unsafe_step);
    CHECK(s.average == 12.5);
    CHECK(s.duration == 1e4);
    CHECK(s.slice == 1000);
    CHECK(s.device == "opencl:1");
    CHECK(s.checkpoint_every == 600);
    CHECK(s.velocity_map);
    CHECK(s.nside == 8192);
    CHECK(s.energy_error);
    CHECK(s.energy_every == 0.25);
    REQUIRE(s.max_energy_error.has_value());
    CHECK(*s.max_energy_error == 3e-7);
    CHECK(s.initial_states);
    CHECK(s.final_states);
    CHECK(s.output_dir == "runs/E400 \"x\"");
    CHECK_FALSE(s.images);
    CHECK(s.formats == std::vector<std::string>{"hdf5", "fits"});
    CHECK(s.writes_format("fits"));
    CHECK(s.cap_center == std::array<double, 2>{10, -20.5});
    CHECK(s.cap_radius == 3.5);
    CHECK(s.box_lon == std::array<double, 2>{-10, 20});
    CHECK(s.box_lat == std::array<double, 2>{60, 70});
    CHECK(s.gaussian_mean == std::array<double, 2>{3.873, 3.873});
    CHECK(s.gaussian_sigma == std::array<double, 2>{0.01, 0.02});
    CHECK(s.zoom);
    CHECK(s.zoom_center == std::array<double, 2>{45, 35.26});
    CHECK(s.zoom_width == 8.0);
    CHECK(s.zoom_resolution == 1024);
    CHECK(s.confine);
    CHECK(s.confine_width == 8.5);
    CHECK(s.frame_times == std::vector<double>{0, 100, 1e3, 1e4});
    CHECK(s.observes("observe.fli"));
    CHECK(s.observes("observe.megno"));
    CHECK(s.observes("observe.lyapunov"));
    CHECK(s.output_value("observe.tangent_initial") == std::vector<double>{1, 0, 0, 0, 0, 2});
    CHECK(s.output_value("observe.frequencies") == std::vector<double>{1});
    CHECK(s.output_value("observe.frequencies.samples") == std::vector<double>{1024});
    CHECK(s.output_value("observe.frequencies.every") == std::vector<double>{0.05});
    CHECK(s.output_value("observe.frequencies.window") == std::vector<double>{2});
    CHECK(s.output_value("observe.diffusion") == std::vector<double>{1});
    CHECK(s.output_value("observe.diffusion.every") == std::vector<double>{20.0});
    CHECK(s.output_value("observe.diffusion.along") == std::vector<double>{1, 2, 0});
    CHECK(s.output_value("observe.diffusion.across") == std::vector<double>{2, -1, 0});
    CHECK(s.output_value("observe.diffusion.fit_from") == std::vector<double>{100});
    CHECK(s.output_value("observe.diffusion.average") == std::vector<double>{10.0});
    CHECK(s.output_value("observe.diffusion.average_every") == std::vector<double>{0.5});
    CHECK(s.grid_kind == "plane");
    CHECK(s.grid_nside == 32);
    CHECK(s.grid_resolution == std::array<double, 2>{128, 256});
    CHECK(s.grid_range1 == std::array<double, 2>{-1, 2});
    CHECK(s.grid_range2 == std::array<double, 2>{-0.25, 1.75});
    CHECK(s.grid_axes == std::array<double, 2>{1, 2});
    CHECK(s.grid_fixed == 0.5);
    CHECK(s.grid_position == std::vector<double>{0.1, 0.2, 0.3});
    REQUIRE(s.panels.size() == 1);
    CHECK(s.panels[0].name == "b");
    CHECK(s.panels[0].title == "zoom (b)");
    CHECK(s.panels[0].sets == std::vector<std::string>{"ensemble.initial=cap"});

    // Every key of the table was read and its position recorded.
    for (const auto& k : arnoldweb::scene_keys()) {
      CAPTURE(k.key);
      if (k.key == "ensemble.file") continue;  // names an existing file: tests/states/test_state_file.cpp
      CHECK(s.where.count(k.key) == 1);
      CHECK(s.pos(k.key).line > 0);
    }
    CHECK(s.pos("model.energy").line == line_of(text, "energy = "));
    CHECK(s.pos("model.energy").column == 1);
    CHECK(s.pos("observe.velocity_map").line == line_of(text, "velocity_map = "));
    CHECK(s.pos("observe.velocity_map.nside").line == line_of(text, "velocity_map = "));
    CHECK(s.pos("observe.velocity_map.nside").column == 18);
    CHECK(s.pos("observe.energy_error.every").column == 18);
    CHECK(s.origin("run.device") == "<test>:" + std::to_string(line_of(text, "device = ")) + ":1");
  }

  TEST_CASE("integers are accepted where floats are expected") {
    const Scene s = parse(
        "[model]\nenergy = 15\n[integrator]\nstep = 1\n"
        "[run]\naverage = 50\nduration = 100\n[observe]\nenergy_error = { every = 2 }\n"
        "max_energy_error = 1\n",
        {"integrator.tolerance=1e-9"});
    CHECK(s.energy == 15.0);
    CHECK(s.step == 1.0);
    CHECK(s.average == 50.0);
    CHECK(s.duration == 100.0);
    CHECK(s.energy_every == 2.0);
    CHECK(s.max_energy_error == 1.0);
    CHECK(s.tolerance == 1e-9);
  }

  TEST_CASE("composite keys: velocity_map and energy_error") {
    Scene s = parse("[observe]\nvelocity_map = false\nenergy_error = false\n");
    CHECK_FALSE(s.velocity_map);
    CHECK_FALSE(s.energy_error);
    s = parse("[observe]\nvelocity_map = true\nenergy_error = true\n");
    CHECK(s.velocity_map);
    CHECK(s.nside == 64);
    CHECK(s.energy_error);
    CHECK(s.energy_every == 1.0);
    s = parse("[observe]\nvelocity_map = {}\nenergy_error = {}\n");
    CHECK(s.velocity_map);
    CHECK(s.energy_error);
    s = parse("[observe.velocity_map]\nnside = 1\n[observe.energy_error]\nevery = 0.5\n");
    CHECK(s.nside == 1);
    CHECK(s.energy_every == 0.5);
    CHECK(s.pos("observe.velocity_map.nside").line == 2);
    s = parse("observe.velocity_map.nside = 256\n");  // dotted keys at the top level
    CHECK(s.nside == 256);
    CHECK(s.pos("observe.velocity_map.nside").line == 1);
  }

  TEST_CASE("step = \"auto\"") {
    const Scene s = parse("[integrator]\nstep = \"auto\"\ntolerance = 1e-6\n");
    CHECK(s.step_auto);
    CHECK(s.tolerance == 1e-6);
    CHECK(s.pos("integrator.step").line == 2);
  }

  TEST_CASE("limits that are allowed") {
    CHECK(parse("[model]\nenergy = -1.999\n").energy == -1.999);
    CHECK(parse("[model]\nenergy = 1e6\n").energy == 1e6);
    CHECK(parse("[ensemble]\ntrajectories = 1\n").trajectories == 1);
    CHECK(parse("[ensemble]\nseed = 0\nchunk = 0\n").seed == 0);
    CHECK(parse("[ensemble]\nseed = 9223372036854775807\n").seed == 9223372036854775807ull);
    CHECK(parse("[integrator]\nstep = 1.0\n").step == 1.0);
    CHECK(parse("[run]\ndevice = \"cpu\"\n").device == "cpu");
    CHECK(parse("[run]\ndevice = \"auto\"\n").device == "auto");
    CHECK(parse("[run]\ndevice = \"cuda:12\"\n").device == "cuda:12");
    CHECK(parse("[run]\ndevice = \"opencl:0\"\n").device == "opencl:0");
    for (const auto& m : arnoldweb::methods())
      CHECK(parse("[integrator]\nmethod = \"" + m.name + "\"\n").method == m.name);
  }

  TEST_CASE("bad values name the key, the position of the value and what is allowed") {
    const std::string methods = arnoldweb::method_names();
    const std::vector<Bad> cases = {
        // [model]
        {"[model]\nenergy = -2e6\n", "model.energy", 2, 10, {"must be a float from -1e6 to 1e6", "got -2"}},
        {"[model]\nenergy = 1000000.5\n", "model.energy", 2, 10, {"to 1e6", "got 1000000.5"}},
        {"[model]\nenergy = \"15\"\n", "model.energy", 2, 10,
         {"must be a float", "got string \"15\""}},
        {"[model]\nenergy = nan\n", "model.energy", 2, 10, {"must be a float", "got nan"}},
        {"[model]\nenergy = inf\n", "model.energy", 2, 10, {"got inf"}},
        {"[model]\n  energy = [15]\n", "model.energy", 2, 12, {"got array"}},
        // [ensemble]
        {"[ensemble]\ntrajectories = -5\n", "ensemble.trajectories", 2, 16,
         {"must be an integer from 1 to 1e13, got -5"}},
        {"[ensemble]\ntrajectories = 0\n", "ensemble.trajectories", 2, 16, {"got 0"}},
        {"[ensemble]\ntrajectories = 10_000_000_000_001\n", "ensemble.trajectories", 2, 16,
         {"from 1 to 1e13", "got 10000000000001"}},
        {"[ensemble]\ntrajectories = 1e6\n", "ensemble.trajectories", 2, 16,
         {"must be an integer", "got float 1e+06", "write it as an integer: 1000000"}},
        {"[ensemble]\ntrajectories = 2.5\n", "ensemble.trajectories", 2, 16, {"got float 2.5"}},
        {"[ensemble]\nseed = -1\n", "ensemble.seed", 2, 8, {"must be an integer >= 0", "got -1"}},
        {"[ensemble]\ninitial = \"disc\"\n", "ensemble.initial", 2, 11,
         {"must be one of \"shell\", \"cap\", \"box\", \"gaussian\"", "got \"disc\""}},
        {"[ensemble]\ncap = { center = [10, 95], radius = 3 }\n", "ensemble.cap.center", 2, 18,
         {"latitude from -90 to 90", "(2 values)"}},
        {"[ensemble]\nbox = { lon = [10, 5], lat = [0, 1] }\n", "ensemble.box.lon", 2, 15,
         {"from < to"}},
        {"[ensemble]\ngaussian = { mean = [1, 2, 3] }\n", "ensemble.gaussian.mean", 2, 21,
         {"an array [p_x, p_y]", "(3 values)"}},
        {"[observe]\nzoom = { width = 200 }\n", "observe.zoom.width", 2, 18, {"less than 120"}},
        {"[observe]\nzoom = true\n", "observe.zoom", 2, 8, {"give the table"}},
        {"[observe]\nframes = { times = [0, 10, 5] }\n", "observe.frames.times", 2, 20,
         {"increasing"}},
        {"[[panel]]\nname = \"a b\"\n", "panel.name", 2, 8, {"letters, digits"}},

        {"[ensemble]\nchunk = -1\n", "ensemble.chunk", 2, 9, {"must be an integer >= 0"}},
        // [integrator]
        {"[integrator]\nmethod = \"yoshida7\"\n", "integrator.method", 2, 10,
         {"must be one of \"leapfrog\"", "got \"yoshida7\""}},
        {"[integrator]\nmethod = \"Yoshida6a\"\n", "integrator.method", 2, 10,
         {"did you mean \"yoshida6a\"?"}},
        {"[integrator]\nstep = 0\n", "integrator.step", 2, 8,
         {"must be a float greater than 0 and at most 1", "or \"auto\"", "got 0"}},
        {"[integrator]\nstep = 1.5\n", "integrator.step", 2, 8, {"got 1.5"}},
        {"[integrator]\nstep = -inf\n", "integrator.step", 2, 8, {"got -inf"}},
        {"[integrator]\nstep = \"fast\"\n", "integrator.step", 2, 8,
         {"or \"auto\"", "got \"fast\""}},
        {"[integrator]\nstep = true\n", "integrator.step", 2, 8, {"got boolean true"}},
        {"[integrator]\ntolerance = 1\n", "integrator.tolerance", 2, 13,
         {"greater than 0 and less than 1", "got 1"}},
        {"[integrator]\ntolerance = 0.0\n", "integrator.tolerance", 2, 13, {"got 0"}},
        {"[integrator]\nprecision = \"single\"\n", "integrator.precision", 2, 13,
         {"must be one of \"double\", \"float\"", "got \"single\""}},
        {"[integrator]\nmath = \"fast\"\n", "integrator.math", 2, 8,
         {"must be one of \"portable\", \"native\""}},
        {"[integrator]\nallow_unsafe_step = 1\n", "integrator.allow_unsafe_step", 2, 21,
         {"must be true or false, got integer 1"}},
        // [run]
        {"[run]\naverage = 0\n", "run.average", 2, 11, {"finite float greater than 0", "got 0"}},
        {"[run]\nduration = -50\n", "run.duration", 2, 12, {"got -50"}},
        {"[run]\nduration = inf\n", "run.duration", 2, 12, {"got inf"}},
        {"[run]\ndevice = \"gpu\"\n", "run.device", 2, 10,
         {"\"auto\", \"all\", \"cpu\", \"opencl:N\", \"cuda:N\" or a list", "got \"gpu\""}},
        {"[run]\ndevice = \"opencl:\"\n", "run.device", 2, 10, {"got \"opencl:\""}},
        {"[run]\ndevice = \"cuda:-1\"\n", "run.device", 2, 10, {"got \"cuda:-1\""}},
        {"[run]\ndevice = 0\n", "run.device", 2, 10, {"got integer 0"}},
        // issue 37: an index as `arnoldweb devices` writes it (opencl:00 passed the form and named no device)
        {"[run]\ndevice = \"opencl:00\"\n", "run.device", 2, 10, {"got \"opencl:00\""}},
        {"[run]\ndevice = \"cpu,cuda:01\"\n", "run.device", 2, 10, {"got \"cpu,cuda:01\""}},
        // issue 37: directions normalised by their length, which must neither overflow nor underflow
        {"[observe.diffusion]\nalong = [1e200, 1e200, 0]\n", "observe.diffusion.along", 2, 9,
         {"largest absolute component from 1e-150 to 1e150", "got [1e+200, 1e+200, 0]", "cannot be computed"}},
        {"[observe.diffusion]\nalong = [1e-170, 1e-170, 0]\n", "observe.diffusion.along", 2, 9,
         {"from 1e-150 to 1e150", "got [1e-170, 1e-170, 0]"}},
        {"[observe.diffusion]\nacross = [0, 0, 0]\n", "observe.diffusion.across", 2, 10,
         {"from 1e-150 to 1e150", "the zero vector has no direction"}},
        {"[observe.diffusion]\nacross = [1, nan, 0]\n", "observe.diffusion.across", 2, 10, {"got [1, nan, 0]"}},
        {"[observe]\ntangent_initial = [0, 0, 0, 0, 0, 1e-200]\n", "observe.tangent_initial", 2, 19,
         {"an array of 6 floats, largest absolute component from 1e-150 to 1e150"}},
        {"[observe]\ntangent_initial = [1e151, 0, 0, 0, 0, 1]\n", "observe.tangent_initial", 2, 19,
         {"cannot be computed"}},
        // [observe]
        {"[observe]\nvelocity_map = { nside = 63 }\n", "observe.velocity_map.nside", 2, 26,
         {"must be a power of two from 1 to 8192, got 63"}},
        {"[observe]\nvelocity_map = { nside = 16384 }\n", "observe.velocity_map.nside", 2, 26,
         {"got 16384"}},
        {"[observe]\nvelocity_map = { nside = 0 }\n", "observe.velocity_map.nside", 2, 26,
         {"got 0"}},
        {"[observe]\nvelocity_map = { nside = 64.0 }\n", "observe.velocity_map.nside", 2, 26,
         {"got float 64", "write it as an integer: 64"}},
        {"[observe]\nvelocity_map = \"yes\"\n", "observe.velocity_map", 2, 16,
         {"must be a table { nside = N }, true (nside 64) or false", "got string \"yes\""}},
        {"[observe]\nenergy_error = 3\n", "observe.energy_error", 2, 16,
         {"must be true, false or a table { every =", "got integer 3"}},
        {"[observe]\nenergy_error = { every = 0 }\n", "observe.energy_error.every", 2, 26,
         {"finite float greater than 0", "got 0"}},
        {"[observe]\nmax_energy_error = -1e-6\n", "observe.max_energy_error", 2, 20,
         {"greater than 0", "got -1e-06"}},
        {"[observe]\ninitial_states = \"yes\"\n", "observe.initial_states", 2, 18,
         {"must be true or false", "got string \"yes\""}},
        {"[observe]\nfinal_states = 1\n", "observe.final_states", 2, 16, {"got integer 1"}},
        // [output]
        {"[output]\ndir = \"\"\n", "output.dir", 2, 7, {"must be a non-empty string", "got \"\""}},
        {"[output]\ndir = 3\n", "output.dir", 2, 7, {"got integer 3"}},
        {"[output]\nimages = \"no\"\n", "output.images", 2, 10, {"must be true or false"}},
    };
    for (const Bad& c : cases) {
      CAPTURE(c.toml);
      const SceneError e = error_of(c.toml);
      CHECK(e.key() == c.key);
      CHECK(e.file() == "<test>");
      CHECK(e.line() == c.line);
      CHECK(e.column() == c.column);
      for (const std::string& part : c.says) {
        CAPTURE(part);
        CHECK(contains(e.message(), part));
      }
      CHECK(contains(e.what(), "<test>:" + std::to_string(c.line) + ":" +
                                   std::to_string(c.column) + ": " + c.key + ": must be "));
    }
    // The method list in the message is the library's.
    CHECK(contains(error_of("[integrator]\nmethod = \"x\"\n").message(),
                   "\"" + arnoldweb::methods().back().name + "\""));
  }

  TEST_CASE("unknown sections and keys: position of the key and the closest known key") {
    const std::vector<Bad> cases = {
        {"[modle]\nenergy = 3\n", "modle", 1, 2,
         {"unknown section", "did you mean 'model'?", "sections: model, ensemble"}},
        {"energy = 3\n", "energy", 1, 1,
         {"unknown key", "did you mean 'model.energy'?", "belongs to a section"}},
        {"[integrator]\nmethod = \"leapfrog\"\nstepsize = 0.1\n", "integrator.stepsize", 3, 1,
         {"unknown key", "did you mean 'integrator.step'?",
          "keys of [integrator]: method, step, tolerance"}},
        {"[run]\n  seed = 3\n", "run.seed", 2, 3, {"did you mean 'ensemble.seed'?"}},
        {"[observe]\nvelocity_map = { nsid = 64 }\n", "observe.velocity_map.nsid", 2, 18,
         {"did you mean 'observe.velocity_map.nside'?", "keys of observe.velocity_map: nside"}},
        {"[observe.energy_error]\nevry = 2\n", "observe.energy_error.evry", 2, 1,
         {"did you mean 'observe.energy_error.every'?"}},
        {"[model.extra]\nx = 1\n", "model.extra", 1, 8, {"unknown key", "keys of [model]: energy"}},
        {"[output]\nfoo = 1\n", "output.foo", 2, 1, {"unknown key ("}},
        {"model = 3\n", "model", 1, 9, {"must be a table (the section [model]), got integer 3"}},
        {"[[run]]\ndevice = \"cpu\"\n", "run", 1, 1, {"must be a table", "got array"}},
    };
    for (const Bad& c : cases) {
      CAPTURE(c.toml);
      const SceneError e = error_of(c.toml);
      CHECK(e.key() == c.key);
      CHECK(e.line() == c.line);
      CHECK(e.column() == c.column);
      for (const std::string& part : c.says) {
        CAPTURE(part);
        CHECK(contains(e.message(), part));
      }
    }
    // No suggestion when nothing is near.
    CHECK_FALSE(contains(error_of("[output]\nfoo = 1\n").message(), "did you mean"));
  }

  TEST_CASE("TOML syntax errors carry the parser's line and column") {
    SceneError e = error_of("[model]\nenergy = 15\n[run\n");
    CHECK(e.key().empty());
    CHECK(e.line() == 3);
    CHECK(e.column() >= 4);
    CHECK(contains(e.message(), "TOML syntax error"));
    e = error_of("[model]\nenergy = 15\nenergy = 16\n");  // duplicate key
    CHECK(e.line() == 3);
    CHECK(contains(e.message(), "TOML syntax error"));
    e = error_of("[run]\naverage = 1..0\n");
    CHECK(e.line() == 2);
    e = error_of("[ensemble]\ntrajectories = 99999999999999999999\n");  // beyond int64
    CHECK(e.line() == 2);
    CHECK(contains(e.what(), "<test>:2:"));
  }

  TEST_CASE("the first problem in file order is the one reported") {
    const SceneError e =
        error_of("[output]\ndir = \"\"\n[model]\nenergy = -5e6\n[typo]\n", {"ensemble.seed=-1"});
    CHECK(e.key() == "output.dir");
    CHECK(e.line() == 2);
    const SceneError f = error_of("[model]\nenergy = -5e6\n[typo]\n");
    CHECK(f.key() == "model.energy");
    // File problems before override problems.
    const SceneError g = error_of("[run]\nduration = 0\n", {"model.energy=-5e6"});
    CHECK(g.key() == "run.duration");
  }

  TEST_CASE("load_scene: a file, a missing file, a directory") {
    const std::string dir = awtest::temp_dir("scene");
    const std::string path = dir + "/e400.toml";
    {
      std::ofstream f(path);
      f << "# comment\n[model]\nenergy = 400\n";
    }
    const Scene s = arnoldweb::load_scene(path, {"ensemble.seed=7"});
    CHECK(s.file == path);
    CHECK(s.energy == 400.0);
    CHECK(s.seed == 7);
    CHECK(s.pos("model.energy").line == 3);
    CHECK(s.origin("model.energy") == path + ":3:1");

    const std::string missing = dir + "/nope.toml";
    try {
      arnoldweb::load_scene(missing);
      FAIL("no error for a missing file");
    } catch (const SceneError& e) {
      CHECK(e.file() == missing);
      CHECK(e.line() == 0);
      CHECK(contains(e.message(), "cannot read the scene file"));
      CHECK(contains(e.message(), std::strerror(ENOENT)));
      CHECK(std::string(e.what()) == missing + ": " + e.message());
      CHECK(e.exit_code() == 2);
    }
    try {
      arnoldweb::load_scene(dir);
      FAIL("no error for a directory");
    } catch (const SceneError& e) {
      CHECK(e.file() == dir);
      CHECK(contains(e.message(), "directory"));
    }
    const std::string bad = dir + "/bad.toml";
    {
      std::ofstream f(bad);
      f << "[ensemble]\ntrajectories = -5\n";
    }
    try {
      arnoldweb::load_scene(bad);
      FAIL("no error for a bad value");
    } catch (const SceneError& e) {
      CHECK(std::string(e.what()) ==
            bad + ":2:16: ensemble.trajectories: must be an integer from 1 to 1e13, got -5");
    }
  }

  TEST_CASE("numbers written by the tests' awtest::num and awtest::set read back exactly, in the file and in --set") {
    // The tests write numbers held in variables into scenes this way
    // (tests/support/support.hpp): a value that did not read back exactly
    // would quietly change what a test runs.
    CHECK(awtest::num(15.0) == "15");
    CHECK(awtest::num(0.1) == "0.1");
    CHECK(awtest::num(-1.9) == "-1.9");
    CHECK(awtest::num(1e-300) == "1e-300");
    for (double x : {15.0, 400.0, -1.9, 0.01, 0.0008, 1.0 / 3.0, 0.1 + 0.2, std::sqrt(15.0), 1.0 / 101, 1e-300,
                     2.5e-8, 123456789.125, 0.25 / 7}) {
      CAPTURE(x);
      const double t = std::fabs(x);  // run.duration > 0; the signs go through ensemble.gaussian.mean
      CHECK(parse("[run]\nduration = " + awtest::num(t) + "\n").duration == t);
      CHECK(parse("", {awtest::set("run.duration", t)}).duration == t);
      const Scene g = parse("", {awtest::set("ensemble.gaussian.mean", std::array<double, 2>{x, -x})});
      CHECK(g.gaussian_mean[0] == x);
      CHECK(g.gaussian_mean[1] == -x);
    }
    const std::uint64_t many = std::uint64_t{1} << 40;
    CHECK(parse("", {awtest::set("ensemble.trajectories", many)}).trajectories == many);
    CHECK(parse("", {awtest::set("observe.initial_states", true)}).initial_states);
    CHECK(parse("", {awtest::set("integrator.method", "saba4")}).method == "saba4");
    CHECK(parse("", {awtest::set("output.dir", std::string("a \"b\"\\c"))}).output_dir == "a \"b\"\\c");
    const std::vector<double> times = {0, 0.5, 1.5};
    CHECK(parse("[run]\naverage = 0.5\nduration = 2\n", {awtest::set("observe.frames.times", times)}).frame_times ==
          times);
  }

  TEST_CASE("--set: numbers, strings, bare strings, tables") {
    const Scene s = parse("[model]\nenergy = 15\n[observe]\nvelocity_map = false\n",
                          {"model.energy=3", "integrator.method=\"leapfrog\"",
                           "run.device=opencl:0", "output.dir=/tmp/x y",
                           "observe.velocity_map.nside=128", "ensemble.trajectories = 1_000",
                           "integrator.step=auto", "observe.max_energy_error=1e-5"});
    CHECK(s.energy == 3.0);
    CHECK(s.method == "leapfrog");
    CHECK(s.device == "opencl:0");
    CHECK(s.output_dir == "/tmp/x y");
    CHECK(s.velocity_map);  // setting nside turns the map on
    CHECK(s.nside == 128);
    CHECK(s.trajectories == 1000);
    CHECK(s.step_auto);
    CHECK(s.max_energy_error == 1e-5);
    REQUIRE(s.overrides.size() == 8);
    CHECK(s.overrides[0] == "model.energy=3");

    // An overridden key points at its override, not at the file.
    CHECK(s.pos("model.energy").line == 0);
    CHECK(s.pos("model.energy").set_index == 1);
    CHECK(s.origin("model.energy") == "--set model.energy=3");
    CHECK(s.pos("observe.velocity_map.nside").set_index == 5);
    CHECK(s.pos("observe.velocity_map").set_index == 5);
    CHECK(s.origin("ensemble.seed") == "default");

    // Bare words for strings; numbers typed as strings stay text for string keys.
    CHECK(parse("", {"integrator.method=leapfrog"}).method == "leapfrog");
    CHECK(parse("", {"output.dir=2024"}).output_dir == "2024");
    CHECK(parse("", {"output.dir='C:\\x'"}).output_dir == "C:\\x");
    CHECK(parse("", {"run.device=cuda:1"}).device == "cuda:1");
    // Whole tables and booleans.
    CHECK(parse("", {"observe.velocity_map={ nside = 32 }"}).nside == 32);
    CHECK_FALSE(parse("", {"observe.velocity_map=false"}).velocity_map);
    CHECK_FALSE(parse("", {"observe.energy_error=false"}).energy_error);
    CHECK(parse("", {"observe.energy_error.every=0.5"}).energy_every == 0.5);
    CHECK(parse("", {"integrator.allow_unsafe_step=true"}).allow_unsafe_step);
    CHECK(parse("", {"integrator.step=0.005"}).step == 0.005);
  }

  TEST_CASE("--set: the later override wins, and overrides win over the file") {
    Scene s = parse("[model]\nenergy = 5\n", {"model.energy=3"});
    CHECK(s.energy == 3.0);
    // but a wrong value in the file is an error whatever overrides it (issue 27, item 9)
    const SceneError bad = error_of("[model]\nenergy = \"abc\"\n", {"model.energy=3"});
    CHECK(bad.file() == "<test>");
    CHECK(bad.line() == 2);
    CHECK(bad.key() == "model.energy");
    s = parse("", {"model.energy=3", "model.energy=4"});
    CHECK(s.energy == 4.0);
    CHECK(s.pos("model.energy").set_index == 2);
    s = parse("[observe]\nvelocity_map = { nside = 16 }\n",
              {"observe.velocity_map.nside=128", "observe.velocity_map={nside=32}"});
    CHECK(s.nside == 32);
    CHECK(s.pos("observe.velocity_map.nside").set_index == 2);
    s = parse("[observe]\nvelocity_map = { nside = 16 }\n", {"observe.velocity_map=false"});
    CHECK_FALSE(s.velocity_map);
    s = parse("[observe]\nenergy_error = { every = 2.0 }\n", {"observe.energy_error.every=5"});
    CHECK(s.energy_every == 5.0);
    CHECK(s.pos("observe.energy_error").line == 2);
    CHECK(s.pos("observe.energy_error.every").set_index == 1);
  }

  TEST_CASE("issue 39: observe.diffusion = true switches the actions row's table key on at its defaults") {
    const Scene on = awtest::scene_from("[observe]\ndiffusion = true\n");
    CHECK(on.output_value("observe.diffusion") == std::vector<double>{1});
    CHECK(on.output_value("observe.diffusion.every") == std::vector<double>{10.0});
    CHECK(on.output_value("observe.diffusion.along") == std::vector<double>{1, 1, 0});
    // average_every is taken only with average: not in the echo at average = 0
    CHECK(on.to_toml().find("diffusion = { every = 10.0, along = [1.0, 1.0, 0.0], across = [1.0, -1.0, 0.0], "
                            "fit_from = 0.0 }\n") != std::string::npos);
    const Scene off = awtest::scene_from("[observe]\ndiffusion = false\n");
    CHECK(off.output_value("observe.diffusion").empty());
    CHECK(off.to_toml().find("diffusion = false\n") != std::string::npos);
    const Scene averaged = awtest::scene_from("", {"observe.diffusion.average=2"});
    CHECK(averaged.output_value("observe.diffusion") == std::vector<double>{1});
    CHECK(averaged.to_toml().find("average = 2.0, average_every = 1.0 }") != std::string::npos);
  }

  TEST_CASE("issue 39: observe.frequencies is the frequencies row's table key: true, a table, a sub-key, false") {
    const Scene on = awtest::scene_from("[observe]\nfrequencies = true\n");
    CHECK(on.output_value("observe.frequencies") == std::vector<double>{1});
    CHECK(on.output_value("observe.frequencies.samples") == std::vector<double>{512});
    CHECK(on.output_value("observe.frequencies.every") == std::vector<double>{0.1});
    CHECK(on.output_value("observe.frequencies.window") == std::vector<double>{1});
    CHECK(on.to_toml().find("frequencies = { samples = 512, every = 0.1, window = 1 }\n") != std::string::npos);
    const Scene off = awtest::scene_from("[observe]\nfrequencies = { samples = 64 }\n", {"observe.frequencies=false"});
    CHECK(off.output_value("observe.frequencies").empty());
    CHECK(off.output_value("observe.frequencies.samples") == std::vector<double>{512});
    CHECK(off.to_toml().find("frequencies = false\n") != std::string::npos);
    // a sub-key alone switches the analysis on, as before the table key
    const Scene window = awtest::scene_from("", {"observe.frequencies.window=0"});
    CHECK(window.output_value("observe.frequencies") == std::vector<double>{1});
    CHECK(window.to_toml().find("frequencies = { samples = 512, every = 0.1, window = 0 }\n") != std::string::npos);
  }

  TEST_CASE("issue 37: directions at the ends of the allowed range are read as written") {
    const Scene s = awtest::scene_from("", {"observe.diffusion.along=[1e-150, 1e-151, 0]",
                                            "observe.diffusion.across=[-1e150, 1e150, 1e150]",
                                            "observe.tangent_initial=[0, 0, 0, 0, 0, -1e-150]"});
    CHECK(s.output_value("observe.diffusion.along") == std::vector<double>{1e-150, 1e-151, 0});
    CHECK(s.output_value("observe.diffusion.across") == std::vector<double>{-1e150, 1e150, 1e150});
    CHECK(s.output_value("observe.tangent_initial").back() == -1e-150);
  }

  TEST_CASE("issue 37: a label a user typed is echoed with its control characters escaped") {
    std::string what;
    try {
      arnoldweb::parse_scene("", "<test>", {"run.device=cpu\nx\x1b[31m"}, {"--device cpu\nx\x1b[31m"});
    } catch (const SceneError& e) {
      CHECK(e.file() == "--device cpu\nx\x1b[31m");  // as given, for callers
      what = e.what();
    }
    CHECK(what.rfind("--device cpu\\nx\\u001b[31m: run.device: must be ", 0) == 0);
    CHECK(what.find('\n') == std::string::npos);
    CHECK(what.find('\x1b') == std::string::npos);
    CHECK(arnoldweb::printable("caf\xc3\xa9 \xff\xc2\x9b\t") == "caf\xc3\xa9 \\xff\\u009b\\t");
  }

  TEST_CASE("--set: bad overrides name the override") {
    SceneError e = error_of("", {"intgrator.step=0.1"});
    CHECK(e.file() == "--set intgrator.step=0.1");
    CHECK(e.key() == "intgrator.step");
    CHECK(e.line() == 0);
    CHECK(contains(e.message(), "unknown key; did you mean 'integrator.step'?"));
    CHECK(std::string(e.what()).rfind("--set intgrator.step=0.1: intgrator.step: unknown key", 0) ==
          0);

    e = error_of("", {"model.energy=3", "ensemble.trajectories=-5"});
    CHECK(e.file() == "--set ensemble.trajectories=-5");
    CHECK(e.key() == "ensemble.trajectories");
    CHECK(e.message() == "must be an integer from 1 to 1e13, got -5");

    e = error_of("", {"integrator.step=fast"});
    CHECK(contains(e.message(), "got \"fast\""));
    e = error_of("", {"observe.velocity_map.nside=100"});
    CHECK(e.key() == "observe.velocity_map.nside");
    CHECK(contains(e.message(), "power of two"));
    e = error_of("", {"observe.velocity_map={nsid=64}"});
    CHECK(e.key() == "observe.velocity_map.nsid");
    CHECK(e.file() == "--set observe.velocity_map={nsid=64}");
    e = error_of("", {"model.energy"});
    CHECK(contains(e.message(), "an override is key=value"));
    e = error_of("", {"=3"});
    CHECK(contains(e.message(), "an override is key=value"));
    e = error_of("", {"model=3"});
    CHECK(e.key() == "model");
    CHECK(contains(e.message(), "is a section"));
    CHECK(contains(e.message(), "--set model.energy="));
    e = error_of("", {"output.dir="});
    CHECK(e.key() == "output.dir");
    CHECK(contains(e.message(), "non-empty"));
    e = error_of("", {"modle.energy=3"});
    CHECK(contains(e.message(), "did you mean 'model.energy'?"));
  }

  TEST_CASE("to_toml: every key, stable order, reads back to the same scene") {
    const Scene d;
    const std::string text = d.to_toml();
    // Sections in order, every top-level key present with its default.
    std::size_t at = 0;
    for (const char* section : {"[model]", "[ensemble]", "[integrator]", "[run]", "[observe]",
                                "[output]"}) {
      const std::size_t next = text.find(section, at);
      CAPTURE(section);
      REQUIRE(next != std::string::npos);
      at = next;
    }
    CHECK(contains(text, "\nenergy = 15.0\n"));  // stays a float
    CHECK(contains(text, "\nstep = 0.01\n"));
    CHECK(contains(text, "\ntolerance = 1e-08\n"));
    CHECK(contains(text, "\nvelocity_map = { nside = 64 }\n"));
    CHECK(contains(text, "\nenergy_error = { every = 1.0 }\n"));
    CHECK(contains(text, "# max_energy_error is not set\n"));
    check_same(parse(text), d);

    // A scene with every key changed, read back and written again.
    const Scene full = parse(full_scene(), {"model.energy=0.30000000000000004"});
    const std::string full_text = full.to_toml();
    CHECK(contains(full_text, "# --set model.energy=0.30000000000000004\n"));
    const Scene back = parse(full_text);
    check_same(back, full);
    CHECK(back.energy == 0.1 + 0.2);
    CHECK(back.to_toml().substr(back.to_toml().find("[model]")) ==
          full_text.substr(full_text.find("[model]")));

    // Disabled composites, "auto", unusual doubles and strings.
    Scene odd;
    odd.velocity_map = false;
    odd.energy_error = false;
    odd.step_auto = true;
    odd.energy = 1e-300;
    odd.average = 1.0 / 3.0;
    odd.duration = 123456789.125;
    odd.max_energy_error = 5e-324;
    odd.output_dir = "a\\b \"q\"\n\tz\x01";
    odd.file = "x\ny.toml";
    const std::string odd_text = odd.to_toml();
    CHECK(contains(odd_text, "\nvelocity_map = false\n"));
    CHECK(contains(odd_text, "\nstep = \"auto\"\n"));
    check_same(parse(odd_text), odd);
  }

  TEST_CASE("scene_keys: complete, documented, and each key is read") {
    const auto& keys = arnoldweb::scene_keys();
    std::vector<std::string> names;
    for (const auto& k : keys) names.push_back(k.key);
    std::sort(names.begin(), names.end());
    CHECK(std::adjacent_find(names.begin(), names.end()) == names.end());  // every key once
    const Scene d;
    const std::string text = d.to_toml();
    for (const auto& k : keys) {
      CAPTURE(k.key);
      CHECK_FALSE(k.type.empty());
      CHECK_FALSE(k.allowed.empty());
      CHECK_FALSE(k.default_value.empty());
      CHECK_FALSE(k.meaning.empty());
      // Fits a Markdown table cell.
      CHECK((k.type + k.allowed + k.default_value + k.meaning).find('|') == std::string::npos);
      // The default is what to_toml writes for a default scene.
      const std::string leaf = k.key.substr(k.key.find('.') + 1);
      if (leaf.find('.') == std::string::npos && k.default_value != "(not set)")
        CHECK(contains(text, "\n" + leaf + " = " + k.default_value + "\n"));
      // Setting the key on its own (to its default) is accepted and recorded.
      if (k.default_value != "(not set)") {
        const Scene s = parse("", {k.key + "=" + k.default_value});
        // a part of a table that is off by default turns the table on
        const std::string table = k.key.substr(0, k.key.rfind('.'));
        const bool turns_on = table == "observe.zoom" || table == "observe.confine" ||
                              table == "observe.diffusion" || table == "observe.frequencies";
        if (turns_on)
          CHECK((s.zoom || s.confine || !s.output_value(table).empty()));
        else
          check_same(s, d);
        CHECK(s.pos(k.key).set_index == 1);
      }
    }
    CHECK(keys.front().key == "model.energy");
    CHECK(keys.front().default_value == "15.0");
    // The method list is the library's.
    for (const auto& k : keys)
      if (k.key == "integrator.method")
        for (const auto& m : arnoldweb::methods()) {
          CAPTURE(m.name);
          CHECK(contains(k.allowed, "\"" + m.name + "\""));
        }
  }

  TEST_CASE("docs/scenes.md's key list is the one generated from the key table") {
    std::ifstream f(std::string(ARNOLDWEB_SOURCE_DIR) + "/docs/scenes.md");
    REQUIRE(f.good());
    std::stringstream doc;
    doc << f.rdbuf();
    const std::string text = doc.str();
    const std::string begin = "<!-- keys:begin (generated by `arnoldweb keys --markdown`; do not edit by hand) -->\n";
    const auto a = text.find(begin);
    const auto b = text.find("<!-- keys:end -->");
    REQUIRE(a != std::string::npos);
    REQUIRE(b != std::string::npos);
    INFO("docs/scenes.md is stale: run `build/arnoldweb keys --markdown` and paste it between the markers");
    CHECK(text.substr(a + begin.size(), b - a - begin.size()) == arnoldweb::scene_keys_markdown());
  }
}
