// One job over several devices (issue 15, parts 1, 2 and 5): the digests of a
// plain run for any number of workers and assignment of chunks, through
// threads of one process (suite "scale") and through mpirun on the cpu
// backend and PoCL (suite "mpi", skipped where MPI was not built or mpirun is
// missing); a checkpointed run killed with kill -9 and resumed with another
// number of ranks gives the same digests.
#include <doctest/doctest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <thread>

#include "arnoldweb/arnoldweb.hpp"
#include "arnoldweb/cluster.hpp"
#include "run_outputs.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kScene =
    "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 12000\nchunk = 1024\n[integrator]\nstep = 0.02\n"
    "[run]\naverage = 1.0\nduration = 1.0\n[observe]\nvelocity_map = { nside = 8 }\n"
    "energy_error = { every = 0.5 }\nfinal_states = true\ninitial_states = true\n"
    "zoom = { center = [45.0, 0.0], width = 30.0, resolution = 16 }\n[output]\nimages = false\n";

void check_same(const arnoldweb::Result& a, const arnoldweb::Result& b) {
  CHECK(a.completed == b.completed);
  CHECK(a.binned == b.binned);
  CHECK(arnoldweb::digest_map(a) == arnoldweb::digest_map(b));
  CHECK(arnoldweb::digest_records(a, "initial_states") == arnoldweb::digest_records(b, "initial_states"));
  CHECK(arnoldweb::digest_records(a, "final_states") == arnoldweb::digest_records(b, "final_states"));
  CHECK(a.zoom == b.zoom);
  CHECK(a.energy.log_hist == b.energy.log_hist);
  CHECK(a.energy.max == b.energy.max);
  CHECK(a.energy.mean == b.energy.mean);
}

// Keeps every checkpoint saved.
class Keep final : public arnoldweb::CheckpointSink {
 public:
  void save(const std::string& image) override { images.push_back(image); }
  std::vector<std::string> images;
};

std::string mpirun_path() {
  for (const char* p : {"/usr/bin/mpirun", "/usr/local/bin/mpirun"})
    if (::access(p, X_OK) == 0) return p;
  return "";
}

bool require_mpi() {
#ifndef ARNOLDWEB_HAVE_MPI
  return awtest::require(false, "mpi", "this build has no MPI (find_package(MPI) found none)");
#else
  return awtest::require(!mpirun_path().empty(), "mpi", "mpirun is not installed (openmpi-bin)");
#endif
}

awtest::CliOptions mpirun(int ranks) {
  awtest::CliOptions o;
  o.launcher = {mpirun_path(), "--oversubscribe", "--allow-run-as-root", "-n", std::to_string(ranks)};
  o.env = {"OMPI_MCA_rmaps_base_oversubscribe=1", "OMPI_MCA_btl=self,vader,tcp"};
  return o;
}

// kill -9 to a process and all its descendants (mpirun and its ranks), children first.
void kill_tree(int pid) {
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(e.path() / "stat");
    std::string stat;
    std::getline(in, stat);
    const auto close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 2));
    char state = 0;
    int ppid = 0;
    rest >> state >> ppid;
    if (ppid == pid) kill_tree(std::stoi(name));
  }
  ::kill(pid, SIGKILL);
}

// Whether `pid` is gone (or a zombie).
bool gone(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!std::getline(in, stat)) return true;
  const auto close = stat.rfind(')');
  return close != std::string::npos && close + 2 < stat.size() && stat[close + 2] == 'Z';
}

}  // namespace

