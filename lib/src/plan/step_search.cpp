// arnoldweb: the step search (step_search.hpp, docs/accuracy.md).
//
// The pilot: the first trajectories of the scene's own ensemble, over a few T,
// |dE| sampled like the scene (at most every 1 T). Every method runs at the
// largest step the step guard advises (h k |p|max <= pi/2) that divides the
// schedule, and at 1/2 and 1/4 of it. Between pilot steps the error is
// interpolated log-linearly; below them it is extrapolated with the slope of
// the last two converging points, never steeper than the nominal order; where
// the error stops falling, round-off has been reached and the error is held at
// that floor (a pre-filter skips the last step of methods that cannot be the
// cheapest even in their best case). The cheapest (stages / step) method and step whose predicted
// pilot max|dE| times the safety factor is within the tolerance is then run on
// the pilot ensemble; if it misses, the measurement joins the fit and the
// search repeats.
#include "plan/step_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "physics/model_descriptor.hpp"
#include "plan/checks.hpp"
#include "plan/plan_params.hpp"

namespace arnoldweb {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMaxVerifications = 6;

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

using detail::exact_ratio;
using detail::fail_at;

// The interval every step must divide: the energy sample interval, or the
// averaging window when energy is not tracked.
double step_unit(const Scene& s) {
  const bool energy = s.energy_error || s.max_energy_error.has_value();
  return energy ? s.energy_every : s.average;
}

// Largest step (in T) with h omega <= pi/2 (the guard's advice; omega: largest_frequency).
double advised_step(double omega) {
  const StepGuard g = step_guard_at(omega, 1.0, 1.0, 1.0);
  return g.advised / g.value;
}

// The pilot's scene of a method at a step: the scene's first n trajectories
// over `duration`, |dE| every `every`, and nothing else observed (no map,
// states, indicators or analyses: the energy error is all it measures).
Scene pilot_scene(const Scene& s, const std::string& method, double step, std::uint64_t n,
                  double duration, double every) {
  Scene p = s;
  p.step_auto = false;
  p.method = method;
  p.step = step;
  p.allow_unsafe_step = true;
  p.trajectories = n;
  p.chunk = 0;
  p.average = duration;
  p.duration = duration;
  p.velocity_map = false;
  p.energy_error = true;
  p.energy_every = every;
  p.max_energy_error.reset();
  p.initial_states = false;
  p.final_states = false;
  p.zoom = false;
  p.confine = false;
  p.frame_times.clear();
  p.switches.clear();  // the output table's switches and table keys: every output off
  p.output_values.clear();
  p.slice = 0;
  p.panels.clear();
  return p;
}

// The pilot's inputs: the scene's, with only the first n of its given states.
PlanInputs pilot_inputs(const Scene& s, const PlanInputs& in, std::uint64_t n) {
  PlanInputs p = in;
  const std::shared_ptr<const StateSet> all = in.states_for(s);
  if (s.initial != "file" || !all || all->count <= n) return p;
  auto first = std::make_shared<StateSet>(*all);
  first->count = n;
  for (auto* v : {&first->position_turns, &first->momentum}) v->resize(3 * n);
  first->winding.resize(3 * n);
  first->status.resize(n);
  if (!first->energy.empty()) first->energy.resize(n);
  if (s.initial_file.empty()) p.given_states = first;
  else p.state_files[s.initial_file] = first;
  return p;
}

// Every measurement of a method, by decreasing step.
std::vector<PilotPoint> merged(const MethodFit& f) {
  std::vector<PilotPoint> all = f.points;
  all.insert(all.end(), f.checks.begin(), f.checks.end());
  std::sort(all.begin(), all.end(), [](const PilotPoint& a, const PilotPoint& b) { return a.step > b.step; });
  return all;
}

// Steps closer than this ratio are not compared for convergence (noise).
constexpr double kMinRatio = 1.4;

// Log-linear model of one series (max or median) over decreasing steps.
double predict(const std::vector<PilotPoint>& pts, double PilotPoint::*value, int nominal, double step) {
  // the converging prefix: every point at least a factor 2^(1 x ratio) below
  // the previous one (local order >= 1); what follows is round-off
  std::vector<std::pair<double, double>> c;  // (log h, log e)
  double floor = 0;
  for (const PilotPoint& p : pts) {
    const double e = p.*value;
    if (!(e > 0) || !std::isfinite(e)) continue;  // lost trajectories: no information
    if (floor > 0) {
      floor = std::max(floor, e);
      continue;
    }
    // compare with the last converging point at least kMinRatio larger
    std::size_t j = c.size();
    while (j > 0 && c[j - 1].first - std::log(p.step) < std::log(kMinRatio)) --j;
    if (j > 0) {
      const double q = (c[j - 1].second - std::log(e)) / (c[j - 1].first - std::log(p.step));
      if (!(q >= 1.0)) {
        floor = e;
        continue;
      }
    }
    c.emplace_back(std::log(p.step), std::log(e));
  }
  if (c.empty()) return floor > 0 ? floor : kInf;
  const double x = std::log(step);
  double y;
  if (c.size() == 1) {
    y = c[0].second + nominal * (x - c[0].first);
  } else if (x >= c.front().first) {  // above the pilot range: the first pair's slope
    const double q = (c[0].second - c[1].second) / (c[0].first - c[1].first);
    y = c[0].second + q * (x - c[0].first);
  } else if (x <= c.back().first) {  // below: the last pair's slope, at most nominal
    const std::size_t n = c.size();
    const double q = (c[n - 2].second - c[n - 1].second) / (c[n - 2].first - c[n - 1].first);
    y = c.back().second + std::min(q, static_cast<double>(nominal)) * (x - c.back().first);
  } else {
    std::size_t i = 1;
    while (c[i].first > x) ++i;
    const double t = (x - c[i - 1].first) / (c[i].first - c[i - 1].first);
    y = c[i - 1].second + t * (c[i].second - c[i - 1].second);
  }
  return std::max(std::exp(y), floor);
}

// Order of the last two converging points, and the round-off floor.
void describe(MethodFit& f) {
  f.order_fit = 0;
  f.floor = 0;
  std::vector<std::pair<double, double>> c;  // converging (log h, log e)
  for (const PilotPoint& p : merged(f)) {
    if (!(p.max > 0) || !std::isfinite(p.max)) continue;
    if (f.floor > 0) {
      f.floor = std::max(f.floor, p.max);
      continue;
    }
    std::size_t j = c.size();
    while (j > 0 && c[j - 1].first - std::log(p.step) < std::log(kMinRatio)) --j;
    if (j > 0) {
      const double q = (c[j - 1].second - std::log(p.max)) / (c[j - 1].first - std::log(p.step));
      if (!(q >= 1.0)) {
        f.floor = p.max;
        continue;
      }
      f.order_fit = q;
    }
    c.emplace_back(std::log(p.step), std::log(p.max));
  }
}

void add_check(MethodFit& f, const PilotPoint& p) {
  f.checks.push_back(p);
  describe(f);
}

class Pilot {
 public:
  Pilot(const Scene& scene, const PlanInputs& inputs, const detail::PilotMeasure& measure, std::uint64_t n,
        double duration, double every)
      : scene_(scene), inputs_(pilot_inputs(scene, inputs, n)), measure_(measure), n_(n), duration_(duration),
        every_(every) {}

