// Checkpoint and resume through the CLI (issue 15, part 3): a run killed with
// kill -9 at random moments and resumed, or stopped by SIGTERM and resumed on
// another device, gives the digests of an uninterrupted run; a checkpoint is
// kept beside the output directory until a resumed run consumes it; a plain
// run beside it, a damaged checkpoint and one of another scene are refused.
#include <doctest/doctest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <thread>

#include "arnoldweb/arnoldweb.hpp"
#include "run_outputs.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kScene =
    "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 100000\nchunk = 1024\n[integrator]\nstep = 0.02\n"
    "[run]\naverage = 1.0\nduration = 10.0\ncheckpoint_every = 0.1\n[observe]\nvelocity_map = { nside = 8 }\n"
    "energy_error = { every = 0.5 }\nfinal_states = true\n[output]\nimages = false\n";
// (10 T: the run lasts several checkpoint intervals; at 2 T a 2-core AVX-512 machine ran it in 0.2 s
// of process, its work done before the first checkpoint was due, and no attempt could resume)

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::vector<std::string> checkpoints_beside(const std::string& out) {
  std::vector<std::string> found;
  for (const auto& f : arnoldweb::find_checkpoints(out)) found.push_back(f.staging_dir);
  return found;
}

// few trajectories for long: each launch advances every trajectory by one slice, and a
// checkpoint between slices holds their whole state (docs/cluster.md, "Long trajectories")
const std::string kSlicedScene =
    "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 2048\nchunk = 1024\n[integrator]\nstep = 0.02\n"
    "[run]\naverage = 1.0\nduration = 200.0\nslice = 5.0\ncheckpoint_every = 0.1\n"
    "[observe]\nvelocity_map = { nside = 8 }\nenergy_error = { every = 0.5 }\nfinal_states = true\n"
    "[output]\nimages = false\n";

// Kills `run` with SIGKILL at random moments (once after its first checkpoint), resumes, and
// checks the digests of an uninterrupted run.
void kill9_then_resume(const std::string& scene_text, const std::string& tag) {
  const std::string root = awtest::temp_dir(tag);
  const std::string scene = root + "/scene.toml";
  std::ofstream(scene) << scene_text;
  const auto t0 = std::chrono::steady_clock::now();
  REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", root + "/plain"}) == 0);
  const double plain_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::mt19937 rng(static_cast<unsigned>(::getpid()));
  int resumed = 0;
  for (int attempt = 0; attempt < 3; ++attempt) {
    CAPTURE(attempt);
    const std::string out = root + "/killed-" + std::to_string(attempt);
    awtest::StartedCli cli = awtest::start_cli({"run", scene, "--device", "cpu", "--out", out});
    if (attempt == 0) {
      // once its first checkpoint exists (so that at least one attempt resumes, however
      // fast the machine: on 16 cores three random moments all missed the checkpoints)
      const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(120);
      // (or the run finished first: then there is nothing to resume in this attempt)
      while (arnoldweb::find_checkpoints(out).empty() && !fs::exists(out + "/summary.json") &&
             std::chrono::steady_clock::now() < until)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    } else {
      // at a random moment between 30% and 90% of an uninterrupted run's time
      const double at = plain_ms * (0.3 + 0.6 * std::uniform_real_distribution<double>(0, 1)(rng));
      std::this_thread::sleep_for(std::chrono::milliseconds(static_cast<long>(at)));
    }
    ::kill(cli.pid, SIGKILL);
    cli.finish();
    // killed before its first checkpoint, or after it finished: nothing to resume
    std::string text;
    if (!fs::exists(out + "/summary.json")) {
      const int rc = awtest::run_cli({"resume", out, "--quiet"}, &text);
      CAPTURE(text);
      if (rc == 0) ++resumed;
      else REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", out}) == 0);
    }
    awtest::check_same_digests(root + "/plain", out);
    CHECK(checkpoints_beside(out).empty());
    // nothing but the listed outputs is left in the directory (no checkpoint temporaries)
    const auto j = awtest::summary_of(out);
    std::size_t files = 0;
    for (const auto& e : fs::recursive_directory_iterator(out)) files += e.is_regular_file();
    CHECK(files == j["files"].size() + 1);
  }
  CHECK(resumed >= 1);
}

}  // namespace