TEST_SUITE("scale") {
  TEST_CASE("a job over 1, 2 and 3 devices of this process (and a mix with PoCL) gives the plain run's bits") {
    const arnoldweb::Job job = arnoldweb::plan_job(awtest::scene_from(kScene));
    auto plain_dev = arnoldweb::open_backend("cpu");
    const arnoldweb::Result plain = arnoldweb::run(job.main(), *plain_dev);
    std::vector<std::unique_ptr<arnoldweb::Backend>> owned;
    std::vector<std::string> ids = {"cpu", "cpu", "cpu"};
    if (!awtest::first_opencl().empty()) ids.push_back(awtest::first_opencl());
    for (const auto& id : ids) owned.push_back(arnoldweb::open_backend(id));
    for (std::size_t n = 1; n <= owned.size(); ++n) {
      CAPTURE(n);
      std::vector<arnoldweb::Backend*> devices;
      for (std::size_t i = 0; i < n; ++i) devices.push_back(owned[i].get());
      const arnoldweb::JobResult r = arnoldweb::run_job_on_devices(job, devices);
      REQUIRE(r.results.size() == 1);
      CHECK_FALSE(r.interrupted);
      check_same(plain, r.results[0]);
    }
  }

  TEST_CASE("checkpoints of a job over several devices resume with another number of devices, same bits") {
    const arnoldweb::Job job = arnoldweb::plan_job(awtest::scene_from(kScene, {"ensemble.chunk=0"}));
    auto plain_dev = arnoldweb::open_backend("cpu");
    const arnoldweb::Result plain = arnoldweb::run(job.main(), *plain_dev);
    auto a = arnoldweb::open_backend("cpu"), b = arnoldweb::open_backend("cpu"), c = arnoldweb::open_backend("cpu");
    Keep keep;
    arnoldweb::Checkpointing cp;
    cp.sink = &keep;
    cp.every_seconds = 1e-9;  // after every chunk: parks the workers each time
    arnoldweb::RunOptions o;
    o.checkpoint = &cp;
    o.chunk_seconds = 0.01;
    const arnoldweb::JobResult full = arnoldweb::run_job_on_devices(job, {a.get(), b.get()}, o);
    check_same(plain, full.results[0]);
    REQUIRE(keep.images.size() >= 3);
    CHECK_FALSE(cp.saved_incomplete);
    // resume from an early, a middle and the last checkpoint: on 3 devices, on 1, in one process
    for (const std::size_t k : {std::size_t{0}, keep.images.size() / 2, keep.images.size() - 1}) {
      CAPTURE(k);
      const auto info = arnoldweb::read_checkpoint_info(keep.images[k], "ck");
      CHECK(info.completed <= 12000);
      arnoldweb::Checkpointing again;
      Keep more;
      again.sink = &more;
      again.every_seconds = 0;
      again.resume = keep.images[k];
      arnoldweb::RunOptions ro;
      ro.checkpoint = &again;
      check_same(plain, arnoldweb::run_job_on_devices(job, {a.get(), b.get(), c.get()}, ro).results[0]);
      check_same(plain, arnoldweb::run_job_on_devices(job, {c.get()}, ro).results[0]);
      check_same(plain, arnoldweb::run_job(job, *a, ro).results[0]);
    }
  }

  TEST_CASE("a stop request ends every device after its chunk and saves a checkpoint that completes the run") {
    const arnoldweb::Job job = arnoldweb::plan_job(awtest::scene_from(kScene));
    auto plain_dev = arnoldweb::open_backend("cpu");
    const arnoldweb::Result plain = arnoldweb::run(job.main(), *plain_dev);
    auto a = arnoldweb::open_backend("cpu"), b = arnoldweb::open_backend("cpu");
    std::atomic<bool> stop{true};  // at once: the first requests end the part
    Keep keep;
    arnoldweb::Checkpointing cp;
    cp.sink = &keep;
    cp.every_seconds = 0;
    arnoldweb::RunOptions o;
    o.stop = &stop;
    o.checkpoint = &cp;
    const arnoldweb::JobResult stopped = arnoldweb::run_job_on_devices(job, {a.get(), b.get()}, o);
    CHECK(stopped.interrupted);
    REQUIRE(cp.saved_incomplete);
    arnoldweb::Checkpointing again;
    again.sink = &keep;
    again.every_seconds = 0;
    again.resume = keep.images.back();
    arnoldweb::RunOptions ro;
    ro.checkpoint = &again;
    check_same(plain, arnoldweb::run_job_on_devices(job, {b.get(), a.get()}, ro).results[0]);
  }

  TEST_CASE("a device that fails ends the job with an error naming the worker and the device") {
    const arnoldweb::Job job =
        arnoldweb::plan_job(awtest::scene_from(kScene, {"ensemble.trajectories=40000"}));  // 40 chunks
    // a device that throws on its first chunk
    class Failing final : public arnoldweb::Backend {
     public:
      explicit Failing(std::unique_ptr<arnoldweb::Backend> b) : b_(std::move(b)) {}
      const arnoldweb::DeviceInfo& info() const override { return b_->info(); }
      void prepare(const arnoldweb::Plan& p, std::uint64_t m) override { b_->prepare(p, m); }
      void run_chunk(const arnoldweb::ChunkWork&, arnoldweb::ChunkOutput&) override {
        throw arnoldweb::DeviceError(b_->info().id, "", 0, "the device was lost");
      }
      std::vector<std::uint64_t> read_histograms() override { return b_->read_histograms(); }
      std::uint64_t preferred_chunk() const override { return b_->preferred_chunk(); }
      std::string kernel_description() const override { return ""; }

     private:
      std::unique_ptr<arnoldweb::Backend> b_;
    };
    Failing bad(arnoldweb::open_backend("cpu"));
    auto good = arnoldweb::open_backend("cpu");
    CHECK_THROWS_WITH_AS(arnoldweb::run_job_on_devices(job, {&bad, good.get()}), doctest::Contains("worker 0 (device cpu"),
                         arnoldweb::DeviceError);
  }
}

