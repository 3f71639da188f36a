// The arnoldweb command as a user meets it: every bad input gets a clear
// message naming the problem, a non-zero exit code and no output directory.
// Exit codes: 2 bad input, 3 output problem, 4 device problem.
#include <doctest/doctest.h>

#include <hdf5.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "backends/backends.hpp"
#include "run_outputs.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

struct Case {
  const char* name;
  std::string scene;  // TOML written to scene.toml ("" = no file)
  std::string args;   // after "run <scene>"
  int code;
  std::vector<std::string> says;
};

// A quick valid scene (the bad ones change one thing).
const std::string kGood =
    "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 200\n[integrator]\nstep = 0.02\n"
    "[run]\naverage = 1.0\nduration = 1.0\n[observe]\nvelocity_map = { nside = 8 }\n"
    "energy_error = { every = 0.5 }\n";

std::string with(const std::string& section, const std::string& line) {
  std::string s = kGood;
  const auto at = s.find("[" + section + "]\n");
  if (at == std::string::npos) return s + "[" + section + "]\n" + line + "\n";
  const auto end = at + section.size() + 3;
  return s.substr(0, end) + line + "\n" + s.substr(end);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_SUITE("cli") {
  TEST_CASE("bad input: a clear message, a non-zero exit and no output") {
    const std::vector<Case> cases = {
        {"missing scene", "", "", 2, {"cannot read the scene file", "No such file"}},
        {"TOML syntax error", "[model]\nenergy = = 3\n", "", 2, {"scene.toml:2:", "TOML syntax error"}},
        {"unknown key", with("model", "energie = 3.0"), "", 2, {"model.energie", "unknown key", "did you mean 'model.energy'"}},
        {"wrong type", with("ensemble", "seed = \"x\""), "", 2, {"ensemble.seed", "must be an integer"}},
        {"no trajectories", "", "--set ensemble.trajectories=0", 2, {"ensemble.trajectories", "from 1 to 1e13"}},
        {"absurdly many trajectories", "", "--set ensemble.trajectories=100000000000000", 2, {"from 1 to 1e13"}},
        {"no accessible phase space", "", "--set model.energy=-2.5", 2, {"model.energy", "no accessible phase space", "choose E > -2"}},
        {"most of the torus forbidden", "", "--set model.energy=-1.97", 2, {"model.energy", "accessible", "choose E >="}},
        {"step <= 0", "", "--set integrator.step=0", 2, {"integrator.step", "greater than 0"}},
        {"step not finite", "", "--set integrator.step=nan", 2, {"integrator.step", "greater than 0"}},
        {"average not a multiple of the step", "", "--set run.average=1.01 --set run.duration=1.01", 2,
         {"run.average", "not a positive multiple of integrator.step"}},
        {"duration not a multiple of the average", "", "--set run.duration=1.5", 2, {"run.duration", "multiple of run.average"}},
        {"nside not a power of two", "", "--set observe.velocity_map.nside=100", 2, {"nside", "power of two"}},
        {"unknown method", "", "--set integrator.method=rk4", 2, {"integrator.method", "yoshida6a"}},
        {"unknown device", "", "--device opencl:99", 4, {"opencl:99", "no such device", "cpu"}},
        {"malformed device", "", "--device gpu", 2, {"run.device", "\"cpu\""}},
        {"unsafe step", "", "--set model.energy=400 --set integrator.step=0.01", 2, {"unsafe", "0.004"}},
    };
    for (const Case& c : cases) {
      const std::string name = c.name;
      CAPTURE(name);
      const std::string dir = awtest::temp_dir("cli");
      const std::string scene = dir + "/scene.toml";
      const std::string text = name == "missing scene" ? "" : c.scene.empty() ? kGood : c.scene;
      if (!text.empty()) std::ofstream(scene) << text;
      std::string out;
      const std::string device = contains(c.args, "--device") ? "" : " --device cpu";
      const int rc = awtest::run_cli("run " + scene + " --quiet" + device + " --out " + dir + "/out " + c.args, &out);
      CAPTURE(out);
      CHECK(rc == c.code);
      for (const auto& s : c.says) CHECK(contains(out, s));
      CHECK_FALSE(fs::exists(dir + "/out"));
    }
  }

  TEST_CASE("an existing output directory is refused (exit 3) and left untouched") {
    const std::string dir = awtest::temp_dir("cli");
    std::ofstream(dir + "/scene.toml") << kGood;
    fs::create_directories(dir + "/out");
    std::ofstream(dir + "/out/mine.txt") << "mine";
    std::string out;
    CHECK(awtest::run_cli("run " + dir + "/scene.toml --quiet --device cpu --out " + dir + "/out", &out) == 3);
    CHECK(contains(out, "exists; use --force"));
    CHECK(fs::exists(dir + "/out/mine.txt"));
    // --force replaces only what arnoldweb wrote: this directory is the user's
    CHECK(awtest::run_cli("run " + dir + "/scene.toml --quiet --device cpu --force --out " + dir + "/out", &out) == 2);
    CHECK(contains(out, "refusing to replace it"));
    CHECK(fs::exists(dir + "/out/mine.txt"));
    CHECK_FALSE(fs::exists(dir + "/out/summary.json"));
  }

  TEST_CASE("double precision on a device without fp64 is refused with a way out") {
    const arnoldweb::Plan p = arnoldweb::make_plan(awtest::scene_from("", {}, "<fp64>"));
    arnoldweb::DeviceInfo d;
    d.id = "opencl:7";
    d.name = "Some GPU";
    d.fp64 = false;
    CHECK_THROWS_WITH_AS(arnoldweb::detail::require_fp64(p, d), doctest::Contains("integrator.precision = \"float\""),
                         arnoldweb::DeviceError);
    d.fp64 = true;
    CHECK_NOTHROW(arnoldweb::detail::require_fp64(p, d));
    d.fp64 = false;
    const arnoldweb::Plan pf =
        arnoldweb::make_plan(awtest::scene_from("[integrator]\nprecision = \"float\"\n", {}, "<fp64>"));
    CHECK_NOTHROW(arnoldweb::detail::require_fp64(pf, d));
  }

  TEST_CASE("issue 37: --device is read as run.device is, and its errors name --device with the value escaped") {
    const std::string dir = awtest::temp_dir("cli-device");
    const std::string scene = dir + "/scene.toml";
    std::ofstream(scene) << kGood;
    std::string out;
    // the value as it is: blanks around the id, or TOML that reads as cpu ('"cpu" #' ran on cpu), name no
    // device; check and run agree
    for (const char* device : {" cpu", "\"cpu\" #", "\"cpu\"", "'cpu'"}) {
      CAPTURE(device);
      for (const char* command : {"check", "run"}) {
        CHECK(awtest::run_cli({command, scene, "--device", device, "--out", dir + "/blank"}, &out) == 2);
        CAPTURE(out);
        CHECK(contains(out, "error: --device " + arnoldweb::printable(device) + ": run.device: must be "));
        CHECK_FALSE(fs::exists(dir + "/blank"));
      }
    }
    CHECK(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", dir + "/plain"}, &out) == 0);
    CHECK(fs::exists(dir + "/plain/summary.json"));
    // an index with a leading zero names no device: refused as a form, like the scene's run.device
    for (const char* command : {"check", "run"}) {
      CAPTURE(command);
      CHECK(awtest::run_cli({command, scene, "--device", "opencl:00", "--out", dir + "/zero"}, &out) == 2);
      CHECK(contains(out, "error: --device opencl:00: run.device: must be "));
      CHECK(contains(out, "got \"opencl:00\""));
      CHECK_FALSE(contains(out, "<scene>"));
      CHECK_FALSE(fs::exists(dir + "/zero"));
    }
    // a control character is echoed as an escape, never raw
    CHECK(awtest::run_cli({"run", scene, "--device", "cpu\nx\x1b[2J", "--out", dir + "/nl"}, &out) == 2);
    CHECK(contains(out, "error: --device cpu\\nx\\u001b[2J: run.device: must be "));
    CHECK(out.find('\x1b') == std::string::npos);
    CHECK(std::count(out.begin(), out.end(), '\n') == 1);
    CHECK(awtest::run_cli({"check", scene, "--out", dir + "/a\x1b[2Jb"}, &out) == 0);
    CHECK(contains(out, "a\\u001b[2Jb"));
    CHECK(out.find('\x1b') == std::string::npos);
  }

  TEST_CASE("issue 37: --out is a directory's name as it is, never read as TOML") {
    const std::string dir = awtest::temp_dir("cli-out-names");
    std::ofstream(dir + "/scene.toml")
        << kGood << "[[panel]]\nname = \"a\"\ntitle = \"A\"\nset = [\"model.energy=16\"]\n";
    awtest::CliOptions here;
    here.cwd = dir;
    std::string out;
    // each would be read as TOML (a string and a comment, a quote, a table, an escape) or lose its
    // blanks: '"q" #' wrote to q; the panels' directories are built from it too
    for (const std::string name : {"\"q\" #", "'q' # x", "a\"b", " lead and trail ", "two\nlines", "back\\slash\\n",
                                   "\"\"\"triple", "[t]\nk = 1", "x = 1", "\u00e9t\u00e9 \U0001f310 # \"", "tab\there"}) {
      CAPTURE(arnoldweb::printable(name));
      CHECK(awtest::run_cli({"check", "scene.toml", "--out", name}, &out, here) == 0);
      CHECK(contains(out, arnoldweb::printable(name)));
      REQUIRE(awtest::run_cli({"run", "scene.toml", "--quiet", "--device", "cpu", "--out", name}, &out, here) == 0);
      CAPTURE(out);
      CHECK(fs::exists(dir + "/" + name + "/summary.json"));
      CHECK(fs::exists(dir + "/" + name + "/panel-a/summary.json"));
      CHECK(awtest::summary_of(dir + "/" + name)["scene"]["output"]["dir"] == name);
      CHECK(awtest::summary_of(dir + "/" + name + "/panel-a")["scene"]["output"]["dir"] == name + "/panel-a");
      fs::remove_all(dir + "/" + name);
    }
    for (const char* other : {"q", "'q'", "a", "lead and trail", "two", "t", "x"}) CHECK_FALSE(fs::exists(dir + "/" + other));
    // a name that is not UTF-8 cannot be recorded in the scene (TOML): refused, nothing written
    CHECK(awtest::run_cli({"run", "scene.toml", "--quiet", "--out", "odd-\xff-name"}, &out, here) == 2);
    CHECK(contains(out, "error: --out odd-\\xff-name: output.dir: is not UTF-8 text"));
    CHECK_FALSE(fs::exists(dir + "/odd-\xff-name"));
  }

  TEST_CASE("issue 37: observe.diffusion: directions refused when checked; actions sampled finer than the energy") {
    const std::string dir = awtest::temp_dir("cli-diffusion");
    const std::string scene = dir + "/scene.toml";
    std::ofstream(scene) << "[model]\nkind = \"fgl\"\nepsilon = 0.01\nenergy = 0.5\n"
                            "[ensemble]\ninitial = \"grid\"\n"
                            "grid = { kind = \"plane\", resolution = [4, 4], range1 = [0.29, 0.31], range2 = [0.29, 0.31], axes = [0, 1] }\n"
                            "[integrator]\nmethod = \"saba3\"\nstep = 0.02\n[run]\naverage = 4.0\nduration = 4.0\n"
                            "[observe]\nvelocity_map = false\nenergy_error = { every = 1.0 }\n[output]\nimages = false\n";
    const std::string on = "observe.diffusion={ every = 0.5, along = [1, 1, 0], across = [1, -1, 0], fit_from = 1 }";
    std::string out;
    // [1e200, 1e200, 0] ran with zero moments, [1e-170, 1e-170, 0] ran and wrote no diffusion.csv: both refused
    for (const char* along : {"[1e200, 1e200, 0]", "[1e-170, 1e-170, 0]"}) {
      CAPTURE(along);
      for (const char* command : {"check", "run"}) {
        CHECK(awtest::run_cli({command, scene, "--device", "cpu", "--set", on, "--set",
                               std::string("observe.diffusion.along=") + along, "--out", dir + "/bad"},
                              &out) == 2);
        CHECK(contains(out, "observe.diffusion.along: must be an array [a, b, c] of floats, largest absolute component "
                            "from 1e-150 to 1e150"));
        CHECK_FALSE(fs::exists(dir + "/bad"));
      }
    }
    // every 0.5 T under an energy interval of 1 T (the documented rule: every interval a multiple of
    // the shortest): the actions at every 0.5 T, the energy sampled as without them
    REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--set", on, "--out", dir + "/fine"}, &out) == 0);
    REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", dir + "/plain"}, &out) == 0);
    const auto fine = awtest::summary_of(dir + "/fine"), plain = awtest::summary_of(dir + "/plain");
    CHECK(fine["energy_error"]["max"] == plain["energy_error"]["max"]);
    CHECK(fine["energy_error"]["mean"] == plain["energy_error"]["mean"]);
    const auto t = fine["analyses"]["diffusion"]["moments"]["t"];
    REQUIRE(t.size() == 9);
    for (std::size_t k = 0; k < t.size(); ++k) CHECK(t[k].get<double>() == 0.5 * static_cast<double>(k));
    // diffusion.h5 names its interval `every` (docs/outputs.md)
    const hid_t f = H5Fopen((dir + "/fine/diffusion.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(f >= 0);
    CHECK(H5Aexists(f, "diffusion_every") == 0);
    REQUIRE(H5Aexists(f, "every") > 0);
    const hid_t a = H5Aopen(f, "every", H5P_DEFAULT);
    double every = 0;
    H5Aread(a, H5T_NATIVE_DOUBLE, &every);
    H5Aclose(a);
    H5Fclose(f);
    CHECK(every == 0.5);
  }

  TEST_CASE("check prints the plan; every command has --help") {
    const std::string dir = awtest::temp_dir("cli");
    std::ofstream(dir + "/scene.toml") << kGood;
    std::string out;
    CHECK(awtest::run_cli("check " + dir + "/scene.toml", &out) == 0);
    CHECK(contains(out, "effects      velocity_map, energy_error"));
    CHECK(contains(out, "work"));
    for (const char* cmd : {"", "devices ", "methods ", "check ", "run ", "keys ", "compare "}) {
      CAPTURE(cmd);
      CHECK(awtest::run_cli(std::string(cmd) + "--help", &out) == 0);
      CHECK(contains(out, "Usage"));
    }
    CHECK(awtest::run_cli("frobnicate", &out) == 2);
  }
}

// Cases that need something a machine may lack, each in a suite (and ctest
// entry) of its own: without it the entry is reported as skipped with the
// reason (exit 77), and nothing else is skipped with it.

TEST_SUITE("cli-memory") {
  TEST_CASE("nside 8192 on a device without room for the map is refused before computing, naming the key") {
    // The map takes 12 nside^2 x (4 + 8) bytes: 9216 MiB at nside 8192; the memory
    // check refuses a map larger than half the device's memory (and one beyond the
    // largest allocation: tests/backends/test_device_memory.cpp tests the check
    // itself with a fake device). Here the run goes to a device where the first
    // rule alone must refuse it.
    const double map_bytes = 12.0 * 8192 * 8192 * 12;
    std::string device;
    for (const auto& d : awtest::devices_under_test())
      if (device.empty() && d.memory > 0 && map_bytes > 0.5 * static_cast<double>(d.memory)) device = d.id;
    if (!awtest::require(!device.empty(), "cli-memory",
                         "every device here has more than 18 GiB of memory: an nside 8192 map fits, so the CLI has "
                         "nothing to refuse (suite backends tests the refusal with a fake small device)"))
      return;
    CAPTURE(device);
    const std::string dir = awtest::temp_dir("cli");
    std::ofstream(dir + "/scene.toml") << kGood;
    std::string out;
    const int rc = awtest::run_cli("run " + dir + "/scene.toml --quiet --device " + device + " --out " + dir +
                                       "/out --set observe.velocity_map.nside=8192 --set ensemble.trajectories=1",
                                   &out);
    CAPTURE(out);
    CHECK(rc == 2);
    CHECK(contains(out, "observe.velocity_map.nside"));
    CHECK(contains(out, "9216 MiB"));
    CHECK(contains(out, device));
    CHECK(contains(out, "choose a smaller value"));
    CHECK_FALSE(fs::exists(dir + "/out"));
  }
}

TEST_SUITE("cli-no-opencl") {
  TEST_CASE("without any OpenCL platform: devices says how to install PoCL; opencl runs fail cleanly") {
    // An empty OCL_ICD_VENDORS directory hides every OpenCL platform from the
    // ICD loader (ocl-icd, Debian's), as on a machine without OpenCL.
    const std::string empty = awtest::temp_dir("icd");
    std::string out;
    CHECK(awtest::run_cli("devices", &out) == 0);
    awtest::CliOptions no_icd;
    no_icd.env = {"OCL_ICD_VENDORS=" + empty};
    std::string text;
    CHECK(awtest::run_cli({"devices"}, &text, no_icd) == 0);
    CAPTURE(text);
    // some ICD loaders (Ubuntu 24.04's) still find platforms registered elsewhere
    if (!awtest::require(!contains(text, "opencl:0"), "cli-no-opencl",
                         "this system's OpenCL ICD loader ignores OCL_ICD_VENDORS, so a machine without OpenCL "
                         "cannot be simulated here (the case runs on Debian's ocl-icd, e.g. in CI)"))
      return;
    CHECK(contains(text, "no OpenCL platform found"));
    CHECK(contains(text, "pocl-opencl-icd"));
    CHECK(contains(text, "cpu"));
    std::ofstream(empty + "/scene.toml") << kGood;
    std::string run_text;
    CHECK(awtest::run_cli({"run", empty + "/scene.toml", "--quiet", "--device", "opencl:0", "--out", empty + "/out"},
                          &run_text, no_icd) == 4);
    CHECK(contains(run_text, "pocl-opencl-icd"));
    CHECK_FALSE(fs::exists(empty + "/out"));
  }
}

TEST_SUITE("cli-no-cuda") {
  TEST_CASE("asking for a CUDA device where there is none fails cleanly (exit 4, the reason, no output)") {
    bool have_cuda = false;
    for (const auto& d : arnoldweb::list_devices()) have_cuda |= d.backend == "cuda";
    if (!awtest::require(!have_cuda, "cli-no-cuda",
                         "this machine has a CUDA device (cuda:0), so the failure for a missing one cannot be "
                         "reached here"))
      return;
    const std::string dir = awtest::temp_dir("cli");
    std::ofstream(dir + "/scene.toml") << kGood;
    std::string out;
    CHECK(awtest::run_cli("run " + dir + "/scene.toml --quiet --device cuda:0 --out " + dir + "/out", &out) == 4);
    CAPTURE(out);
    CHECK(contains(out, "cuda:0"));
    CHECK(contains(out, "no such device"));
    CHECK((contains(out, "cuda: no CUDA") || contains(out, "no CUDA backend") || contains(out, "driver too old")));
    CHECK_FALSE(fs::exists(dir + "/out"));
  }
}

TEST_SUITE("cli-opencl") {
  TEST_CASE("an OpenCL build that fails reports the full build log and the options") {
    bool have_opencl = false;
    for (const auto& d : arnoldweb::list_devices()) have_opencl |= d.backend == "opencl";
    if (!awtest::require(have_opencl, "cli-opencl", "no OpenCL device here (install pocl-opencl-icd)")) return;
    const std::string dir = awtest::temp_dir("cli");
    std::ofstream(dir + "/scene.toml") << kGood;
    awtest::CliOptions bad_option;
    bad_option.env = {"ARNOLDWEB_OPENCL_OPTIONS=-DAW_STAGES=oops"};
    std::string text;
    CHECK(awtest::run_cli({"run", dir + "/scene.toml", "--quiet", "--device", "opencl:0", "--out", dir + "/out"}, &text,
                          bad_option) == 4);
    CAPTURE(text);
    CHECK(contains(text, "kernel build failed"));
    CHECK(contains(text, "options: -DAW_FEATURES="));
    CHECK(contains(text, "build log:"));
    CHECK(contains(text, "oops"));
    CHECK_FALSE(fs::exists(dir + "/out"));
  }
}
