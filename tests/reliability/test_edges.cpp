// Reliability: the edges of issue 27 (items 6-10 and 12): a NUL in a path,
// compare's significance level, Ctrl-\ with PoCL loaded, values in the file
// that an override replaces, panels, and the memory of a very large map. Each
// case failed before the fix it guards (ARNOLDWEB_TEST_CLI=<old build>).
#include <doctest/doctest.h>
#include <signal.h>

#include <filesystem>
#include <fstream>

#include "support.hpp"

namespace fs = std::filesystem;
using namespace arnoldweb;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string write(const std::string& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir + "/" + name) << text;
  return dir + "/" + name;
}

const std::string kQuick =
    "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 200\n[integrator]\nstep = 0.02\n"
    "[run]\naverage = 1.0\nduration = 1.0\n[observe]\nvelocity_map = { nside = 8 }\n[output]\nimages = false\n";

// A run of 20 million trajectories (tens of seconds) into dir/out, started
// and seen computing (its progress line).
awtest::StartedCli started_long_run(const std::string& dir) {
  const std::string scene = write(dir, "scene.toml", kQuick);
  awtest::StartedCli cli = awtest::start_cli({"run", scene, "--device", "cpu", "--out", dir + "/out", "--set",
                                              "ensemble.trajectories=20000000", "--set", "ensemble.chunk=2000"});
  REQUIRE(cli.wait_for("progress:", 60));
  return cli;
}

}  // namespace

