#include "plan_report.hpp"

#include <cstdio>

namespace arnoldweb::cli {

std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// As an ostream writes a double (%g).
std::string general_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void print_plan(std::ostream& o, const Plan& p, const std::string& device) {
  const Scene& s = p.scene;
  o << "scene        " << s.file << "\n"
    << "device       " << device << "\n"
    << "model        "
    << (p.effective_perturbation != 0
            ? "E = " + general_number(s.energy) + "  (eps_eff = " + short_number(p.effective_perturbation) +
                  ", accessible torus " + short_number(100 * p.accessible_fraction) + "%)"
            : s.model_kind + ", E = " + general_number(s.energy) + "  (energy surface reached from " +
                  short_number(100 * p.accessible_fraction) + "% of positions and directions)")
    << "\n"
    << "ensemble     " << s.trajectories << " trajectories, " << s.initial << ", seed " << s.seed << "\n"
    << "integrator   " << p.method.name << " (order " << p.method.order << ", " << p.method.stages
    << " force evaluations/step), h = " << p.step << " T, " << to_string(s.precision) << ", "
    << to_string(s.math) << " math\n"
    << "schedule     " << p.windows << " window(s) of " << s.average << " T = " << p.segments_per_window
    << " x " << p.steps_per_segment << " steps; " << p.steps_per_trajectory << " steps per trajectory\n"
    << "step guard   " << p.guard.quantity << " = "
    << short_number(p.guard.value) << " (refused >= pi, advised <= pi/2; " << p.guard.basis << ")\n"
    << "effects      ";
  const auto eff = p.effects();
  for (std::size_t i = 0; i < eff.size(); ++i) o << (i ? ", " : "") << eff[i];
  o << (eff.empty() ? "(none)" : "") << "\n"
    << "kernel       " << p.kernel.defines() << "\n"
    << "chunks       " << (s.chunk ? std::to_string(s.chunk) + " trajectories each"
                                   : std::string("sized by the runner to about 0.25 s each")) << "\n"
    << "work         " << short_number(p.trajectory_steps) << " trajectory-steps, "
    << short_number(p.force_evaluations) << " force evaluations\n";
  if (s.velocity_map) o << "velocity map HEALPix nside " << s.nside << " (" << p.npix << " pixels, RING)\n";
  if (p.scene.auto_step.used)
    o << "auto step    " << p.scene.auto_step.method << " at h = " << p.scene.auto_step.step << " T for max |dE| <= "
      << short_number(p.scene.auto_step.tolerance) << " (pilot: " << p.scene.auto_step.pilot_trajectories << " trajectories, max |dE| "
      << short_number(p.scene.auto_step.pilot_max) << ")\n";
  for (const auto& w : p.warnings) o << "warning      " << w.text << "\n";
}

}  // namespace arnoldweb::cli
