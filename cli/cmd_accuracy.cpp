// arnoldweb accuracy SCENE: a short pilot ensemble predicts the energy error
// and cost of the scene as written, and finds the cheapest method and step for
// a target error (docs/accuracy.md). Runs nothing else and writes nothing.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "arnoldweb/accuracy.hpp"
#include "arnoldweb/arnoldweb.hpp"
#include "command.hpp"
#include "plan_report.hpp"

namespace arnoldweb::cli {
namespace {

struct AccuracyFlags {
  SceneArgs scene;
  double target = 0;  // 0: the scene's integrator.tolerance
  double safety = 4;
  std::uint64_t pilot = 512;
  double pilot_duration = 5;
  std::vector<std::string> methods;
  bool no_prefilter = false;
};

std::string num(double v) {
  if (v < 0) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", v);
  return buf;
}

// A step as T/n when it is one (the pilot's steps are), else its digits.
std::string step_str(double v) {
  char buf[48];
  const double n = std::nearbyint(1.0 / v);
  if (n >= 1 && std::fabs(1.0 / v - n) <= 1e-9 * n) std::snprintf(buf, sizeof buf, "T/%.0f", n);
  else std::snprintf(buf, sizeof buf, "%.6g T", v);
  return buf;
}

// Digits enough for --set to give back a step that divides the schedule.
std::string step_value(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

std::string seconds_str(double s) {
  char buf[48];
  if (s < 120) std::snprintf(buf, sizeof buf, "%.3g s", s);
  else if (s < 7200) std::snprintf(buf, sizeof buf, "%.3g min", s / 60);
  else if (s < 2 * 86400) std::snprintf(buf, sizeof buf, "%.3g h", s / 3600);
  else std::snprintf(buf, sizeof buf, "%.3g days", s / 86400);
  return buf;
}

int run_accuracy(const AccuracyFlags& f) {
  const Scene scene = load_scene_args(f.scene);
  const double target = f.target > 0 ? f.target : scene.tolerance;
  auto backend = open_backend(scene.device);
  PilotOptions o;
  o.safety = f.safety;
  o.trajectories = f.pilot;
  o.duration = f.pilot_duration;
  o.methods = f.methods;
  o.prefilter = !f.no_prefilter;
  const AccuracyReport r = assess_accuracy(scene, read_plan_inputs(scene), *backend, target, o);

  std::cout << "scene        " << scene.file << " (E = " << scene.energy << ", " << scene.trajectories
            << " trajectories, " << scene.duration << " T, " << to_string(scene.precision) << ", "
            << to_string(scene.math) << " math)\n"
            << "pilot        " << r.pilot_trajectories << " trajectories x " << r.pilot_duration << " T on "
            << r.device << " (" << backend->info().name << "), |dE| every " << r.pilot_every << " T; "
            << short_number(r.pilot_seconds) << " s\n";
  if (r.as_written_measured) {
    const AccuracyChoice& a = r.as_written;
    std::cout << "as written   " << a.method << ", h = " << step_str(a.step) << " (h k |p|max = "
              << short_number(a.guard_value) << "): pilot max |dE| " << num(a.measured_max) << ", median "
              << num(a.measured_median)
              << (a.guard_value >= M_PI ? "\n             (the step guard refuses this step: h k |p|max >= pi)" : "")
              << "\n"
              << "             cost " << short_number(r.scene_force_evaluations) << " force evaluations ("
              << short_number(r.scene_trajectory_steps) << " trajectory-steps), about "
              << seconds_str(r.scene_seconds) << " on " << r.device << " at " << short_number(r.rate)
              << " trajectory-steps/s\n";
  } else {
    std::cout << "as written   step = \"auto\" (tolerance " << scene.tolerance << "): "
              << short_number(r.scene_trajectory_steps) << " trajectory-steps at h = 0.01 T for scale\n";
  }
  std::cout << "target       max |dE| <= " << target << " with safety " << r.safety
            << " (pilot max |dE| <= " << num(target / r.safety) << ")\n\n";

  std::printf("%-13s %5s %6s  %-24s  %-10s %9s  %-9s %-9s %-9s  %s\n", "method", "order", "forces",
              "pilot max |dE| at h0,h0/2,h0/4", "step", "forces/T", "pred.max", "meas.max", "median",
              "vs best");
  for (std::size_t i = 0; i < r.fits.size(); ++i) {
    const MethodFit& fit = r.fits[i];
    const AccuracyChoice& c = r.per_method[i];
    std::string pts;
    for (std::size_t k = 0; k < fit.points.size(); ++k) pts += (k ? " " : "") + num(fit.points[k].max);
    if (fit.prefiltered) pts += " -";
    if (c.meets) {
      char ratio[32];
      std::snprintf(ratio, sizeof ratio, "%.2fx", r.found ? c.forces_per_t / r.best.forces_per_t : 0.0);
      std::printf("%-13s %5d %6d  %-24s  %-10s %9.0f  %-9s %-9s %-9s  %s\n", fit.method.c_str(), fit.order,
                  fit.stages, pts.c_str(), step_str(c.step).c_str(), c.forces_per_t,
                  num(c.predicted_max).c_str(), num(c.measured_max).c_str(),
                  num(c.measured_max >= 0 ? c.measured_median : c.predicted_median).c_str(), ratio);
    } else {
      std::printf("%-13s %5d %6d  %-24s  (%s)\n", fit.method.c_str(), fit.order, fit.stages, pts.c_str(),
                  c.note.c_str());
    }
  }
  int skipped = 0;
  for (const MethodFit& fit : r.fits) skipped += fit.prefiltered ? 1 : 0;
  if (skipped > 0)
    std::cout << "pre-filter   h0/4 not run for " << skipped << " of " << r.fits.size()
              << " methods: even at their highest order they cost more than the best prediction"
                 " (--no-prefilter runs it)\n";
  std::cout << "\n";
  if (!r.found) {
    std::cout << "no choice    " << r.why_not << "\n";
    return 0;
  }
  const AccuracyChoice& b = r.best;
  std::cout << "cheapest     " << b.method << ", h = " << step_str(b.step) << ": pilot max |dE| "
            << num(b.measured_max) << " (predicted " << num(b.predicted_max) << "), median "
            << num(b.measured_median) << "; " << short_number(b.forces_per_t)
            << " force evaluations per trajectory per T\n";
  if (r.as_written_measured && r.as_written.forces_per_t > 0) {
    const AccuracyChoice& a = r.as_written;
    // one generic stepper: the time per force evaluation is the same for every method
    const double ratio = b.forces_per_t / a.forces_per_t;
    std::cout << "             the scene with it: " << short_number(r.scene_force_evaluations * ratio)
              << " force evaluations, about " << seconds_str(r.scene_seconds * ratio) << " on " << r.device
              << "\n";
    std::cout << "as written   " << a.method << " at h = " << step_str(a.step) << " "
              << (a.meets ? "meets" : "misses") << " the target (pilot max |dE| " << num(a.measured_max)
              << ")";
    if (a.meets)
      std::cout << " at " << short_number(a.forces_per_t / b.forces_per_t) << "x the cost of the cheapest";
    std::cout << "\n";
    for (const AccuracyChoice& c : r.per_method)
      if (c.method == a.method && c.meets && c.method != b.method)
        std::cout << "             " << c.method << " meets it at h = " << step_str(c.step) << ", "
                  << short_number(c.forces_per_t / b.forces_per_t) << "x the cost of the cheapest\n";
  }
  std::cout << "use          --set integrator.method=" << b.method << " --set integrator.step=" << step_value(b.step)
            << "\n             or integrator.step = \"auto\" with integrator.tolerance = " << target << "\n";
  return 0;
}

}  // namespace

void add_accuracy_command(CLI::App& app, Action& action) {
  auto flags = std::make_shared<AccuracyFlags>();
  auto* c = app.add_subcommand(
      "accuracy", "Pilot ensemble: energy error and cost of a scene, and the cheapest method and step for a target");
  add_scene_options(c, flags->scene);
  c->add_option("--target,-t", flags->target, "Target max |dE| over the ensemble (default: integrator.tolerance)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            double v = 0;
            try {
              std::size_t used = 0;
              v = std::stod(text, &used);
              if (used != text.size()) return "--target: " + text + " is not a number";
            } catch (const std::exception&) {
              return "--target: " + text + " is not a number";
            }
            if (!(v > 0 && v < 1)) return "--target must be a number greater than 0 and less than 1, got " + text;
            return "";
          },
          "in (0, 1)"));
  c->add_option("--safety", flags->safety, "The pilot's max |dE| times this must meet the target (default 4)")
      ->check(CLI::Range(1.0, 1000.0));
  c->add_option("--pilot", flags->pilot, "Trajectories in the pilot ensemble (default 512)")
      ->check(CLI::Range(1, 100000000));
  c->add_option("--pilot-duration", flags->pilot_duration, "Pilot duration in T (default 5)")
      ->check(CLI::PositiveNumber);
  std::vector<std::string> names;
  for (const auto& m : methods()) names.push_back(m.name);
  c->add_option("--methods", flags->methods, "Only these methods, comma-separated (default: all)")
      ->delimiter(',')
      ->check(CLI::IsMember(names));
  c->add_flag("--no-prefilter", flags->no_prefilter,
              "Run every method at h0/4 too (by default methods that cannot be the cheapest stop at h0/2)");
  c->callback([&action, flags] { action = [flags] { return run_accuracy(*flags); }; });
}

}  // namespace arnoldweb::cli
