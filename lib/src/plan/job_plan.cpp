// arnoldweb: planning a job: the scene and its panels (job.hpp).
#include "arnoldweb/job.hpp"

#include "output/pictures.hpp"
#include "plan/checks.hpp"

namespace arnoldweb {

namespace {

// A scene that asks for pictures where none can be drawn runs and writes its
// numbers; its plan says why it will draw none.
Plan plan_resolved(const Scene& scene, const StepResolver& resolve) {
  Plan p = make_plan(scene.step_auto && resolve ? resolve(scene) : scene);
  if (std::string why; p.scene.images && !detail::pictures_available(&why))
    p.warnings.push_back({"output.images", "output.images: no pictures will be drawn: " + why});
  return p;
}

// The states a part starts from when it names no file.
void give_states(JobPart& part, const std::shared_ptr<const StateSet>& states) {
  Plan& p = part.plan;
  if (p.scene.initial != "file" || p.states) return;
  if (!states)
    detail::fail_at(p.scene, "ensemble.initial",
                    "\"file\" needs ensemble.file = \"path.h5\", the HDF5 file of the states (docs/outputs.md, "
                    "\"State files\"), or the states from Python (run(scene, initial=(X, P)))");
  if (states->count != p.scene.trajectories) p = with_trajectories(p, states->count);
  p.states = states;
}

}  // namespace

Job plan_job(const Scene& scene, const StepResolver& resolve, std::shared_ptr<const StateSet> states) {
  Job job;
  JobPart main;
  main.plan = plan_resolved(scene, resolve);
  give_states(main, states);
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
    give_states(part, states);
    job.parts.push_back(std::move(part));
  }
  return job;
}

}  // namespace arnoldweb