TEST_SUITE("mpi") {
  TEST_CASE("mpirun -n 1, 2, 3 on the cpu backend and on PoCL give the plain run's digests") {
    if (!require_mpi()) return;
    const std::string root = awtest::temp_dir("mpi");
    const std::string scene = root + "/scene.toml";
    std::ofstream(scene) << kScene;
    REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", root + "/plain"}) == 0);
    std::vector<std::string> devices = {"cpu"};
    if (!awtest::first_opencl().empty()) devices.push_back(awtest::first_opencl());
    for (const auto& device : devices) {
      for (int n = 1; n <= 3; ++n) {
        CAPTURE(device);
        CAPTURE(n);
        const std::string out = root + "/mpi-" + std::to_string(n) + "-" + device.substr(0, device.find(':'));
        std::string text;
        const int rc = awtest::run_cli({"run", scene, "--device", device, "--out", out}, &text, mpirun(n));
        CAPTURE(text);
        REQUIRE(rc == 0);
        awtest::check_same_digests(root + "/plain", out);
        // one progress stream (rank 0's totals) and one report
        CHECK(std::count(text.begin(), text.end(), '\n') < 40);
        if (n > 1) CHECK(text.find("ranks        " + std::to_string(n)) != std::string::npos);
      }
    }
    // a list gives each rank its device: cpu and PoCL mixed
    if (devices.size() > 1) {
      const std::string out = root + "/mixed";
      std::string text;
      CHECK(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu," + devices[1], "--out", out}, &text, mpirun(2)) ==
            0);
      CAPTURE(text);
      awtest::check_same_digests(root + "/plain", out);
    }
  }

  TEST_CASE("mpirun -n 2 killed with kill -9, resumed with -n 3 and with one process: the same digests") {
    if (!require_mpi()) return;
    const std::string root = awtest::temp_dir("mpi-kill");
    const std::string scene = root + "/scene.toml";
    std::ofstream(scene) << kScene << "";
    const std::vector<std::string> sets = {"--set", "ensemble.trajectories=150000", "--set", "run.duration=2.0",
                                           "--set", "run.checkpoint_every=0.1"};
    auto args = [&](const std::string& out) {
      std::vector<std::string> a = {"run", scene, "--device", "cpu", "--out", out};
      a.insert(a.end(), sets.begin(), sets.end());
      return a;
    };
    std::vector<std::string> plain_args = args(root + "/plain");
    plain_args.push_back("--quiet");
    // an uninterrupted run under mpirun -n 2, timed: the kills fall inside such a run
    const auto t0 = std::chrono::steady_clock::now();
    REQUIRE(awtest::run_cli(args(root + "/timed"), nullptr, mpirun(2)) == 0);
    const double run_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    REQUIRE(awtest::run_cli(plain_args) == 0);
    std::mt19937 rng(static_cast<unsigned>(::getpid()));
    int resumed = 0;
    for (int attempt = 0; attempt < 2; ++attempt) {
      CAPTURE(attempt);
      const std::string out = root + "/killed-" + std::to_string(attempt);
      awtest::StartedCli cli = awtest::start_cli(args(out), mpirun(2));
      const double at = run_ms * (0.4 + 0.5 * std::uniform_real_distribution<double>(0, 1)(rng));
      std::this_thread::sleep_for(std::chrono::milliseconds(static_cast<long>(at)));
      kill_tree(cli.pid);  // mpirun and every rank, as a lost job
      cli.finish();
      // the ranks' staging directory names rank 0's process: wait until it is gone
      for (const auto& f : arnoldweb::find_checkpoints(out))
        for (int i = 0; i < 100 && !gone(static_cast<int>(f.pid)); ++i)
          std::this_thread::sleep_for(std::chrono::milliseconds(50));
      std::string text;
      if (!fs::exists(out + "/summary.json")) {
        const int rc = attempt == 0 ? awtest::run_cli({"resume", out, "--quiet"}, &text, mpirun(3))
                                    : awtest::run_cli({"resume", out, "--quiet"}, &text);
        CAPTURE(text);
        if (rc == 0) ++resumed;
        else REQUIRE(awtest::run_cli(args(out)) == 0);
      }
      awtest::check_same_digests(root + "/plain", out);
      CHECK(arnoldweb::find_checkpoints(out).empty());
    }
    CHECK(resumed >= 1);
  }
}

TEST_SUITE("mpi-absent") {
  TEST_CASE("a build without MPI started by mpirun refuses to run each rank's own copy of the scene") {
#ifdef ARNOLDWEB_HAVE_MPI
    if (!awtest::require(false, "mpi-absent", "this build has MPI (the case is for builds without it)")) return;
#else
    const std::string root = awtest::temp_dir("no-mpi");
    const std::string scene = root + "/scene.toml";
    std::ofstream(scene) << kScene;
    awtest::CliOptions o;
    o.env = {"OMPI_COMM_WORLD_SIZE=3"};  // what mpirun -n 3 sets
    std::string text;
    CHECK(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", root + "/out"}, &text, o) == 2);
    CAPTURE(text);
    CHECK(text.find("built without MPI") != std::string::npos);
    CHECK(text.find("mpirun needs the MPI build") != std::string::npos);
    CHECK_FALSE(fs::exists(root + "/out"));
    // one process is a plain run
    CHECK(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", root + "/out"}) == 0);
#endif
  }
}
