// Accuracy planning (accuracy.hpp): a pilot ensemble measures the energy
// error of each method at a few steps and finds the cheapest method and step
// for a target, as `arnoldweb accuracy` reports it.
#include "bindings.hpp"

#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

namespace awpy {
namespace {

nb::dict choice_dict(const arnoldweb::AccuracyChoice& c) {
  nb::dict d;
  d["method"] = c.method;
  d["stages"] = c.stages;
  d["step"] = c.step;
  d["forces_per_t"] = c.forces_per_t;
  d["predicted_max"] = c.predicted_max;
  d["predicted_median"] = c.predicted_median;
  d["measured_max"] = c.measured_max;
  d["measured_median"] = c.measured_median;
  d["guard_value"] = c.guard_value;
  d["meets"] = c.meets;
  d["note"] = c.note;
  return d;
}

nb::list points(const std::vector<arnoldweb::PilotPoint>& ps) {
  nb::list l;
  for (const auto& p : ps) {
    nb::dict d;
    d["step"] = p.step;
    d["max"] = p.max;
    d["median"] = p.median;
    l.append(d);
  }
  return l;
}

nb::dict accuracy(const arnoldweb::Scene& scene, double target, double safety, std::uint64_t pilot,
                  double pilot_duration, const std::vector<std::string>& methods, bool prefilter) {
  arnoldweb::PilotOptions o;
  o.safety = safety;
  o.trajectories = pilot;
  o.duration = pilot_duration;
  o.methods = methods;
  o.prefilter = prefilter;
  arnoldweb::AccuracyReport r;
  {
    nb::gil_scoped_release unlocked;
    auto backend = arnoldweb::open_backend(scene.device);
    r = arnoldweb::assess_accuracy(scene, arnoldweb::read_plan_inputs(scene), *backend,
                                   target > 0 ? target : scene.tolerance, o);
  }
  nb::dict d;
  d["device"] = r.device;
  d["pilot_trajectories"] = r.pilot_trajectories;
  d["pilot_duration"] = r.pilot_duration;
  d["pilot_every"] = r.pilot_every;
  d["pilot_seconds"] = r.pilot_seconds;
  d["tolerance"] = r.tolerance;
  d["safety"] = r.safety;
  nb::list fits;
  for (const auto& f : r.fits) {
    nb::dict x;
    x["method"] = f.method;
    x["order"] = f.order;
    x["stages"] = f.stages;
    x["points"] = points(f.points);
    x["checks"] = points(f.checks);
    x["order_fit"] = f.order_fit;
    x["floor"] = f.floor;
    x["prefiltered"] = f.prefiltered;
    fits.append(x);
  }
  d["fits"] = fits;
  d["as_written"] = r.as_written_measured ? nb::object(choice_dict(r.as_written)) : nb::none();
  d["scene_trajectory_steps"] = r.scene_trajectory_steps;
  d["scene_force_evaluations"] = r.scene_force_evaluations;
  d["rate"] = r.rate;
  d["scene_seconds"] = r.scene_seconds;
  d["found"] = r.found;
  d["best"] = r.found ? nb::object(choice_dict(r.best)) : nb::none();
  nb::list per;
  for (const auto& c : r.per_method) per.append(choice_dict(c));
  d["per_method"] = per;
  d["why_not"] = r.why_not;
  return d;
}

}  // namespace

void bind_accuracy(nb::module_& m) {
  m.def("_accuracy", &accuracy, nb::arg("scene"), nb::arg("target"), nb::arg("safety"), nb::arg("pilot"),
        nb::arg("pilot_duration"), nb::arg("methods"), nb::arg("prefilter"),
        "Runs the pilot ensemble on the scene's device; returns the report as a dict.");
}

}  // namespace awpy
