// Every device of a node in one process (issue 25, item 4): run.device and
// --device take a list of ids ("cpu,opencl:0") or "all"; one process drives
// every device listed, with a thread each, and gives one device's digests; a
// list is never silently cut to one entry; a repeated or malformed id is bad
// input (exit 2), a device this machine lacks a device problem (exit 4), and
// neither leaves an output behind. Ctrl-C, checkpoints and resume work with a
// list as with one device. Suite "scale" needs only the cpu backend; suite
// "devices" needs an OpenCL device (PoCL) beside it and is skipped without one.
#include <doctest/doctest.h>
#include <signal.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "arnoldweb/arnoldweb.hpp"
#include "arnoldweb/cluster.hpp"
#include "run_outputs.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kScene =
    "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 20000\nchunk = 1024\n[integrator]\nstep = 0.02\n"
    "[run]\naverage = 1.0\nduration = 1.0\n[observe]\nvelocity_map = { nside = 8 }\n"
    "energy_error = { every = 0.5 }\nfinal_states = true\ninitial_states = true\n[output]\nimages = false\n";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// What "all" must give on this machine: the CUDA devices, else the OpenCL
// devices that are not CPUs, else the default device.
std::vector<std::string> expected_all() {
  std::vector<std::string> cuda, gpus;
  for (const auto& d : arnoldweb::list_devices()) {
    if (d.backend == "cuda") cuda.push_back(d.id);
    if (d.backend == "opencl" && !d.is_cpu) gpus.push_back(d.id);
  }
  if (!cuda.empty()) return cuda;
  if (!gpus.empty()) return gpus;
  return {arnoldweb::default_device_id()};
}

std::string write_scene(const std::string& root) {
  const std::string scene = root + "/scene.toml";
  std::ofstream(scene) << kScene;
  return scene;
}

}  // namespace

TEST_SUITE("scale") {
  TEST_CASE("run.device: lists and \"all\" are read; a repeated, empty or unknown form is refused naming it") {
    CHECK(awtest::scene_from(kScene, {"run.device=cpu,opencl:0,cuda:1"}).device == "cpu,opencl:0,cuda:1");
    CHECK(awtest::scene_from(kScene, {"run.device=all"}).device == "all");
    CHECK(awtest::scene_from(kScene, {"run.device=cuda:3"}).device == "cuda:3");
    for (const std::string bad : {"cpu,cpu", "cuda:0,cuda:1,cuda:0"}) {
      CAPTURE(bad);
      CHECK_THROWS_WITH_AS(awtest::scene_from(kScene, {"run.device=" + bad}), doctest::Contains("is listed twice"),
                           arnoldweb::SceneError);
    }
    for (const std::string bad : {"cpu,", ",cpu", "cpu,,opencl:0", "cpu,auto", "all,cpu", "gpu", "cuda:x", "cuda:"}) {
      CAPTURE(bad);
      CHECK_THROWS_WITH_AS(awtest::scene_from(kScene, {"run.device=" + bad}), doctest::Contains("run.device: must be"),
                           arnoldweb::SceneError);
    }
  }

  TEST_CASE("device_ids: a list in order, \"all\" as documented, repeats and unknown devices refused") {
    CHECK(arnoldweb::device_ids("cpu") == std::vector<std::string>{"cpu"});
    CHECK(arnoldweb::device_ids("all") == expected_all());
    CHECK_THROWS_WITH_AS(arnoldweb::device_ids("cpu,cpu"), doctest::Contains("lists cpu twice"), arnoldweb::SceneError);
    CHECK_THROWS_WITH_AS(arnoldweb::device_ids("cpu,opencl:99"), doctest::Contains("no such device"),
                         arnoldweb::DeviceError);
    CHECK_THROWS_AS(arnoldweb::device_ids("cpu;opencl:0"), arnoldweb::SceneError);
    // one device is what open_backend opens; a list that names several is not cut to its first
    CHECK(arnoldweb::open_backends("cpu").size() == 1);
    if (arnoldweb::device_ids("all").size() == 1) CHECK(arnoldweb::open_backend("all")->info().id == expected_all()[0]);
  }

  TEST_CASE("describe_devices names every device of a result") {
    arnoldweb::DeviceInfo a, b;
    a.id = "cuda:0";
    a.backend = "cuda";
    a.name = "NVIDIA H200";
    a.compute_units = 132;
    a.memory = 100;
    b = a;
    b.id = "cuda:1";
    const arnoldweb::DeviceInfo two = arnoldweb::describe_devices({a, b});
    CHECK(two.id == "cuda:0,cuda:1");
    CHECK(two.backend == "cuda");
    CHECK(two.name == "2 x NVIDIA H200");
    CHECK(two.compute_units == 264);
    CHECK(two.memory == 200);
    b.id = "opencl:0";
    b.backend = "opencl";
    b.name = "pthread";
    const arnoldweb::DeviceInfo mixed = arnoldweb::describe_devices({a, b});
    CHECK(mixed.backend == "cuda+opencl");
    CHECK(mixed.name == "NVIDIA H200 + pthread");
    CHECK(arnoldweb::describe_devices({a}).id == "cuda:0");
  }

  TEST_CASE("the CLI refuses a repeated device (exit 2) and a missing one (exit 4), writing nothing") {
    const std::string root = awtest::temp_dir("devlist-bad");
    const std::string scene = write_scene(root);
    std::string text;
    CHECK(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu,cpu", "--out", root + "/a"}, &text) == 2);
    CHECK(contains(text, "--device cpu,cpu"));
    CHECK(contains(text, "cpu is listed twice"));
    CHECK(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu,cuda:97", "--out", root + "/b"}, &text) == 4);
    CHECK(contains(text, "cuda:97: no such device"));
    // the devices open while the scene is planned: a scene problem found then is still the one reported
    CHECK(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu,cuda:97", "--set", "integrator.step=-1", "--out",
                           root + "/b"},
                          &text) == 2);
    CHECK(contains(text, "integrator.step"));
    CHECK_FALSE(contains(text, "cuda:97"));
    CHECK(awtest::run_cli({"run", scene, "--quiet", "--set", "run.device=\"cpu,opencl:0,cpu\"", "--out", root + "/c"},
                          &text) == 2);
    CHECK(contains(text, "cpu is listed twice"));
    CHECK_FALSE(fs::exists(root + "/a"));
    CHECK_FALSE(fs::exists(root + "/b"));
    CHECK_FALSE(fs::exists(root + "/c"));
    // a command that runs on one device says so instead of using the list's first entry
    CHECK(awtest::run_cli({"accuracy", scene, "--device", "cpu,opencl:0"}, &text) == 2);
    CHECK(contains(text, "names 2 devices"));
  }
}