  PilotPoint measure(const std::string& method, double step) {
    const detail::PilotRun r = measure_(plan_at(method, step));
    PilotPoint p;
    p.step = step;
    p.max = r.max;
    p.median = r.median;
    return p;
  }

  // trajectory-steps per second of a kernel like the scene's (compiled by
  // then), on an ensemble grown until the run takes a quarter of a second
  double rate(const std::string& method, double step, std::uint64_t n, std::uint64_t most) {
    double rate = 0;
    for (int i = 0; i < 8; ++i) {
      const detail::PilotRun r = measure_(with_trajectories(plan_at(method, step), n));
      rate = r.rate;
      if (r.wall_seconds >= 0.25 || n >= most) break;
      n = std::min(most, n * 4);
    }
    return rate;
  }

 private:
  // The pilot's plan of a method at a step: planned once per method, then
  // only its step changes (with_step).
  Plan plan_at(const std::string& method, double step) {
    auto it = planned_.find(method);
    if (it == planned_.end())
      it = planned_.emplace(method, make_plan(pilot_scene(scene_, method, step, n_, duration_, every_), inputs_))
               .first;
    return with_step(it->second, step);
  }

  const Scene& scene_;
  const PlanInputs inputs_;
  const detail::PilotMeasure& measure_;
  std::uint64_t n_;
  double duration_, every_;
  std::map<std::string, Plan> planned_;
};

// The cheapest step of one method meeting `target` (pilot max|dE|), a
// divisor every/n of the pilot sample interval, at most `largest`.
AccuracyChoice cheapest_step(const MethodFit& f, double target, double every, double largest,
                             double omega) {
  AccuracyChoice c;
  c.method = f.method;
  c.stages = f.stages;
  if (f.floor > 0 && f.floor > target) {
    c.note = "round-off floor ~" + fmt(f.floor);
    return c;
  }
  auto pm = [&](double h) { return f.predict_max(h); };
  double h;
  if (pm(largest) <= target) {
    h = largest;
  } else {
    double lo = largest * 1e-6, hi = largest;
    if (pm(lo) > target) {
      c.note = "needs a step below " + fmt(lo) + " T";
      return c;
    }
    for (int i = 0; i < 100; ++i) {
      const double mid = std::sqrt(lo * hi);
      (pm(mid) <= target ? lo : hi) = mid;
    }
    h = lo;
  }
  std::int64_t n = static_cast<std::int64_t>(std::ceil(every / h - 1e-9));
  n = std::max<std::int64_t>(n, 1);
  while (pm(every / static_cast<double>(n)) > target && n < (1 << 30)) ++n;
  c.step = every / static_cast<double>(n);
  c.predicted_max = pm(c.step);
  c.predicted_median = f.predict_median(c.step);
  c.forces_per_t = f.work / c.step;
  c.guard_value = step_guard_at(omega, c.step, every, every).value;
  c.meets = true;
  return c;
}

// The pre-filter's best case for one method: force evaluations per T if its error fell
// from its smallest measured step as h^(top_order + 2) (faster than any term of the
// method; 0 where the pilot gives no finite error to start from).
double optimistic_forces(const MethodFit& f, double target, double largest) {
  const PilotPoint& p = f.points.back();
  if (!(p.max > 0) || !std::isfinite(p.max)) return 0;
  double h = p.max <= target ? largest : p.step * std::pow(target / p.max, 1.0 / (f.top_order + 2));
  h = std::min(h, largest);
  return f.work / h;
}

}  // namespace

