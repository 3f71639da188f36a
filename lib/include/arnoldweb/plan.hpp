// arnoldweb: a plan is a validated scene turned into what the kernels need:
// the feature mask, the step schedule, the parameter buffers.
// Data flows one way: Scene -> Plan -> backend -> Result -> writers.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "arnoldweb/methods.hpp"
#include "arnoldweb/scene.hpp"

namespace arnoldweb {

// What a kernel is compiled for. Two plans with equal KernelConfig share a
// compiled program.
struct KernelConfig {
  Precision precision = Precision::Double;
  MathMode math = MathMode::Portable;
  std::uint32_t features = 0;  // AW_F_* bits (lib/device/aw_params.h)
  int stages = 0;
  bool kick_first = true;
  int initial = 0;  // AW_INITIAL_*

  // -D options for the OpenCL and CUDA compilers (without lanes).
  std::string defines() const;
  bool operator==(const KernelConfig& o) const;
};

// Names of the effects in a feature mask, e.g. {"velocity_map", "energy_error"}.
std::vector<std::string> feature_names(std::uint32_t features);

// The step-size guard: h k |p|max against the splitting resonance at pi.
struct StepGuard {
  double p_max = 0;     // sqrt(2 (E + 2)): largest momentum on the shell
  double value = 0;     // h k |p|max with h in time units (step * 2 pi), k = 2
  double limit = 0;     // pi: refuse at or above
  double advised = 0;   // pi / 2: warn above
  double safe_step = 0; // largest step (in T) dividing the schedule with value <= advised
  bool refused() const { return value >= limit; }
  bool warned() const { return value > advised; }
};
StepGuard step_guard(double energy, double step, double average, double energy_every);

// How integrator.step = "auto" was resolved (make_plan; accuracy.hpp). The
// plan's scene then holds the chosen method and step, so that the scene as run
// reproduces the run without a pilot.
struct AutoStep {
  bool used = false;               // the scene asked for step = "auto"
  double tolerance = 0;            // integrator.tolerance: target max|dE|
  double safety = 0;               // the pilot's max|dE| x safety <= tolerance
  bool method_chosen = false;      // the pilot chose the method too (integrator.method not written)
  std::string method;              // the method chosen (or written)
  double step = 0;                 // the step chosen, in T
  double predicted_max = 0;        // pilot max|dE| predicted by the fit at that step
  double pilot_max = -1;           // measured at that method and step on the pilot ensemble
  double pilot_median = -1;
  std::uint64_t pilot_trajectories = 0;
  double pilot_duration = 0;       // in T
  std::string pilot_device;        // where the pilot ran
  double pilot_seconds = 0;
};

struct Plan {
  Scene scene;
  Method method;
  KernelConfig kernel;

  double step = 0;                      // in T
  std::int64_t steps_per_segment = 0;   // steps between energy samples
  std::int64_t segments_per_window = 0; // samples per averaging window
  std::int64_t windows = 0;             // averaging windows per trajectory
  std::int64_t steps_per_trajectory = 0;
  double trajectory_steps = 0;          // trajectories * steps_per_trajectory
  double force_evaluations = 0;         // trajectory_steps * stages

  std::uint64_t npix = 0;               // 12 nside^2 (0 without a velocity map)
  int frames = 1;                       // velocity maps (> 1: a time series)
  std::vector<std::int64_t> frame_bounds;  // frame k holds windows [b_k, b_k+1)
  int zoom_resolution = 0;              // R of the R x R zoom histogram (0: none)
  std::uint64_t hist_size = 0;          // counts on the device: frames * npix + R^2
  double accessible_fraction = 1;       // of the torus, for the initial states
  StepGuard guard;
  std::vector<std::string> warnings;
  AutoStep auto_step;                   // integrator.step = "auto": the choice and its pilot

  // Kernel parameter buffers (layout: lib/device/aw_params.h).
  std::vector<double> rp;
  std::vector<std::int64_t> ip;

  std::vector<std::string> effects() const { return feature_names(kernel.features); }
};

// Validate the scene as a whole and build the plan. Throws SceneError for
// values that are wrong together (average not a multiple of the step, ...),
// naming the key and its position. For integrator.step = "auto" the step (and
// the method, unless the scene names one) is chosen by a pilot ensemble on the
// cpu backend; make_plan(scene, backend) in accuracy.hpp runs it elsewhere.
Plan make_plan(const Scene& scene);

// Fraction of the torus where V(X) < E (Monte Carlo with a fixed seed).
double accessible_fraction(double energy);

}  // namespace arnoldweb