TEST_SUITE("checkpoint") {
  TEST_CASE("kill -9 at random moments, then resume: the digests of an uninterrupted run") {
    kill9_then_resume(kScene, "kill9");
  }

  TEST_CASE("a sliced run (run.slice) killed with kill -9 at random moments resumes to the uninterrupted digests") {
    kill9_then_resume(kSlicedScene, "kill9-sliced");
  }

  TEST_CASE("SIGTERM writes a checkpoint; resume on another device gives the same digests; refusals") {
    const std::string root = awtest::temp_dir("term");
    const std::string scene = root + "/scene.toml";
    std::ofstream(scene) << kScene;
    const std::string out = root + "/out";
    REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", root + "/plain"}) == 0);
    awtest::StartedCli cli = awtest::start_cli({"run", scene, "--device", "cpu", "--out", out});
    REQUIRE(cli.wait_for("progress:", 60));
    ::kill(cli.pid, SIGTERM);
    CHECK(cli.finish() == 143);
    CAPTURE(cli.output);
    CHECK(contains(cli.output, "checkpoint written to"));
    CHECK_FALSE(fs::exists(out));
    const auto found = checkpoints_beside(out);
    REQUIRE(found.size() == 1);

    // a later plain run does not start beside it, and staging clean-up keeps it
    std::string text;
    CHECK(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", out}, &text) == 3);
    CHECK(contains(text, "a checkpoint of an interrupted run is waiting in"));
    REQUIRE(checkpoints_beside(out).size() == 1);
    // another scene's values are refused, and the checkpoint is kept
    CHECK(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", out, "--resume", "--set",
                           "ensemble.seed=9"},
                          &text) == 2);
    CHECK(contains(text, "another scene"));
    REQUIRE(checkpoints_beside(out).size() == 1);
    // a damaged checkpoint is refused and left as it is
    const std::string file = arnoldweb::find_checkpoints(out).front().file;
    std::string bytes;
    {
      std::ifstream in(file, std::ios::binary);
      bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::string bad = bytes;
    bad[bad.size() / 3] ^= 0x40;
    std::ofstream(file, std::ios::binary) << bad;
    CHECK(awtest::run_cli({"resume", out, "--quiet"}, &text) == 2);
    CHECK(contains(text, "damaged"));
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;

    // what a process killed while writing left half-written in the checkpoint's directory
    // (an output or a checkpoint temporary) does not reach the results
    const std::string staging = arnoldweb::find_checkpoints(out).front().staging_dir;
    std::ofstream(staging + "/.map.h5.tmp-999999-0") << "half an HDF5 file";
    std::ofstream(staging + "/.checkpoint.awck.tmp-999999-3") << "half a checkpoint";

    // resumed on another device where there is one (PoCL), else on the cpu backend
    std::string device = "cpu";
    for (const auto& d : arnoldweb::list_devices())
      if (d.backend == "opencl") device = d.id;
    CAPTURE(device);
    CHECK(awtest::run_cli({"resume", out, "--quiet", "--device", device}, &text) == 0);
    CAPTURE(text);
    awtest::check_same_digests(root + "/plain", out);
    CHECK(checkpoints_beside(out).empty());
    CHECK_FALSE(fs::exists(out + "/.map.h5.tmp-999999-0"));
    CHECK_FALSE(fs::exists(out + "/.checkpoint.awck.tmp-999999-3"));
    std::size_t files = 0;
    for (const auto& e : fs::recursive_directory_iterator(out)) files += e.is_regular_file();
    CHECK(files == awtest::summary_of(out)["files"].size() + 1);
    // the directory is an ordinary arnoldweb output: --force may replace it
    CHECK(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", out, "--force", "--set",
                           "run.checkpoint_every=\"off\""}) == 0);
  }
}