double MethodFit::predict_max(double step) const { return predict(merged(*this), &PilotPoint::max, order, step); }
double MethodFit::predict_median(double step) const {
  return predict(merged(*this), &PilotPoint::median, order, step);
}

namespace {

// What the phases of the search share: the options, the pilot, its sample
// interval and ladder (h0 = every / n0, the guard's largest step), the target.
struct Search {
  const PilotOptions& o;
  Pilot& pilot;
  double target, every, largest, omega;
  std::int64_t n0;
  double ladder_step(int k) const { return every / static_cast<double>(n0 << k); }
};

// Every method (of o.methods) at h0 and h0/2, and h0/4 ... unless the pre-filter measures those later.
void measure_ladders(const Search& s, AccuracyReport& rep) {
  const int first = s.o.prefilter ? std::min(s.o.steps_per_method, 2) : s.o.steps_per_method;
  for (const Method& m : methods()) {
    if (!s.o.methods.empty() && std::find(s.o.methods.begin(), s.o.methods.end(), m.name) == s.o.methods.end())
      continue;
    MethodFit f;
    f.method = m.name;
    f.order = m.order;
    f.stages = m.stages;
    f.work = m.work();
    f.top_order = m.eps_orders.empty() ? m.order : *std::max_element(m.eps_orders.begin(), m.eps_orders.end());
    for (int k = 0; k < first; ++k) f.points.push_back(s.pilot.measure(m.name, s.ladder_step(k)));
    describe(f);
    rep.fits.push_back(f);
  }
}

// The pre-filter: the rest of the ladder only for the methods that could still be the cheapest.
void measure_past_prefilter(const Search& s, AccuracyReport& rep) {
  if (!s.o.prefilter || s.o.steps_per_method <= 2) return;
  double best = kInf;  // the cheapest conservative prediction after two steps
  for (const MethodFit& f : rep.fits) {
    const AccuracyChoice c = cheapest_step(f, s.target, s.every, s.largest, s.omega);
    if (c.meets) best = std::min(best, c.forces_per_t);
  }
  for (MethodFit& f : rep.fits) {
    f.optimistic_forces_per_t = optimistic_forces(f, s.target, s.largest);
    if (f.optimistic_forces_per_t > best) {
      f.prefiltered = true;
      continue;
    }
    for (int k = 2; k < s.o.steps_per_method; ++k) f.points.push_back(s.pilot.measure(f.method, s.ladder_step(k)));
    describe(f);
  }
}

// The scene's own method and step on the pilot, its predictions, and the rate of its kernel.
void measure_as_written(const Search& s, const Plan& wp, double unit, std::uint64_t preferred_chunk,
                        AccuracyReport& rep) {
  const Scene& scene = wp.scene;
  AccuracyChoice& a = rep.as_written;
  const Method& m = wp.method;
  a.method = m.name;
  a.stages = m.stages;
  a.step = scene.step;
  const PilotPoint p = s.pilot.measure(m.name, scene.step);
  a.measured_max = p.max;
  a.measured_median = p.median;
  for (const MethodFit& f : rep.fits)
    if (f.method == m.name) {
      a.predicted_max = f.predict_max(scene.step);
      a.predicted_median = f.predict_median(scene.step);
    }
  a.forces_per_t = m.work() / scene.step;
  a.guard_value = step_guard_at(s.omega, scene.step, unit, unit).value;
  a.meets = p.max <= s.target;
  if (!a.meets) a.note = "pilot max " + fmt(p.max) + " > " + fmt(s.target);
  rep.as_written_measured = true;
  // given states: the rate on the pilot's own (it carries no more)
  const std::uint64_t total = scene.trajectories;
  const std::uint64_t most = scene.initial == "file" ? rep.pilot_trajectories : total;
  const std::uint64_t nt = std::min<std::uint64_t>(most, std::max<std::uint64_t>(rep.pilot_trajectories, preferred_chunk));
  rep.rate = s.pilot.rate(m.name, scene.step, nt, most);
  rep.scene_seconds = rep.rate > 0 ? rep.scene_trajectory_steps / rep.rate : 0;
}

// The cheapest choice of every method; the cheapest of all run on the pilot until one is confirmed
// (a miss joins its method's fit), at most kMaxVerifications times.
void choose(const Search& s, AccuracyReport& rep) {
  for (int attempt = 0;; ++attempt) {
    rep.per_method.clear();
    for (const MethodFit& f : rep.fits)
      rep.per_method.push_back(cheapest_step(f, s.target, s.every, s.largest, s.omega));
    const AccuracyChoice* best = nullptr;
    for (const AccuracyChoice& c : rep.per_method)
      if (c.meets && (!best || c.forces_per_t < best->forces_per_t)) best = &c;
    if (!best) return;
    if (!s.o.verify) {
      rep.found = true;
      rep.best = *best;
      return;
    }
    if (attempt >= kMaxVerifications) {
      rep.why_not = "the pilot did not confirm a prediction after " + std::to_string(kMaxVerifications) +
                    " tries (last: " + best->method + " at h = " + fmt(best->step) + " T)";
      return;
    }
    const PilotPoint p = s.pilot.measure(best->method, best->step);
    MethodFit& f = *std::find_if(rep.fits.begin(), rep.fits.end(),
                                 [&](const MethodFit& x) { return x.method == best->method; });
    if (p.max <= s.target) {
      rep.found = true;
      rep.best = *best;
      rep.best.measured_max = p.max;
      rep.best.measured_median = p.median;
      add_check(f, p);
      return;
    }
    add_check(f, p);  // the fit learns from the miss; search again
  }
}

// The measured values of the per-method rows that were run.
void fill_measured(AccuracyReport& rep) {
  for (AccuracyChoice& c : rep.per_method)
    for (const MethodFit& f : rep.fits)
      if (f.method == c.method && c.meets)
        for (const PilotPoint& p : merged(f))
          if (std::fabs(p.step - c.step) <= 1e-12 * c.step) {
            c.measured_max = p.max;
            c.measured_median = p.median;
          }
}

}  // namespace

