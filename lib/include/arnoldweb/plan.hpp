// arnoldweb: a plan is a validated scene turned into what the kernels need:
// the feature mask, the step schedule, the parameter buffers.
// Data flows one way: Scene -> Plan -> backend -> Result -> writers.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "arnoldweb/methods.hpp"
#include "arnoldweb/scene.hpp"

namespace arnoldweb {

namespace detail {
struct KernelParams;
}

// What a kernel is compiled for. Two plans with equal KernelConfig share a
// compiled program.
struct KernelConfig {
  Precision precision = Precision::Double;
  MathMode math = MathMode::Portable;
  std::uint32_t features = 0;  // AW_F_* bits (lib/device/aw_params.h)
  int stages = 0;
  bool kick_first = true;
  bool gradient = false;  // the method's kicks carry force-gradient terms
  int initial = 0;  // AW_INITIAL_*
  int model = 0;    // AW_MODEL_* (lib/device/models/aw_models.h)
  // An expression model's device header (model.kind = "expression", docs/models.md),
  // compiled as models/aw_expression.h; empty for the built-in models.
  std::string model_source;

  // -D options for the OpenCL and CUDA compilers (without lanes).
  std::string defines() const;
  bool operator==(const KernelConfig& o) const;
};

// Names of the effects in a feature mask, e.g. {"velocity_map", "energy_error"}.
std::vector<std::string> feature_names(std::uint32_t features);

// The step-size guard: h k |p|max against the splitting resonance at pi.
struct StepGuard {
  double p_max = 0;     // sqrt(2 (E + 2)): largest momentum on the shell (other models: omega / 2)
  double value = 0;     // h omega with h in time units (step * 2 pi); the paper's model: omega = k |p|max, k = 2
  double omega = 0;     // the model's largest frequency (radians per time unit)
  std::string basis;    // how omega was found, for messages
  double limit = 0;     // pi: refuse at or above
  double advised = 0;   // pi / 2: warn above
  double safe_step = 0; // largest step (in T) dividing the schedule with value <= advised
  bool refused() const { return value >= limit; }
  bool warned() const { return value > advised; }
};
StepGuard step_guard(double energy, double step, double average, double energy_every);  // the paper's model
StepGuard step_guard_at(double omega, double step, double average, double energy_every);  // any omega
// The largest frequency omega of the scene's model at its energy (the guard's
// h omega): the paper's model k |p|max; other models from their kinetic
// coefficients, the range and Hessian bound of V and their wave vectors
// (docs/models.md). Throws SceneError for a scene whose model keys are wrong.
double largest_frequency(const Scene& scene, std::string* basis = nullptr);

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

  // The kernels' parameter blocks (lib/device/aw_param_blocks.h), filled by
  // make_plan; read by the backends (lib/src/plan/kernel_params.hpp).
  std::shared_ptr<const detail::KernelParams> params;

  std::vector<std::string> effects() const { return feature_names(kernel.features); }
};

// Validate the scene as a whole and build the plan: a pure function of the
// scene (it opens no device and runs nothing). Throws SceneError for values
// that are wrong together (average not a multiple of the step, ...), naming
// the key and where its value came from. integrator.step = "auto" must be
// resolved first (resolve_step, accuracy.hpp).
Plan make_plan(const Scene& scene);

// What a plan needs in memory (estimates from the plan alone, upper bounds).
struct MemoryEstimate {
  std::uint64_t max_chunk = 0;  // the largest launch, in trajectories
  double histogram_bytes = 0;   // the histograms on the device (32-bit counts + 64-bit totals)
  double device_bytes = 0;      // everything on the device, for launches of max_chunk
  double state_bytes = 0;       // the state records of all trajectories, in this process
  double host_bytes = 0;        // everything in this process (results, copies while writing)
};
MemoryEstimate estimate_memory(const Plan& plan);

// The largest launch the runner makes for this plan (trajectories).
std::uint64_t largest_chunk(const Plan& plan);

struct DeviceInfo;
// Refuses, before anything is computed, a plan that does not fit the device
// (its memory and largest buffer) or this process (host_available bytes; 0:
// unknown): SceneError naming the key to change, with the numbers.
void check_memory(const Plan& plan, const DeviceInfo& device, std::uint64_t host_available);

}  // namespace arnoldweb
