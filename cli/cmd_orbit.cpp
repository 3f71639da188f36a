// arnoldweb orbit SCENE --id N: trajectory N of a scene alone, sampled every
// T (observe.trajectories = { ids = [N], every = T }), with the bits it has in
// a run of the whole ensemble (run_range): trajectories.h5 and summary.json
// (and the scene's per-trajectory files, of that trajectory) in --out, by
// default <output.dir>-orbit-N. Velocity maps, zoom, frames, panels and time
// slices are left out: they sample nothing of one orbit.
#include <iostream>

#include "arnoldweb/arnoldweb.hpp"
#include "arnoldweb/errors.hpp"
#include "command.hpp"
#include "plan_report.hpp"
#include "ranks.hpp"

namespace arnoldweb::cli {
namespace {

struct OrbitFlags {
  SceneArgs scene;
  std::uint64_t id = 0;
  std::optional<double> every;
  bool force = false;
  bool quiet = false;
};

int run_orbit(const OrbitFlags& f) {
  refuse_mpirun_without_mpi();
  if (cluster())  // one trajectory: one process (each rank would write the same directory)
    throw OutputRefused("", "arnoldweb orbit runs one trajectory in one process: run it without mpirun or srun");
  Scene scene = load_scene_args(f.scene);
  if (f.id >= scene.trajectories)
    throw SceneError("--id", 0, 0, "observe.trajectories.ids",
                     "trajectory " + std::to_string(f.id) + " is not in the ensemble (ensemble.trajectories = " +
                         std::to_string(scene.trajectories) + ": --id 0 to " + std::to_string(scene.trajectories - 1) +
                         ")");
  scene.output_values["observe.trajectories.ids"] = {static_cast<double>(f.id)};
  scene.output_values.erase("observe.trajectories.count");
  if (f.every) scene.output_values["observe.trajectories.every"] = {*f.every};
  scene.velocity_map = false;
  scene.zoom = false;
  scene.frame_times.clear();
  scene.panels.clear();
  scene.slice = 0;
  if (!f.scene.out) scene.output_dir += "-orbit-" + std::to_string(f.id);
  const PreparedJob prepared = prepare_scene_job(scene, f.scene.scene, f.force);
  const Plan& plan = prepared.job.main();
  const auto backends = open_backends(plan.scene.device);
  JobResult result;
  result.results.push_back(run_range(plan, *backends.front(), f.id, 1));
  const auto files = write_job(prepared.job, result, prepared.output);
  if (!f.quiet) {
    std::cout << "orbit        trajectory " << f.id << " of " << plan.scene.trajectories << ", every "
              << short_number(plan.scene.output_value("observe.trajectories.every").at(0)) << " T over " << short_number(plan.scene.duration)
              << " T, on " << backends.front()->info().id << "\n";
    for (const auto& file : files) std::cout << "wrote        " << file << "\n";
  }
  return 0;
}

}  // namespace

void add_orbit_command(CLI::App& app, Action& action) {
  auto flags = std::make_shared<OrbitFlags>();
  auto* c = app.add_subcommand("orbit", "Run one trajectory of a scene alone (the bits it has in the whole run) and "
                                        "write its sampled states: trajectories.h5");
  add_scene_options(c, flags->scene);
  c->add_option("--id", flags->id, "The trajectory (its index in the scene's ensemble)")->required();
  c->add_option("--every", flags->every,
                "Sample interval in T (default: observe.trajectories.every); divides run.duration and is a "
                "multiple of the shortest sample interval")
      ->check(CLI::PositiveNumber);
  c->add_flag("--force,-f", flags->force,
              "Replace an existing output directory, if a run of arnoldweb wrote it and nothing else is inside");
  c->add_flag("--quiet,-q", flags->quiet, "Print nothing but errors");
  c->callback([&action, flags] { action = [flags] { return run_orbit(*flags); }; });
}

}  // namespace arnoldweb::cli
