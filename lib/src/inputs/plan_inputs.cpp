// arnoldweb: the stage before planning (inputs.hpp), and the checks of states
// against a scene (states.hpp): the scene's model, its parameters and energy, and run.duration.
#include "arnoldweb/inputs.hpp"

#include "arnoldweb/job.hpp"
#include "output/pictures.hpp"
#include "plan/model_plan.hpp"
#include "states/state_energy.hpp"
#include "states/state_rules.hpp"

namespace arnoldweb {

void check_states(StateSet& states, const Scene& scene) {
  const detail::ModelDescriptor& model = detail::model_of(scene);
  detail::RealParams rp{};
  detail::plan_model_values(scene, model, rp);
  detail::check_state_energies(states, model, rp, scene.energy);
  detail::check_start_time(states, scene.duration);
}

StateSet load_initial_states(const Scene& scene) {
  StateSet s = read_state_file(scene.initial_file);
  check_states(s, scene);
  return s;
}

PlanInputs read_plan_inputs(const Scene& scene, std::shared_ptr<const StateSet> given) {
  PlanInputs in;
  in.given_states = std::move(given);
  bool pictures = false;
  for (const PartScene& part : part_scenes(scene)) {
    const Scene& s = part.scene;
    pictures = pictures || s.images;
    if (s.initial != "file" || s.initial_file.empty()) continue;
    auto& states = in.state_files[s.initial_file];
    if (states) {  // read for another part: checked against this one's model and energy too
      StateSet again = *states;
      check_states(again, s);
    } else {
      states = std::make_shared<const StateSet>(load_initial_states(s));
    }
  }
  if (std::string why; pictures && !detail::pictures_available(&why)) in.no_pictures = why;
  return in;
}

}  // namespace arnoldweb