TEST_SUITE("reliability") {
  TEST_CASE("6. a NUL in output.dir is refused naming output.dir (exit 2), not cut short") {
    const std::string dir = awtest::temp_dir("nul");
    const std::string scene = write(dir, "scene.toml", kQuick);
    for (const std::string value : {"\"\\u0000\"", "\"x\\u0000y\""}) {
      CAPTURE(value);
      std::string out;
      CHECK(awtest::run_cli({"check", scene, "--set", "output.dir=" + value}, &out) == 2);  // exit 3 before
      CAPTURE(out);
      CHECK(contains(out, "output.dir: must be a non-empty string without NUL characters"));
    }
    const std::string in_file = write(dir, "nul.toml", "[output]\ndir = \"out\\u0000put\"\n");
    std::string out;
    CHECK(awtest::run_cli({"check", in_file}, &out) == 2);
    CHECK(contains(out, "nul.toml:2:7: output.dir"));
    CHECK_FALSE(fs::exists(dir + "/out"));
  }

  TEST_CASE("7. compare --alpha outside (0, 1) or not a number is exit 2") {
    const std::string dir = awtest::temp_dir("alpha");
    for (const char* bad : {"nan", "0", "1e-400", "1", "inf", "-0.5", "2", "x", "0.1x"}) {
      CAPTURE(bad);
      std::string out;
      // checked before the directories are read: "different at alpha = nan" (exit 1) before
      CHECK(awtest::run_cli({"compare", dir, dir, "--alpha", bad}, &out) == 2);
      CHECK(contains(out, "--alpha must be a number strictly between 0 and 1"));
    }
  }

  TEST_CASE("9. a wrong value in the file is an error whatever overrides it") {
    const std::string dir = awtest::temp_dir("overridden");
    struct Case {
      std::string file;
      std::vector<std::string> args;
      std::string says;
    };
    const std::vector<Case> cases = {
        {"[output]\ndir = 5\n", {"--out", dir + "/x"}, "s.toml:2:7: output.dir: must be"},
        {"[model]\nenergy = \"abc\"\n", {"--set", "model.energy=15"}, "s.toml:2:10: model.energy: must be"},
        {"[run]\ndevice = 7\n", {"--device", "cpu"}, "s.toml:2:10: run.device: must be"},
        {"[observe]\nvelocity_map = { nside = 7 }\n", {"--set", "observe.velocity_map=false"},
         "s.toml:2:26: observe.velocity_map.nside: must be"},
    };
    for (const Case& c : cases) {
      CAPTURE(c.file);
      const std::string scene = write(dir, "s.toml", c.file);
      std::vector<std::string> args = {"check", scene};
      args.insert(args.end(), c.args.begin(), c.args.end());
      std::string out;
      CHECK(awtest::run_cli(args, &out) == 2);  // exit 0 before
      CAPTURE(out);
      CHECK(contains(out, c.says));
    }
    // a good value in the file is replaced as before
    const std::string scene = write(dir, "s.toml", "[model]\nenergy = 30.0\n[run]\naverage = 1.0\nduration = 1.0\n");
    std::string out;
    CHECK(awtest::run_cli({"check", scene, "--set", "model.energy=15", "--device", "cpu"}, &out) == 0);
    CHECK(contains(out, "E = 15"));
  }

  TEST_CASE("10. panels: panel.* cannot be overridden, a panel's set is blamed at its place, the step is blamed") {
    const std::string dir = awtest::temp_dir("panels");
    const std::string base = "[run]\naverage = 1.0\nduration = 1.0\n\n[[panel]]\nname = \"a\"\n";
    std::string out;
    // set = ["panel.name=b"] was ignored silently
    CHECK(awtest::run_cli({"check", write(dir, "rename.toml", base + "set = [\"panel.name=b\"]\n")}, &out) == 2);
    CHECK(contains(out, "rename.toml:7:8: [[panel]] a: panel.name=b: panel.name: is a key of the [[panel]] tables"));
    CHECK(awtest::run_cli({"check", write(dir, "cli.toml", base), "--set", "panel.title=x"}, &out) == 2);
    CHECK(contains(out, "--set panel.title=x: panel.title: is a key of the [[panel]] tables"));
    // a bad value in a panel's set carries the file, line and column of the set
    CHECK(awtest::run_cli({"check", write(dir, "bad.toml", base + "set = [\"run.average=1.0\", \"model.energy=abc\"]\n")},
                          &out) == 2);
    CHECK(contains(out, "bad.toml:7:27: [[panel]] a: model.energy=abc: model.energy: must be"));
    // integrator.step = 1e-300 in a file was blamed on run.duration, which the file does not set
    CHECK(awtest::run_cli({"check", write(dir, "step.toml", "[integrator]\nstep = 1e-300\n")}, &out) == 2);
    CHECK(contains(out, "step.toml:2:1: integrator.step: run.duration / integrator.step"));
    CHECK(awtest::run_cli({"check", write(dir, "duration.toml", "[integrator]\nstep = 1e-9\n[run]\nduration = 1e20\n"
                                                                "average = 1e20\n")},
                          &out) == 2);
    CHECK(contains(out, "duration.toml:4:1: run.duration: run.duration / integrator.step"));
  }

  TEST_CASE("12. memory is planned by what the run holds: on a CPU device its buffers are this process's memory") {
    // nside 8192 with 2,000 trajectories on the cpu backend of a 24 GiB machine with
    // 22 GiB available: 9216 MiB of histograms on the "device" (this process's
    // memory) and 18.4 GiB of results and copies in the process; it passed before
    const Plan p = make_plan(awtest::scene_from(kQuick, {"observe.velocity_map.nside=8192",
                                                         "ensemble.trajectories=2000"}));
    const double gib = 1024.0 * 1024 * 1024;
    DeviceInfo cpu;
    cpu.id = "cpu";
    cpu.name = "a CPU";
    cpu.backend = "cpu";
    cpu.is_cpu = true;
    cpu.memory = static_cast<std::uint64_t>(24 * gib);
    const MemoryEstimate need = estimate_memory(p);
    REQUIRE(need.host_bytes < 22 * gib);                     // the process alone fits ...
    REQUIRE(need.host_bytes + need.device_bytes > 22 * gib);  // ... but not with the device's buffers
    try {
      check_memory(p, cpu, static_cast<std::uint64_t>(22 * gib));
      FAIL("nside 8192 accepted with 22 GiB available on a CPU device");
    } catch (const SceneError& e) {
      CHECK(e.key() == "observe.velocity_map.nside");
      CHECK(contains(e.message(), "which computes in this memory"));
    }
    // on a GPU with that much memory of its own the same process fits
    DeviceInfo gpu = cpu;
    gpu.id = "cuda:0";
    gpu.backend = "cuda";
    gpu.is_cpu = false;
    gpu.memory = static_cast<std::uint64_t>(80 * gib);
    CHECK_NOTHROW(check_memory(p, gpu, static_cast<std::uint64_t>(22 * gib)));
  }

  TEST_CASE("12. a stop says what is still to be written, and ends") {
    const std::string dir = awtest::temp_dir("stop");
    awtest::StartedCli cli = started_long_run(dir);
    kill(cli.pid, SIGTERM);
    CHECK(cli.wait_for("(up to about ", 20));  // the bytes to write (none said before)
    CAPTURE(cli.output);
    CHECK(cli.finish_within(60) == 128 + SIGTERM);
    CHECK(fs::exists(dir + "/out/summary.json"));
  }
}

// Ctrl-\ once PoCL (and its LLVM) is loaded: needs an OpenCL platform.
TEST_SUITE("reliability-pocl") {
  TEST_CASE("8. Ctrl-\\ (SIGQUIT) quits at once, even with PoCL loaded for the device inventory") {
    bool opencl = false;
    for (const DeviceInfo& d : list_devices()) opencl |= d.backend == "opencl";
    if (!awtest::require(opencl, "reliability-pocl",
                         "no OpenCL platform here (Debian: pocl-opencl-icd): nothing loads LLVM's signal handlers"))
      return;
    const std::string dir = awtest::temp_dir("quit");
    // --device cpu: PoCL is loaded all the same, to list the devices
    awtest::StartedCli cli = started_long_run(dir);
    kill(cli.pid, SIGQUIT);
    const int rc = cli.finish_within(20);  // it ran on, then ended with exit 0, before
    CHECK(rc == 128 + SIGQUIT);
    CHECK_FALSE(fs::exists(dir + "/out"));  // at once: nothing written
  }
}
