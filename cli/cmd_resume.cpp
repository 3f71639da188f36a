// arnoldweb resume OUTDIR: continue the run whose checkpoint waits beside
// OUTDIR (in OUTDIR.partial-PID). The scene comes from the checkpoint (its
// text and --set values as they were given), planned again; --device may
// choose another device. The result is the same bits as an uninterrupted run.
#include <iostream>

#include "arnoldweb/arnoldweb.hpp"
#include "arnoldweb/checkpoint.hpp"
#include "command.hpp"
#include "ranks.hpp"

namespace arnoldweb::cli {
namespace {

struct ResumeFlags {
  std::string out;
  std::optional<std::string> device;
  bool quiet = false;
};

int resume(const ResumeFlags& f) {
  refuse_mpirun_without_mpi();
  if (cluster() && cluster()->rank() != 0) return serve_rank(f.device);
  std::string out = f.out;
  while (out.size() > 1 && out.back() == '/') out.pop_back();
  const FoundCheckpoint found = checkpoint_to_resume(out);
  const CheckpointInfo info = read_checkpoint_info(read_checkpoint_file(found.file), found.file);
  std::vector<std::string> sets = info.overrides, labels = info.override_labels;
  labels.resize(sets.size());
  sets.push_back(string_override("output.dir", out, "resume " + out));
  labels.push_back("resume " + out);
  if (f.device) {
    const std::string device = explicit_rank_device(f.device).value_or(*f.device);
    sets.push_back(string_override("run.device", device, "--device " + device));
    labels.push_back("--device " + device);
  }
  const Scene scene = parse_scene(info.scene_text, info.scene_file, sets, labels);
  const PreparedJob prepared = prepare_scene_job(scene, info.scene_file, false);
  return execute_job(prepared, f.quiet, found, f.device);
}

}  // namespace

void add_resume_command(CLI::App& app, Action& action) {
  auto flags = std::make_shared<ResumeFlags>();
  auto* c = app.add_subcommand("resume", "Continue an interrupted run from the checkpoint beside its output directory");
  c->add_option("outdir", flags->out, "The output directory of the interrupted run")->required();
  c->add_option("--device,-d", flags->device, "Device: cpu, opencl:N, cuda:N, auto, all (every GPU) or a list cuda:0,cuda:1 (default: the scene's)");
  c->add_flag("--quiet,-q", flags->quiet, "Print nothing but errors");
  c->callback([&action, flags] { action = [flags] { return resume(*flags); }; });
}

}  // namespace arnoldweb::cli
