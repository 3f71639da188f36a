// arnoldweb run SCENE: run a scene and write its outputs. Ctrl-C stops after
// the current chunk and writes what was computed (exit 130).
#include <atomic>
#include <csignal>
#include <iostream>

#include "arnoldweb/arnoldweb.hpp"
#include "command.hpp"
#include "plan_report.hpp"
#include "progress.hpp"

namespace arnoldweb::cli {
namespace {

std::atomic<bool> g_stop{false};
extern "C" void on_sigint(int) { g_stop.store(true); }

struct RunFlags {
  SceneArgs scene;
  bool force = false;
  bool quiet = false;
};

int run_scene(const RunFlags& f) {
  const Plan plan = make_plan(load_scene_args(f.scene));
  check_output_dir(plan.scene.output_dir, f.force);  // before any work
  auto backend = open_backend(plan.scene.device);
  if (!f.quiet) {
    print_plan(std::cout, plan, backend->info().id + " (" + backend->info().name + ")");
    std::cout.flush();
  }
  ConsoleProgress progress(static_cast<double>(plan.steps_per_trajectory), f.quiet);
  RunOptions options;
  options.progress = &progress;
  options.stop = &g_stop;
  std::signal(SIGINT, on_sigint);
  const Result result = run(plan, *backend, options);
  std::signal(SIGINT, SIG_DFL);
  const auto files = write_outputs(plan, result, plan.scene.output_dir, f.force);
  if (!f.quiet) {
    std::cout << "done         " << result.completed << " trajectories in " << short_number(result.wall_seconds)
              << " s (" << short_number(result.rate()) << " trajectory-steps/s)\n"
              << "binned       " << result.binned << ", flagged " << result.flagged() << " (non-finite "
              << result.flagged_nonfinite << ", energy " << result.flagged_energy << ", initial "
              << result.flagged_initial << ")\n";
    if (result.energy.tracked)
      std::cout << "energy error max " << short_number(result.energy.max) << ", mean "
                << short_number(result.energy.mean) << "\n";
    std::cout << "map digest   " << digest_map(result) << "\n";
    for (const auto& file : files) std::cout << "wrote        " << file << "\n";
  }
  if (result.interrupted) {
    std::cerr << "arnoldweb: interrupted after " << result.completed << " of " << result.trajectories
              << " trajectories; the partial result was written\n";
    return 130;
  }
  return 0;
}

}  // namespace

void add_run_command(CLI::App& app, Action& action) {
  auto flags = std::make_shared<RunFlags>();
  auto* c = app.add_subcommand("run", "Run a scene and write its outputs (summary.json, map.h5, pictures)");
  add_scene_options(c, flags->scene);
  c->add_flag("--force,-f", flags->force, "Replace an existing output directory");
  c->add_flag("--quiet,-q", flags->quiet, "Print nothing but errors");
  c->callback([&action, flags] { action = [flags] { return run_scene(*flags); }; });
}

}  // namespace arnoldweb::cli
