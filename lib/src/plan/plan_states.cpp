// arnoldweb: the planner's part for given initial states (plan_states.hpp)
// and where a scene's states are among the plan's inputs (plan.hpp).
#include "plan/plan_states.hpp"

#include "plan/checks.hpp"

namespace arnoldweb {

std::shared_ptr<const StateSet> PlanInputs::states_for(const Scene& scene) const {
  if (scene.initial_file.empty()) return given_states;
  const auto it = state_files.find(scene.initial_file);
  return it == state_files.end() ? nullptr : it->second;
}

namespace detail {

std::shared_ptr<const StateSet> plan_states(Scene& scene, const PlanInputs& inputs) {
  if (scene.initial != "file") {
    if (!scene.initial_file.empty())
      fail_at(scene, "ensemble.file",
              "is read only with ensemble.initial = \"file\" (ensemble.initial is \"" + scene.initial + "\")");
    return nullptr;
  }
  std::shared_ptr<const StateSet> states = inputs.states_for(scene);
  if (!states) return nullptr;  // planned without them: attached later, or the run is refused
  // a file's states are the ensemble: ensemble.trajectories, where written, must count them (the
  // states Python gives replace the scene's ensemble, its count included)
  const SourcePos at = scene.pos("ensemble.trajectories");
  if (!scene.initial_file.empty() && (at.line > 0 || at.set_index > 0) && scene.trajectories != states->count)
    fail_at(scene, "ensemble.trajectories",
            "ensemble.initial = \"file\" integrates one trajectory per state: " + states->source + " has " +
                show_count(states->count) + " states, ensemble.trajectories says " + show_count(scene.trajectories) +
                "; leave ensemble.trajectories out or set it to " + show_count(states->count));
  scene.trajectories = states->count;
  return states;
}

}  // namespace detail
}  // namespace arnoldweb
