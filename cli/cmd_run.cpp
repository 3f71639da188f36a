// arnoldweb run SCENE: run a scene (and its panels) and write the outputs.
// SIGINT, SIGTERM and SIGHUP stop after the current chunk; what was computed
// is written, and the exit code is 128 + the signal (130, 143, 129).
#include <iostream>

#include "arnoldweb/arnoldweb.hpp"
#include "command.hpp"
#include "plan_report.hpp"
#include "progress.hpp"
#include "stop_signals.hpp"

namespace arnoldweb::cli {
namespace {

struct RunFlags {
  SceneArgs scene;
  bool force = false;
  bool quiet = false;
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
}

int run_scene(const RunFlags& f) {
  // everything is checked before any work: scene, panels, output place
  const PreparedJob prepared = prepare_job(f.scene, f.force);
  const Job& job = prepared.job;
  auto backend = open_backend(job.main().scene.device);
  if (!f.quiet) {
    print_plan(std::cout, job.main(), backend->info().id + " (" + backend->info().name + ")");
    std::cout.flush();
  }
  StopSignals signals;  // held until the outputs are written
  RunOptions options;
  options.stop = &signals.flag();
  PartProgress progress(f.quiet);
  const JobResult result = run_job(job, *backend, options, &progress);
  const auto files = write_job(job, result, prepared.output);
  if (!f.quiet) {
    for (std::size_t k = 0; k < result.results.size(); ++k) report(job.parts[k], result.results[k]);
    for (const auto& file : files) std::cout << "wrote        " << file << "\n";
  }
  if (signals.signal()) {
    const Result& last = result.results.empty() ? Result{} : result.results.back();
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

}  // namespace

void add_run_command(CLI::App& app, Action& action) {
  auto flags = std::make_shared<RunFlags>();
  auto* c = app.add_subcommand("run", "Run a scene and write its outputs (summary.json, map.h5, pictures)");
  add_scene_options(c, flags->scene);
  c->add_flag("--force,-f", flags->force,
              "Replace an existing output directory, if a run of arnoldweb wrote it and nothing else is inside");
  c->add_flag("--quiet,-q", flags->quiet, "Print nothing but errors");
  c->callback([&action, flags] { action = [flags] { return run_scene(*flags); }; });
}

}  // namespace arnoldweb::cli
