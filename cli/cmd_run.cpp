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

// A panel of the scene: the scene file with the panel's overrides, then the
// user's (so --set applies to every panel), writing into <dir>/panel-<name>.
Plan panel_plan(const Plan& main, const Scene::Panel& panel) {
  std::vector<std::string> sets = panel.sets;
  sets.insert(sets.end(), main.scene.overrides.begin(), main.scene.overrides.end());
  sets.push_back("output.dir=" + main.scene.output_dir + "/panel-" + panel.name);
  Scene s = load_scene(main.scene.file, sets);
  s.panels.clear();
  return make_plan(s);
}

int run_scene(const RunFlags& f) {
  const Plan plan = make_plan(load_scene_args(f.scene));
  std::vector<Plan> panel_plans;  // planned up front: a bad panel fails before any work
  for (const auto& panel : plan.scene.panels) panel_plans.push_back(panel_plan(plan, panel));
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

  // the panels, then the figure that shows them together
  std::vector<Result> panel_results;
  for (std::size_t k = 0; k < panel_plans.size(); ++k) {
    const Plan& pp = panel_plans[k];
    if (!f.quiet) std::cout << "\npanel        " << plan.scene.panels[k].name << ": " << plan.scene.panels[k].title << "\n";
    ConsoleProgress panel_progress(static_cast<double>(pp.steps_per_trajectory), f.quiet);
    options.progress = &panel_progress;
    std::signal(SIGINT, on_sigint);
    panel_results.push_back(run(pp, *backend, options));
    std::signal(SIGINT, SIG_DFL);
    const Result& pr = panel_results.back();
    for (const auto& file : write_outputs(pp, pr, pp.scene.output_dir, false))
      if (!f.quiet) std::cout << "wrote        " << file << "\n";
    if (pr.interrupted) {
      std::cerr << "arnoldweb: interrupted in panel " << plan.scene.panels[k].name << "; what was computed was written\n";
      return 130;
    }
  }
  if (!panel_plans.empty()) {
    std::vector<FigurePanel> panels;
    for (std::size_t k = 0; k < panel_plans.size(); ++k)
      panels.push_back({plan.scene.panels[k].name, plan.scene.panels[k].title, &panel_plans[k], &panel_results[k]});
    const std::string figure = write_figure(plan.scene.output_dir, plan, result, panels);
    if (!figure.empty() && !f.quiet) std::cout << "wrote        " << figure << "\n";
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
