// arnoldweb run SCENE: run a scene (and its panels) and write the outputs.
// SIGINT, SIGTERM and SIGHUP stop after the current chunk; what was computed
// is written (as a checkpoint when the run checkpoints, else as the outputs),
// and the exit code is 128 + the signal (130, 143, 129).
// arnoldweb resume OUTDIR (and run --resume) continue from a checkpoint.
#include <sys/stat.h>

#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "arnoldweb/arnoldweb.hpp"
#include "command.hpp"
#include "device_opening.hpp"
#include "plan_report.hpp"
#include "progress.hpp"
#include "ranks.hpp"
#include "stop_signals.hpp"

namespace arnoldweb::cli {
namespace {

struct RunFlags {
  SceneArgs scene;
  bool force = false;
  bool quiet = false;
  bool resume = false;
};

// A progress bar per part; panels are announced.
class PartProgress final : public JobObserver {
 public:
  explicit PartProgress(bool quiet) : quiet_(quiet) {}
  Progress* begin_part(const Job& job, std::size_t k) override {
    const JobPart& part = job.parts[k];
    if (!quiet_ && k > 0) std::cout << "\npanel        " << part.name << ": " << part.title << std::endl;
    bar_ = std::make_unique<ConsoleProgress>(static_cast<double>(part.plan.steps_per_trajectory), quiet_);
    return bar_.get();
  }

