// arnoldweb: planning a job: the scene and its panels (job.hpp).
#include "arnoldweb/job.hpp"

namespace arnoldweb {

namespace {

Plan plan_resolved(const Scene& scene, const StepResolver& resolve) {
  return make_plan(scene.step_auto && resolve ? resolve(scene) : scene);
}

}  // namespace

Job plan_job(const Scene& scene, const StepResolver& resolve) {
  Job job;
  JobPart main;
  main.plan = plan_resolved(scene, resolve);
  job.parts.push_back(std::move(main));
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
    sets.push_back("output.dir=" + scene.output_dir + "/panel-" + panel.name);
    labels.push_back("the output directory of panel " + panel.name);
    Scene s = parse_scene(scene.text, scene.file, sets, labels);
    s.panels.clear();
    JobPart part;
    part.name = panel.name;
    part.title = panel.title;
    part.subdir = "panel-" + panel.name;
    part.plan = plan_resolved(s, resolve);
    job.parts.push_back(std::move(part));
  }
  return job;
}

}  // namespace arnoldweb
