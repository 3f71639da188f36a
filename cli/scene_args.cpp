#include "command.hpp"

namespace arnoldweb::cli {

void add_scene_options(CLI::App* c, SceneArgs& a) {
  c->add_option("scene", a.scene, "Scene file (TOML); see docs/scenes.md")->required();
  c->add_option("--device,-d", a.device, "Device id: cpu, opencl:N, cuda:N or auto (overrides run.device)");
  c->add_option("--set,-s", a.sets, "Override a scene key, e.g. --set integrator.step=0.005 (repeatable)")
      ->allow_extra_args(false);
  c->add_option("--out,-o", a.out, "Output directory (overrides output.dir)");
}

Scene load_scene_args(const SceneArgs& a) {
  std::vector<std::string> sets = a.sets;
  if (!a.out.empty()) sets.push_back("output.dir=" + a.out);
  if (!a.device.empty()) sets.push_back("run.device=" + a.device);
  return load_scene(a.scene, sets);
}

}  // namespace arnoldweb::cli
