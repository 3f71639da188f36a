// arnoldweb: the planner's part for given initial states (plan_states.hpp),
// and the public checks of states against a scene (states.hpp).
#include "plan/plan_states.hpp"

#include "arnoldweb/errors.hpp"
#include "plan/checks.hpp"
#include "plan/model_plan.hpp"
#include "states/state_energy.hpp"
#include "states/state_rules.hpp"

namespace arnoldweb {
namespace detail {

std::shared_ptr<StateSet> read_scene_states(Scene& scene) {
  if (scene.initial != "file") {
    if (!scene.initial_file.empty())
      fail_at(scene, "ensemble.file",
              "is read only with ensemble.initial = \"file\" (ensemble.initial is \"" + scene.initial + "\")");
    return nullptr;
  }
  if (scene.initial_file.empty()) return nullptr;  // given by the caller (Python's initial=)
  auto states = std::make_shared<StateSet>(read_state_file(scene.initial_file));
  const SourcePos at = scene.pos("ensemble.trajectories");
  if ((at.line > 0 || at.set_index > 0) && scene.trajectories != states->count)
    fail_at(scene, "ensemble.trajectories",
            "ensemble.initial = \"file\" integrates one trajectory per state: " + states->source + " has " +
                std::to_string(states->count) + " states, ensemble.trajectories says " +
                std::to_string(scene.trajectories) + "; leave ensemble.trajectories out or set it to " +
                std::to_string(states->count));
  scene.trajectories = states->count;
  return states;
}

void check_scene_states(StateSet& states, const Scene& scene, const ModelDescriptor& model, const RealParams& rp) {
  check_state_energies(states, model, rp, scene.energy);
  check_start_time(states, scene.duration);
}

}  // namespace detail

void check_states(StateSet& states, const Scene& scene) {
  const detail::ModelDescriptor& model = detail::model_of(scene);
  detail::RealParams rp{};
  detail::plan_model_values(scene, model, rp);
  detail::check_scene_states(states, scene, model, rp);
}

StateSet load_initial_states(const Scene& scene) {
  StateSet s = read_state_file(scene.initial_file);
  check_states(s, scene);
  return s;
}

}  // namespace arnoldweb