namespace detail {

AccuracyReport search_step(const Scene& scene, const PlanInputs& inputs, double tolerance, const PilotOptions& o,
                           std::uint64_t preferred_chunk, const PilotMeasure& measure) {
  AccuracyReport rep;
  rep.tolerance = tolerance;
  rep.safety = o.safety;
  const double target = tolerance / o.safety;
  const std::string precision = to_string(scene.precision);  // for the messages
  // ---- the scene as written, validated (the guard does not stop a report)
  const bool concrete = !scene.step_auto;
  const double unit = step_unit(scene);
  Scene written = scene;
  written.allow_unsafe_step = true;
  if (!concrete) {  // any step that divides the schedule, to check the rest
    written.step_auto = false;
    written.step = unit / std::ceil(unit / 0.01 - 1e-9);
  }
  const Plan wp = make_plan(written, inputs);
  rep.scene_trajectory_steps = wp.trajectory_steps;
  rep.scene_force_evaluations = wp.force_evaluations;

  // Round-off bounds the energy error from below: a target under a few dozen
  // ulps of the energy scale (|E| and the model's largest |V|) cannot be met,
  // whatever the pilot would try (which would take minutes to find out).
  const auto v = wp.model->v_range(detail::params(wp).reals);
  const double eps = scene.precision == Precision::Float ? 5.96e-8 : 1.11e-16;
  const double floor = 32 * eps * (std::fabs(scene.energy) + std::max(std::fabs(v[0]), std::fabs(v[1])));
  if (target < floor)
    fail_at(scene, "integrator.tolerance",
         "max|dE| <= " + fmt(tolerance) + " (" + fmt(target) + " on the pilot with safety " + fmt(o.safety) +
             ") is below what " + precision + " precision can reach at E = " + fmt(scene.energy) +
             " (round-off: about " + fmt(floor) + "); choose a tolerance of at least " + fmt(floor * o.safety) +
             (scene.precision == Precision::Float ? " or integrator.precision = \"double\"" : ""));

  // ---- pilot schedule: |dE| every <= 1 T, a divisor of the scene's unit
  // (and a multiple of the scene's step, so that it can be measured as written)
  std::int64_t parts = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(unit - 1e-9)));
  for (; parts > 1; --parts)
    if (!concrete || exact_ratio(unit / static_cast<double>(parts), scene.step) > 0) break;
  const double every = unit / static_cast<double>(parts);
  const double horizon = std::min(o.duration, scene.duration);
  const double duration = every * std::max(1.0, std::round(horizon / every));
  const std::uint64_t total = wp.scene.trajectories;  // as planned: a state file's count, a grid's points
  const std::uint64_t n = std::max<std::uint64_t>(1, std::min(o.trajectories, total));
  rep.pilot_trajectories = n;
  rep.pilot_duration = duration;
  rep.pilot_every = every;
  Pilot pilot(scene, inputs, measure, n, duration, every);

  // ---- the methods: steps h0, h0/2, h0/4 below the guard's advice
  const double omega = wp.guard.omega;
  const std::int64_t n0 =
      std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(every / advised_step(omega) - 1e-9)));
  const Search s{o, pilot, target, every, every / static_cast<double>(n0), omega, n0};
  measure_ladders(s, rep);
  measure_past_prefilter(s, rep);
  if (rep.fits.empty())
    fail_at(scene, "integrator.method", "no method to consider (known: " + method_names() + ")");
  if (concrete) measure_as_written(s, wp, unit, preferred_chunk, rep);

  // ---- the cheapest choice, checked on the pilot ensemble
  choose(s, rep);
  if (!rep.found && rep.why_not.empty()) {
    double lowest = kInf;
    for (const MethodFit& f : rep.fits)
      for (const PilotPoint& p : merged(f)) lowest = std::min(lowest, p.max);
    rep.why_not = "no method reaches max|dE| <= " + fmt(tolerance) + " / " + fmt(o.safety) + " = " +
                  fmt(target) + " on the pilot in " + precision +
                  " precision (smallest pilot error " + fmt(lowest) + "; round-off limits it" +
                  (scene.precision == Precision::Float ? ": use integrator.precision = \"double\"" : "") +
                  "); choose a larger integrator.tolerance";
  }
  fill_measured(rep);
  return rep;
}

}  // namespace detail


}  // namespace arnoldweb
