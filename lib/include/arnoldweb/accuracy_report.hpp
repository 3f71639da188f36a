// arnoldweb: what accuracy planning reports (accuracy.hpp): the pilot's
// options, its measurements, each method's fit and the cheapest choice. The
// search over methods and steps that fills it is planning (plan/step_search.hpp,
// which runs nothing itself: the pilot ensembles are run by whoever calls it,
// accuracy.cpp on a device).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace arnoldweb {

struct PilotOptions {
  // The pilot ensemble: the first trajectories of the scene's own ensemble
  // (same seed and initial distribution), at most the scene's count.
  std::uint64_t trajectories = 512;
  double duration = 5.0;  // in T; at most the scene's duration
  // A choice must satisfy (max|dE| on the pilot) x safety <= tolerance: the
  // maximum over a full ensemble (10^5..10^8 trajectories, 50 T) is up to
  // ~2.5x the pilot's (docs/accuracy.md).
  double safety = 4.0;
  int steps_per_method = 3;  // pilot steps per method: h0, h0/2, h0/4
  // Methods to consider; empty: every method.
  std::vector<std::string> methods;
  // Run the chosen method and step on the pilot ensemble before accepting it.
  bool verify = true;
  // Pre-filter: measure the steps past h0/2 (the costliest: h0/4 costs 4x h0) only for
  // methods that could still be the cheapest. After h0 and h0/2, a method is passed over
  // where even its most optimistic extrapolation (error ~ h^(q+2), q its highest order in
  // eps) needs more force evaluations than the cheapest conservative prediction of any
  // method. Such a method keeps its two points and is never the cheapest (docs/accuracy.md).
  bool prefilter = true;
};

// One pilot measurement.
struct PilotPoint {
  double step = 0;    // in T
  double max = 0;     // max over the pilot ensemble of max_t |dE|
  double median = 0;  // median of the same (upper edge of its log2 histogram bin)
};

// The pilot of one method and what it predicts.
struct MethodFit {
  std::string method;
  int order = 0;   // nominal
  int stages = 0;  // force evaluations per step
  double work = 0;  // their cost in plain force evaluations (Method::work)
  std::vector<PilotPoint> points;  // the pilot ladder, decreasing steps
  std::vector<PilotPoint> checks;  // runs at candidate steps (they join the fit)
  // max|dE| ~ C step^p between and below the measured steps; `order_fit` is
  // the slope of the last two converging points, `floor` the error where the
  // pilot stopped converging (round-off), 0 if it did not.
  double order_fit = 0;
  double floor = 0;
  int top_order = 0;         // highest order in h and eps (Method::eps_orders)
  bool prefiltered = false;  // the pre-filter skipped the steps past h0/2
  double optimistic_forces_per_t = 0;  // the pre-filter's best case (0: not evaluated)
  double predict_max(double step) const;
  double predict_median(double step) const;
};

// A method and step, with what the pilot says about them.
struct AccuracyChoice {
  std::string method;
  int stages = 0;
  double step = 0;                  // in T, divides the scene's schedule
  double predicted_max = 0;         // from the fit, on the pilot ensemble
  double predicted_median = 0;
  double measured_max = -1;         // run on the pilot ensemble (-1: not run)
  double measured_median = -1;
  double forces_per_t = 0;          // force evaluations per trajectory per T (Method::work per step)
  double guard_value = 0;           // h k |p|max
  bool meets = false;               // meets the tolerance with the safety factor
  std::string note;                 // why not, if it does not
};

struct AccuracyReport {
  std::string device;  // where the pilot ran
  std::uint64_t pilot_trajectories = 0;
  double pilot_duration = 0;  // T
  double pilot_every = 0;     // |dE| sample interval of the pilot, in T
  double pilot_seconds = 0;   // wall time of the whole pilot
  double tolerance = 0;
  double safety = 0;
  std::vector<MethodFit> fits;

  // The scene as written (when its step is a number): measured on the pilot
  // ensemble, and its whole cost.
  bool as_written_measured = false;
  AccuracyChoice as_written;
  double scene_trajectory_steps = 0;
  double scene_force_evaluations = 0;
  double rate = 0;              // trajectory-steps/s of the scene's kernel on the device
  double scene_seconds = 0;     // scene_trajectory_steps / rate

  // The cheapest method and step meeting the tolerance, and the cheapest step
  // of every method considered (in the order of methods()).
  bool found = false;
  AccuracyChoice best;
  std::vector<AccuracyChoice> per_method;
  std::string why_not;  // when nothing meets the tolerance
};

}  // namespace arnoldweb
