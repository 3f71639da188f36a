#include "arnoldweb/accuracy.hpp"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/inputs.hpp"
#include "command.hpp"

namespace arnoldweb::cli {

void add_scene_options(CLI::App* c, SceneArgs& a) {
  c->add_option("scene", a.scene, "Scene file (TOML); see docs/scenes.md")->required();
  c->add_option("--device,-d", a.device, "Device: cpu, opencl:N, cuda:N, auto, all (every GPU) or a list cuda:0,cuda:1 (overrides run.device)");
  c->add_option("--set,-s", a.sets, "Override a scene key, e.g. --set integrator.step=0.005 (repeatable)")
      ->allow_extra_args(false);
  c->add_option("--out,-o", a.out, "Output directory (overrides output.dir)");
}

Scene load_scene_args(const SceneArgs& a) {
  std::vector<std::string> sets = a.sets, labels(a.sets.size());
  if (a.out) {
    if (a.out->empty()) throw OutputRefused("", "--out was given an empty directory name");
    sets.push_back(string_override("output.dir", *a.out, "--out " + *a.out));
    labels.push_back("--out " + *a.out);
  }
  if (a.device) {
    sets.push_back(string_override("run.device", *a.device, "--device " + *a.device));
    labels.push_back("--device " + *a.device);
  }
  return load_scene(a.scene, sets, labels);
}

std::optional<std::string> read_device_option(const std::optional<std::string>& device) {
  if (!device) return device;
  const std::string label = "--device " + *device;
  return parse_scene("", "", {string_override("run.device", *device, label)}, {label}).device;
}

PreparedJob prepare_job(const SceneArgs& args, bool force, std::string* device_warning) {
  return prepare_scene_job(load_scene_args(args), args.scene, force, device_warning);
}

PreparedJob prepare_scene_job(const Scene& scene, const std::string& scene_file, bool force,
                              std::string* device_warning) {
  PreparedJob p;
  p.job = plan_job(scene, read_plan_inputs(scene), cpu_pilot());
  p.output.force = force;
  p.output.scene_file = scene_file;
  p.output.expected_bytes = estimate_output_bytes(p.job);
  // memory: every device's and this process's, before anything is computed
  std::vector<DeviceInfo> devices;
  try {
    for (const std::string& id : device_ids(p.job.main().scene.device)) devices.push_back(find_device(id));
  } catch (const DeviceError& e) {
    if (!device_warning) throw;
    *device_warning = e.what();
    devices = {DeviceInfo{}};
  }
  const std::uint64_t host = available_memory();
  for (const DeviceInfo& device : devices)
    for (const JobPart& part : p.job.parts) check_memory(part.plan, device, host);
  p.out_dir = check_output_dir(p.job.main().scene.output_dir, p.output);
  return p;
}

}  // namespace arnoldweb::cli
