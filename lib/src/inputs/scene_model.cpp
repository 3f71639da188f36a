// arnoldweb: a scene's model evaluated on the host (models.hpp: SceneModel):
// the planner's model and parameters (model_plan.hpp) with the functions the
// planner and the state checks use, so that a state's energy is the one
// check_states gives and a shell momentum is made as the kernels make initial
// states (lib/device/aw_initial.h: P = s n, s = aw_model_speed(E - V(X), n)).
#include "arnoldweb/models.hpp"

#include "plan/model_plan.hpp"
#include "states/state_energy.hpp"
#include "states/state_rules.hpp"

namespace arnoldweb {

struct SceneModel::Model {
  const detail::ModelDescriptor* model = nullptr;
  detail::RealParams rp{};
  std::array<double, 6> kinetic{};
  double energy = 0;

  std::array<double, 3> wrapped(const double* u) const {
    return {detail::wrapped_turns(u[0]), detail::wrapped_turns(u[1]), detail::wrapped_turns(u[2])};
  }
};

SceneModel::SceneModel(const Scene& scene) : m_(std::make_unique<Model>()) {
  m_->model = &detail::model_of(scene);
  detail::plan_model_values(scene, *m_->model, m_->rp);
  m_->kinetic = m_->model->kinetic(m_->rp);
  m_->energy = scene.energy;
}

SceneModel::~SceneModel() = default;
SceneModel::SceneModel(SceneModel&&) noexcept = default;

double SceneModel::energy() const { return m_->energy; }

double SceneModel::potential(const double* u) const {
  const auto w = m_->wrapped(u);
  return m_->model->potential(w[0], w[1], w[2], m_->rp);
}

double SceneModel::hamiltonian(const double* u, const double* p) const {
  return detail::state_energy(*m_->model, m_->rp, m_->kinetic, m_->wrapped(u).data(), p);
}

bool SceneModel::shell_momentum(const double* u, const double* n, double* p) const {
  double s = 0;
  if (!m_->model->speed(m_->energy - potential(u), n, m_->rp, s)) return false;
  for (int k = 0; k < 3; ++k) p[k] = s * n[k];
  return true;
}

}  // namespace arnoldweb