 private:
  bool quiet_;
  std::unique_ptr<ConsoleProgress> bar_;
};

double last_write(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 ? static_cast<double>(st.st_mtim.tv_sec) + 1e-9 * st.st_mtim.tv_nsec : 0;
}

// Where the start-up went (summary.json's "startup"): the inventory, then each device.
std::string startup_line(const Startup& s) {
  std::string line;
  for (const auto& [backend, seconds] : s.inventory_seconds)
    line += (line.empty() ? "devices asked: " : ", ") + backend + " " + short_number(seconds) + " s";
  for (const DeviceStartup& d : s.devices)
    line += (line.empty() ? "" : "; ") + d.id + ": open " + short_number(d.open_seconds) + " s, kernel " +
            short_number(d.kernel_seconds) + " s (" + d.kernel_from + "), buffers " + short_number(d.buffers_seconds) +
            " s, " + (d.first_launch_seconds > 0 ? "first launch " + short_number(d.first_launch_seconds) + " s" : "no launch");
  return line;
}

void report(const JobPart& part, const Result& result) {
  std::cout << (part.name.empty() ? "done         " : "done panel   ") << result.completed << " trajectories in "
            << short_number(result.wall_seconds) << " s (" << short_number(result.rate()) << " trajectory-steps/s)\n"
            << "binned       " << result.binned << ", flagged " << result.flagged() << " (non-finite "
            << result.flagged_nonfinite << ", energy " << result.flagged_energy << ", initial "
            << result.flagged_initial << ")" << (result.left_region ? ", left the region " + std::to_string(result.left_region) : "")
            << "\n";
  if (result.energy.tracked)
    std::cout << "energy error max " << short_number(result.energy.max) << ", mean " << short_number(result.energy.mean)
              << "\n";
  std::cout << "map digest   " << digest_map(result) << "\n";
  if (!result.startup.devices.empty()) std::cout << "start-up     " << startup_line(result.startup) << "\n";
}

}  // namespace

// The checkpoint beside `out_dir` that a resumed run continues (the newest
// of those whose process is gone); CheckpointError if there is none.
FoundCheckpoint checkpoint_to_resume(const std::string& out_dir) {
  const auto found = find_checkpoints(out_dir);
  const FoundCheckpoint* pick = nullptr;
  for (const auto& f : found) {
    if (f.running) continue;
    if (!pick || last_write(f.file) > last_write(pick->file)) pick = &f;
  }
  if (pick) return *pick;
  if (!found.empty())
    throw CheckpointError(found.front().staging_dir, "its run (process " + std::to_string(found.front().pid) +
                                                         ") is still going; there is nothing to resume yet");
  throw CheckpointError(out_dir, "there is no checkpoint to resume (none of " + out_dir +
                                     ".partial-PID holds one); a run writes one when it is stopped or every "
                                     "run.checkpoint_every");
}

namespace {

// A plain run into a place where an interrupted run left a checkpoint would
// start afresh beside it: refused, so that nobody loses the computed work.
void refuse_beside_checkpoint(const std::string& out_dir) {
  for (const auto& f : find_checkpoints(out_dir))
    if (!f.running)
      throw OutputError(out_dir, "a checkpoint of an interrupted run is waiting in " + f.staging_dir +
                                     "; continue it with `arnoldweb resume " + out_dir +
                                     "` (or run --resume), or remove " + f.staging_dir + " to start afresh");
}

}  // namespace

int execute_job(const PreparedJob& prepared, bool quiet, const std::optional<FoundCheckpoint>& resume,
                const std::optional<std::string>& device_option, DeviceOpening* opening) {
  const Job& job = prepared.job;
  if (!resume) refuse_beside_checkpoint(prepared.out_dir);
  // one process drives every device that run.device (or --device) names; an MPI rank its own
  const auto backends =
      opening ? opening->take() : open_backends(rank_device(device_option, job.main().scene.device));
  std::vector<Backend*> devices;
  std::vector<DeviceInfo> infos;
  for (const auto& b : backends) {
    devices.push_back(b.get());
    infos.push_back(b->info());
  }
  Backend& backend = *devices.front();  // under MPI, this rank's only device
  if (!quiet) {
    const DeviceInfo all = describe_devices(infos);
    print_plan(std::cout, job.main(),
               all.id + " (" + all.name + (devices.size() > 1 ? "; one process, a thread per device" : "") + ")");
    std::cout.flush();
  }
  CheckpointStore store(prepared.out_dir, prepared.output);
  Checkpointing checkpoints;
  checkpoints.sink = &store;
  checkpoints.every_seconds = job.main().scene.checkpoint_every;
  if (resume) {
    checkpoints.resume = store.adopt(*resume);
    checkpoints.resume_path = store.file();
    if (!quiet) std::cout << "resuming    from " << store.file() << "\n";
  }
  if (cluster() && !quiet)
    std::cout << "ranks        " << cluster()->size() << " (MPI; rank 0 coordinates, drives " << backend.info().id
              << " and writes the outputs)\n";
  share_scene(job.main().scene);  // the other ranks plan it and serve
  StopSignals signals(prepared.output.expected_bytes);  // held until the outputs are written
  RunOptions options;
  options.stop = &signals.flag();
  const bool checkpointing = checkpoints.every_seconds != 0 || resume;
  if (checkpointing) options.checkpoint = &checkpoints;
  PartProgress progress(quiet);
  JobResult result;
  try {
    result = cluster() ? cluster()->run_job(job, backend, options, &progress)
                       : run_job_on(job, devices, options, &progress);
  } catch (const Error&) {
    if (!store.file().empty())
      std::cerr << "arnoldweb: the last checkpoint is in " << store.file() << "; `arnoldweb resume "
                << prepared.out_dir << "` continues from it\n";
    throw;
  }
  if (result.interrupted && checkpoints.saved_incomplete) {
    const Result& last = result.results.back();
    std::cerr << "arnoldweb: stopped by " << signals.name() << " after " << last.completed << " of "
              << last.trajectories << " trajectories"
              << (job.parts.size() > 1 ? " of part " + std::to_string(result.results.size()) + " of " +
                                             std::to_string(job.parts.size())
                                       : std::string())
              << "; checkpoint written to " << store.file() << "; continue with `arnoldweb resume "
              << prepared.out_dir << "`\n";
    return signals.exit_code();
  }
  OutputOptions output = prepared.output;
  output.staging = store.staging();
  const auto files = write_job(job, result, output);
  // an analysis's warnings (summary.json lists them too): a diffusion fit that is not diffusive
  for (const Result& r : result.results)
    for (const auto& [name, text] : r.analyses)
      for (const auto& w : nlohmann::json::parse(text).value("warnings", nlohmann::json::array()))
        std::cerr << "arnoldweb: warning: " << w.get<std::string>() << "\n";
  if (!quiet) {
    for (std::size_t k = 0; k < result.results.size(); ++k) report(job.parts[k], result.results[k]);
    for (const auto& file : files) std::cout << "wrote        " << file << "\n";
  }
  if (signals.signal()) {
    static const Result none;  // (a Result{} here made the ternary copy the whole result: GBs of maps)
    const Result& last = result.results.empty() ? none : result.results.back();
    std::cerr << "arnoldweb: stopped by " << signals.name() << " after " << last.completed << " of "
              << last.trajectories << " trajectories"
              << (result.results.size() < job.parts.size() ? " (panels not run: " +
                                                                 std::to_string(job.parts.size() - result.results.size()) + ")"
                                                           : "")
              << "; what was computed was written to " << prepared.out_dir << "\n";
    return signals.exit_code();
  }
  return 0;
}

namespace {

int run_scene(const RunFlags& f) {
  refuse_mpirun_without_mpi();
  if (cluster() && cluster()->rank() != 0) return serve_rank(f.scene.device);
  // everything is checked before any work: scene, panels, output place
  SceneArgs args = f.scene;
  if (auto pick = explicit_rank_device(args.device)) args.device = *pick;
  const Scene scene = load_scene_args(args);
  DeviceOpening opening(rank_device(f.scene.device, scene.device));  // while the scene is planned
  const PreparedJob prepared = prepare_scene_job(scene, args.scene, f.force);
  std::optional<FoundCheckpoint> resume;
  if (f.resume) resume = checkpoint_to_resume(prepared.out_dir);
  return execute_job(prepared, f.quiet, resume, f.scene.device, &opening);
}

}  // namespace

void add_run_command(CLI::App& app, Action& action) {
  auto flags = std::make_shared<RunFlags>();
  auto* c = app.add_subcommand("run", "Run a scene and write its outputs (summary.json, map.h5, pictures)");
  add_scene_options(c, flags->scene);
  c->add_flag("--force,-f", flags->force,
              "Replace an existing output directory, if a run of arnoldweb wrote it and nothing else is inside");
  c->add_flag("--quiet,-q", flags->quiet, "Print nothing but errors");
  c->add_flag("--resume", flags->resume,
              "Continue from the checkpoint an interrupted run of this scene left beside its output directory");
  c->callback([&action, flags] { action = [flags] { return run_scene(*flags); }; });
}

}  // namespace arnoldweb::cli
