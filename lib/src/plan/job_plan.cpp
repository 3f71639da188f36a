// arnoldweb: planning a job: the scene and its panels (job.hpp).
#include "arnoldweb/job.hpp"

#include "plan/checks.hpp"

namespace arnoldweb {

std::vector<PartScene> part_scenes(const Scene& scene) {
  std::vector<PartScene> parts = {{"", "", "", scene}};
  for (const Scene::Panel& panel : scene.panels) {
    // the panel's overrides, then the user's (so --set applies to every panel)
    std::vector<std::string> sets = panel.sets;
    std::vector<std::string> labels;
    for (std::size_t i = 0; i < panel.sets.size(); ++i)  // where it was written, for messages
      labels.push_back((i < panel.set_origins.size() ? panel.set_origins[i] + ": " : std::string()) + "[[panel]] " +
                       panel.name + ": " + panel.sets[i]);
    sets.insert(sets.end(), scene.overrides.begin(), scene.overrides.end());
    labels.insert(labels.end(), scene.override_labels.begin(), scene.override_labels.end());
    labels.resize(sets.size());
    const std::string label = "the output directory of panel " + panel.name;
    sets.push_back(string_override("output.dir", scene.output_dir + "/panel-" + panel.name, label));
    labels.push_back(label);
    Scene s = parse_scene(scene.text, scene.file, sets, labels);
    s.panels.clear();
    parts.push_back({panel.name, panel.title, "panel-" + panel.name, std::move(s)});
  }
  return parts;
}

Job plan_job(const Scene& scene, const PlanInputs& inputs, const StepResolver& resolve) {
  Job job;
  for (const PartScene& part : part_scenes(scene)) {
    const Scene& s = part.scene;
    Plan plan = make_plan(s.step_auto && resolve ? resolve(s, inputs) : s, inputs);
    if (plan.scene.initial == "file" && !plan.states) {
      if (!plan.scene.initial_file.empty())
        detail::fail_at(plan.scene, "ensemble.file",
                        "its states are read before planning, and these inputs lack them (read_plan_inputs, "
                        "inputs.hpp)");
      detail::fail_at(plan.scene, "ensemble.initial",
                      "\"file\" needs ensemble.file = \"path.h5\", the HDF5 file of the states (docs/outputs.md, "
                      "\"State files\"), or the states from Python (run(scene, initial=(X, P)))");
    }
    job.parts.push_back({part.name, part.title, part.subdir, std::move(plan)});
  }
  return job;
}

}  // namespace arnoldweb