TEST_SUITE("devices") {
  TEST_CASE("cpu and PoCL in one process give the cpu backend's digests, from the CLI, the library and run.device") {
    if (!awtest::require(!awtest::first_opencl().empty(), "devices", "no OpenCL device (PoCL) beside the cpu backend")) return;
    const std::string both = "cpu," + awtest::first_opencl();
    const std::string root = awtest::temp_dir("devlist");
    const std::string scene = write_scene(root);
    REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", root + "/one"}) == 0);
    std::string text;
    REQUIRE(awtest::run_cli({"run", scene, "--device", both, "--out", root + "/two"}, &text) == 0);
    CAPTURE(text);
    awtest::check_same_digests(root + "/one", root + "/two");
    CHECK(contains(text, "device       " + both + " ("));
    CHECK(contains(text, "one process, a thread per device"));
    const auto j = awtest::summary_of(root + "/two");
    CHECK(j["device"]["id"] == both);
    CHECK(contains(j["kernel"].get<std::string>(), "2 devices of this process (threads)"));
    // each device's start-up, in the list's order (issue 42, item 4): opened at once, kernels, first launch
    const auto& started = j["startup"]["devices"];
    REQUIRE(started.size() == 2);
    CHECK(started[0]["device"] == "cpu");
    CHECK(started[1]["device"] == awtest::first_opencl());
    CHECK(started[0]["kernel_from"] == "built in");
    CHECK(started[1]["kernel_from"] == "driver");
    for (const auto& d : started) {
      CHECK(d["open_seconds"].get<double>() > 0);
      CHECK(d["kernel_seconds"].get<double>() > 0);
      // 0 for a device that ran no chunk (PoCL still compiling when the cpu backend had done them all)
      CHECK(d["first_launch_seconds"].get<double>() >= 0);
      CHECK(d["first_launch_seconds"].get<double>() < j["wall_seconds"].get<double>());
    }
    CHECK(started[0]["first_launch_seconds"].get<double>() > 0);
    CHECK(j["startup"]["inventory_seconds"].contains("opencl"));  // PoCL was asked for its devices
    CHECK(contains(text, "start-up     devices asked: "));
    CHECK(text.find("; cpu: open ") < text.find("; " + awtest::first_opencl() + ": open "));
    CHECK(awtest::summary_of(root + "/one")["startup"]["devices"].size() == 1);
    // the same through the scene's run.device, and in the other order
    REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--set", "run.device=\"" + awtest::first_opencl() + ",cpu\"", "--out",
                             root + "/scene-key"}) == 0);
    awtest::check_same_digests(root + "/one", root + "/scene-key");
    // both devices computed chunks: a job of many chunks spread over them
    const arnoldweb::Job job = arnoldweb::plan_job(awtest::scene_from(kScene, {"run.device=" + both}));
    const auto backends = arnoldweb::open_backends(job.main().scene.device);
    REQUIRE(backends.size() == 2);
    CHECK(backends[0]->info().id == "cpu");
    CHECK(backends[1]->info().id == awtest::first_opencl());
  }

  TEST_CASE("a list stopped by SIGTERM checkpoints; resumed on the list, on one device: the uninterrupted digests") {
    if (!awtest::require(!awtest::first_opencl().empty(), "devices", "no OpenCL device (PoCL) beside the cpu backend")) return;
    const std::string both = "cpu," + awtest::first_opencl();
    const std::string root = awtest::temp_dir("devlist-term");
    const std::string scene = write_scene(root);
    const std::vector<std::string> longer = {"--set", "ensemble.trajectories=200000", "--set", "run.checkpoint_every=0.1"};
    auto args = [&](const std::string& device, const std::string& out) {
      std::vector<std::string> a = {"run", scene, "--device", device, "--out", out};
      a.insert(a.end(), longer.begin(), longer.end());
      return a;
    };
    auto plain = args("cpu", root + "/plain");
    plain.push_back("--quiet");
    REQUIRE(awtest::run_cli(plain) == 0);
    const std::vector<std::string> resume_on_each = {both, "cpu"};
    for (std::size_t k = 0; k < resume_on_each.size(); ++k) {
      const std::string& resume_on = resume_on_each[k];
      CAPTURE(resume_on);
      const std::string out = root + "/stopped-" + std::to_string(k);
      awtest::StartedCli cli = awtest::start_cli(args(both, out));
      REQUIRE(cli.wait_for("progress:", 120));
      ::kill(cli.pid, SIGTERM);
      CHECK(cli.finish() == 143);
      CAPTURE(cli.output);
      CHECK(contains(cli.output, "checkpoint written to"));
      CHECK_FALSE(fs::exists(out));
      REQUIRE(arnoldweb::find_checkpoints(out).size() == 1);
      std::string text;
      CHECK(awtest::run_cli({"resume", out, "--device", resume_on}, &text) == 0);
      CAPTURE(text);
      CHECK(contains(text, "resuming"));
      awtest::check_same_digests(root + "/plain", out);
      CHECK(arnoldweb::find_checkpoints(out).empty());
    }
  }

  TEST_CASE("Ctrl-C to a list without checkpoints stops after the current chunks and writes what was computed") {
    if (!awtest::require(!awtest::first_opencl().empty(), "devices", "no OpenCL device (PoCL) beside the cpu backend")) return;
    const std::string root = awtest::temp_dir("devlist-int");
    const std::string scene = write_scene(root);
    const std::string out = root + "/out";
    awtest::StartedCli cli = awtest::start_cli({"run", scene, "--device", "cpu," + awtest::first_opencl(), "--out", out, "--set",
                                                "ensemble.trajectories=400000", "--set", "run.checkpoint_every=\"off\""});
    REQUIRE(cli.wait_for("progress:", 120));
    ::kill(cli.pid, SIGINT);
    CHECK(cli.finish() == 130);
    CAPTURE(cli.output);
    CHECK(contains(cli.output, "what was computed was written to"));
    const auto j = awtest::summary_of(out);
    CHECK(j["interrupted"] == true);
    CHECK(j["completed"].get<std::uint64_t>() > 0);
    CHECK(j["completed"].get<std::uint64_t>() < 400000);
    CHECK(j["completed"].get<std::uint64_t>() % 1024 == 0);  // whole chunks only
  }
}
