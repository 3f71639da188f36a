// arnoldweb continue OUTDIR --for DURATION: go on from where a finished run
// ended. The scene is the run's scene as run (summary.json's scene_toml), its
// trajectories start from the final states, windings and time of its
// states.h5 (ensemble.initial = "file"), and they run DURATION more T: a run
// of 2T is, bit for bit, a run of T continued for T (the final states, and
// the map of the second window). The outputs go to --out (default
// OUTDIR-to-<end time>); --device and --set apply on top, --set only for the
// keys that leave the trajectories unchanged (continue_keys()).
#include "arnoldweb/arnoldweb.hpp"
#include "command.hpp"
#include "ranks.hpp"

namespace arnoldweb::cli {
namespace {

struct ContinueFlags {
  std::string from;
  double duration = 0;
  SceneArgs scene;  // --out, --device, --set (the scene itself comes from the run)
  bool force = false;
  bool quiet = false;
};

int continue_run(ContinueFlags& f) {
  refuse_mpirun_without_mpi();
  if (cluster() && cluster()->rank() != 0) return serve_rank(f.scene.device);
  std::string from = f.from;
  while (from.size() > 1 && from.back() == '/') from.pop_back();
  if (!(f.duration > 0))
    throw SceneError("--for", 0, 0, "run.duration", "--for must be a duration in T greater than 0");
  // the run's scene as run, then what continuing changes, then the user's --set, --out, --device
  ContinueArgs args;
  args.duration = f.duration;
  args.sets = f.scene.sets;
  args.out = f.scene.out;
  args.out_beside = true;
  args.device = f.scene.device;
  const Continuation run = continuation_of(from, args);
  const Scene scene = parse_scene(run.scene_toml, run.source, run.overrides, run.labels);
  const PreparedJob prepared = prepare_scene_job(scene, run.source, f.force);
  return execute_job(prepared, f.quiet, std::nullopt, f.scene.device);
}

}  // namespace

void add_continue_command(CLI::App& app, Action& action) {
  auto flags = std::make_shared<ContinueFlags>();
  auto* c = app.add_subcommand("continue", "Go on from where a finished run ended: its final states, windings and "
                                           "time, for DURATION more (bit for bit as one longer run)");
  c->add_option("outdir", flags->from, "The output directory of the finished run (with states.h5)")->required();
  c->add_option("--for", flags->duration, "How much longer, in T (a multiple of run.average)")->required();
  c->add_option("--out,-o", flags->scene.out, "Output directory (default: OUTDIR-to-<end time>)");
  c->add_option("--device,-d", flags->scene.device,
                "Device: cpu, opencl:N, cuda:N, auto, all (every GPU) or a list cuda:0,cuda:1 (default: the run's)");
  c->add_option("--set,-s", flags->scene.sets,
                "Override a key of the run's scene that leaves the trajectories unchanged (outputs, device, "
                "checkpoints; docs/cluster.md): --set key=value");
  c->add_flag("--force,-f", flags->force, "Replace an existing output directory that arnoldweb wrote");
  c->add_flag("--quiet,-q", flags->quiet, "Print nothing but errors");
  c->callback([&action, flags] { action = [flags] { return continue_run(*flags); }; });
}

}  // namespace arnoldweb::cli
