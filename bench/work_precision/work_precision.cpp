// arnoldweb_work_precision: what each digit of accuracy costs (issue 4).
//
// For every energy x device x precision x math x method, a ladder of steps
// h = T/n (n = 24, 36, 48, 72, 100, 140, 200, ... : ratio ~sqrt 2, the
// paper's T/100 included) runs two ensembles of the same trajectories:
//   energy run:     D_E (5 T), |dE| sampled every 1/4 T: max and median over
//                   the ensemble of max_t |dE|, and the run's wall and CPU time;
//   trajectory run: D_X (1 T, Lyapunov-safe at E = 15: round-off amplified at
//                   most ~10x), final state against a reference computed in
//                   long double (64-bit mantissa) with Kahan-Li s15odr8 at a
//                   tiny step, whose own error is printed.
// A ladder stops below 1e-11, where the error stops falling (round-off), or
// beyond a cost cap. At E = 400 only steps the guard accepts (h k |p|max < pi)
// run, plus the paper's own point (Yoshida-6A, h = T/100) marked unsafe.
// Boost.Odeint's symplectic_rkn_sb3a_mclachlan runs the same initial states on
// the same CPU (OpenMP over trajectories, glibc sin/cos) as a peer curve.
// Cost: core-seconds (CPU time of all threads) per force evaluation, measured
// once per kernel (device, precision, math, method) as the least of three runs,
// times force evaluations; the machine is shared, and other programs' load
// changes wall times far more than core-seconds. Wall and CPU seconds of every
// run are in the CSV too.
//
// Output: CSV (one row per point) on --csv FILE (default stdout); progress on
// stderr. bench/work_precision/plot.py draws it and prints the tables of
// docs/accuracy.md.
#include <omp.h>

#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "arnoldweb/arnoldweb.hpp"

using namespace arnoldweb;

namespace {

constexpr long double kTwoPiL = 6.283185307179586476925286766559005768L;

// CPU time of this process, all threads (core-seconds). The machine is shared:
// another program's load slows a run's wall time, not the core-seconds it uses.
double cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <class F>
double cpu_time_of(F&& f) {
  const double t0 = cpu_seconds();
  f();
  return cpu_seconds() - t0;
}

struct Options {
  std::vector<double> energies = {15, 400};
  std::vector<std::string> devices = {"cpu", "opencl:0"};
  std::vector<std::string> precisions = {"double", "float"};
  std::vector<std::string> maths = {"portable", "native"};
  std::vector<std::string> methods;  // empty: all
  std::uint64_t trajectories = 256;
  double energy_horizon = 5;   // T
  double energy_every = 0.25;  // T
  double traj_horizon = 1;     // T
  double min_error = 1e-11;    // stop a ladder below this max|dE|
  double max_forces_per_t = 30000;
  double calibration_seconds = 0.1;
  bool odeint = true;
  bool horizon_check = false;
  std::string csv;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

// The step ladder: n = 4 round(6.25 2^(k/2)), steps per T (multiples of 4, so
// that they divide the 1/4 T energy samples).
std::vector<int> ladder() {
  std::vector<int> n;
  for (int k = 0; k < 30; ++k) n.push_back(4 * static_cast<int>(std::nearbyint(6.25 * std::pow(2.0, k / 2.0))));
  return n;
}

// ----------------------------------------------------------------- reference
// H = |p|^2/2 + 2 cos x cos y cos^2 z in long double, Kahan-Li s15odr8.
struct StateL {
  long double x[3], p[3];
};

void force_l(const long double x[3], long double f[3]) {
  long double s[3], c[3];
  for (int i = 0; i < 3; ++i) sincosl(x[i], &s[i], &c[i]);
  f[0] = 2 * s[0] * c[1] * c[2] * c[2];
  f[1] = 2 * c[0] * s[1] * c[2] * c[2];
  f[2] = 4 * c[0] * c[1] * s[2] * c[2];
}

std::vector<long double> s15_weights() {
  const long double half[7] = {0.74167036435061295345L, -0.40910082580003159400L, 0.19075471029623837995L,
                               -0.57386247111608226666L, 0.29906418130365592384L, 0.33462491824529818378L,
                               0.31529309239676659663L};
  std::vector<long double> w(half, half + 7);
  w.push_back(-0.79688793935291635402L);
  for (int i = 6; i >= 0; --i) w.push_back(half[i]);
  return w;
}

StateL integrate_l(StateL s, long double t, long long steps) {
  static const std::vector<long double> w = s15_weights();
  const long double h = t / steps;
  long double f[3];
  force_l(s.x, f);
  for (long long n = 0; n < steps; ++n)
    for (long double wi : w) {
      for (int i = 0; i < 3; ++i) s.p[i] += 0.5L * wi * h * f[i];
      for (int i = 0; i < 3; ++i) s.x[i] += wi * h * s.p[i];
      force_l(s.x, f);
      for (int i = 0; i < 3; ++i) s.p[i] += 0.5L * wi * h * f[i];
    }
  return s;
}

long double energy_l(const long double x[3], const long double p[3]) {
  const long double c0 = cosl(x[0]), c1 = cosl(x[1]), c2 = cosl(x[2]);
  return 0.5L * (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) + 2 * c0 * c1 * c2 * c2;
}

double distance(const StateL& a, const StateL& b) {
  long double d2 = 0;
  for (int i = 0; i < 3; ++i) d2 += (a.x[i] - b.x[i]) * (a.x[i] - b.x[i]) + (a.p[i] - b.p[i]) * (a.p[i] - b.p[i]);
  return static_cast<double>(sqrtl(d2));
}

struct Reference {
  std::vector<StateL> initial, final;
  long long steps = 0;
  double self_error = 0;  // max distance between the reference at n and n/2 steps
};

Reference make_reference(const std::vector<double>& initial_r, double horizon_t, double energy) {
  Reference ref;
  const std::size_t n = initial_r.size() / 6;
  ref.initial.resize(n);
  ref.final.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      ref.initial[i].x[c] = kTwoPiL * initial_r[6 * i + c];
      ref.initial[i].p[c] = initial_r[6 * i + 3 + c];
    }
  // s15 at h |p|max ~ 0.02: error ~1e-18, far below the double results
  const double pmax = std::sqrt(2 * (energy + 2));
  ref.steps = static_cast<long long>(std::ceil(horizon_t * 2 * M_PI * pmax / 0.02 / 2)) * 2;
  std::vector<double> self(n, 0.0);
#pragma omp parallel for schedule(dynamic, 4)
  for (std::size_t i = 0; i < n; ++i) {
    ref.final[i] = integrate_l(ref.initial[i], kTwoPiL * horizon_t, ref.steps);
    self[i] = distance(ref.final[i], integrate_l(ref.initial[i], kTwoPiL * horizon_t, ref.steps / 2));
  }
  ref.self_error = *std::max_element(self.begin(), self.end());
  return ref;
}

// ----------------------------------------------------------------- statistics
double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

struct Row {
  double energy = 0;
  std::string device, precision, math, method;
  int order = 0, stages = 0, n_per_t = 0;
  double step = 0, guard = 0;
  bool unsafe = false;
  std::uint64_t trajectories = 0;
  double max_de = 0, median_de = 0, mean_de = 0;  // max_t |dE| over the ensemble
  double traj_max = 0, traj_median = 0, traj_rms = 0;
  double seconds = 0;      // energy run, wall
  double cpu_seconds = 0;  // energy run, core-seconds
  double traj_steps = 0;
  double s_per_force = 0;  // calibrated core-seconds per force evaluation (per trajectory)
  std::uint64_t lost = 0;
};

void write_header(FILE* f) {
  std::fprintf(f,
               "energy,device,precision,math,method,order,forces_per_step,step_T,steps_per_T,guard_hkp,unsafe,"
               "trajectories,energy_horizon_T,energy_every_T,traj_horizon_T,max_dE,median_dE,mean_dE,"
               "traj_err_max,traj_err_median,traj_err_rms,seconds,cpu_seconds,traj_steps_per_s,force_evals_per_s,"
               "s_per_traj_per_T,s_per_force_eval,cost_s_per_traj_per_T,lost\n");
}

void write_row(FILE* f, const Row& r, const Options& o) {
  const double sps = r.seconds > 0 ? r.traj_steps / r.seconds : 0;
  std::fprintf(f, "%g,%s,%s,%s,%s,%d,%d,%.10g,%d,%.4f,%d,%llu,%g,%g,%g,%.4e,%.4e,%.4e,%.4e,%.4e,%.4e,%.5g,%.5g,%.5g,%.5g,%.5g,%.5g,%.5g,%llu\n",
               r.energy, r.device.c_str(), r.precision.c_str(), r.math.c_str(), r.method.c_str(), r.order,
               r.stages, r.step, r.n_per_t, r.guard, r.unsafe ? 1 : 0,
               static_cast<unsigned long long>(r.trajectories), o.energy_horizon, o.energy_every, o.traj_horizon,
               r.max_de, r.median_de, r.mean_de, r.traj_max, r.traj_median, r.traj_rms, r.seconds, r.cpu_seconds, sps,
               sps * r.stages, r.seconds / (static_cast<double>(r.trajectories) * o.energy_horizon),
               r.s_per_force, r.s_per_force * r.stages * r.n_per_t, static_cast<unsigned long long>(r.lost));
  std::fflush(f);
}

// ------------------------------------------------------------- library runs
Scene base_scene(double energy, std::uint64_t n, const std::string& precision, const std::string& math) {
  Scene s;
  s.file = "<work_precision>";
  s.energy = energy;
  s.trajectories = n;
  s.seed = 20261121;
  s.velocity_map = false;
  s.energy_error = false;
  s.precision = precision == "float" ? Precision::Float : Precision::Double;
  s.math = math == "native" ? MathMode::Native : MathMode::Portable;
  s.allow_unsafe_step = true;  // the ladder decides what runs
  return s;
}

std::vector<double> initial_states(double energy, std::uint64_t n, const std::string& precision) {
  Scene s = base_scene(energy, n, precision, "portable");
  s.method = "leapfrog";
  s.step = 0.25;
  s.average = s.duration = 0.25;
  s.initial_states = true;
  auto cpu = open_backend("cpu");
  return run(make_plan(s), *cpu).reals("initial_states");
}

void trajectory_errors(const Result& r, const Reference& ref, Row& row) {
  std::vector<double> d;
  double sum = 0;
  for (std::size_t i = 0; i < ref.final.size(); ++i) {
    if (r.ints("final_states")[4 * i + 3] != 0) continue;
    StateL s;
    for (int c = 0; c < 3; ++c) {
      s.x[c] = kTwoPiL * (static_cast<long double>(r.ints("final_states")[4 * i + c]) + static_cast<long double>(r.reals("final_states")[6 * i + c]));
      s.p[c] = r.reals("final_states")[6 * i + 3 + c];
    }
    d.push_back(distance(s, ref.final[i]));
    sum += d.back() * d.back();
  }
  row.traj_max = d.empty() ? INFINITY : *std::max_element(d.begin(), d.end());
  row.traj_median = median(d);
  row.traj_rms = d.empty() ? INFINITY : std::sqrt(sum / d.size());
}

Row library_point(Backend& b, const Options& o, double energy, const std::string& precision,
                  const std::string& math, const Method& m, int n_per_t, const Reference& ref) {
  Row row;
  row.energy = energy;
  row.device = b.info().id;
  row.precision = precision;
  row.math = math;
  row.method = m.name;
  row.order = m.order;
  row.stages = m.stages;
  row.n_per_t = n_per_t;
  row.step = 1.0 / n_per_t;
  row.trajectories = o.trajectories;

  Scene s = base_scene(energy, o.trajectories, precision, math);
  s.method = m.name;
  s.step = row.step;
  s.average = s.duration = o.energy_horizon;
  s.energy_error = true;
  s.energy_every = o.energy_every;
  const Plan pe = make_plan(s);
  row.guard = pe.guard.value;
  row.unsafe = pe.guard.refused();
  Result re;
  row.cpu_seconds = cpu_time_of([&] { re = run(pe, b); });
  row.max_de = re.energy.max;
  row.median_de = re.energy.quantile(0.5);
  row.mean_de = re.energy.mean;
  row.seconds = re.wall_seconds;
  row.traj_steps = re.trajectory_steps;
  row.lost = re.flagged();
  if (re.flagged_nonfinite) row.max_de = row.median_de = INFINITY;

  s.average = s.duration = o.traj_horizon;
  s.energy_error = false;
  s.final_states = true;
  const Result rx = run(make_plan(s), b);
  trajectory_errors(rx, ref, row);
  return row;
}

// Seconds per force evaluation of one trajectory for a kernel (device,
// precision, math, method): the energy-run kernel at T/100 over 1 T on an
// ensemble grown until a run takes `seconds`, then the least CPU time (all
// threads, core-seconds) of three such runs. One generic stepper: a run's
// cost is this times stages x steps, whatever the step.
double calibrate(Backend& b, const std::string& precision, const std::string& math, const Method& m,
                 double seconds) {
  Scene s = base_scene(15, 1024, precision, math);
  s.method = m.name;
  s.step = 0.01;
  s.average = s.duration = 1;
  s.energy_error = true;
  s.energy_every = 0.25;
  {  // compile (and cache) the kernel first
    Scene w = s;
    w.trajectories = 8;
    run(make_plan(w), b);
  }
  for (int i = 0; i < 12; ++i) {
    const Result r = run(make_plan(s), b);
    if (r.wall_seconds >= seconds || i == 11) break;
    s.trajectories *= std::max(2.0, std::min(16.0, 1.2 * seconds / std::max(r.wall_seconds, 1e-3)));
  }
  double best = INFINITY;
  const Plan plan = make_plan(s);
  for (int k = 0; k < 3; ++k) {
    Result r;
    const double t = cpu_time_of([&] { r = run(plan, b); });
    best = std::min(best, t / (r.trajectory_steps * m.stages));
  }
  return best;
}

// ------------------------------------------------------------- Boost.Odeint
using Vec = std::array<double, 3>;

struct OdeintForce {
  void operator()(const Vec& x, Vec& dpdt) const {
    const double s0 = std::sin(x[0]), c0 = std::cos(x[0]), s1 = std::sin(x[1]), c1 = std::cos(x[1]);
    const double s2 = std::sin(x[2]), c2 = std::cos(x[2]);
    dpdt[0] = 2 * s0 * c1 * c2 * c2;
    dpdt[1] = 2 * c0 * s1 * c2 * c2;
    dpdt[2] = 4 * c0 * c1 * s2 * c2;
  }
};

double energy_d(const Vec& x, const Vec& p) {
  const double c2 = std::cos(x[2]);
  return 0.5 * (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) + 2 * std::cos(x[0]) * std::cos(x[1]) * c2 * c2;
}

Row odeint_point(const Options& o, double energy, int n_per_t, const std::vector<double>& init,
                 const Reference& ref) {
  namespace odeint = boost::numeric::odeint;
  Row row;
  row.energy = energy;
  row.device = "cpu-odeint";
  row.precision = "double";
  row.math = "libm";
  row.method = "odeint-sb3a";
  row.order = 4;
  row.stages = 6;  // odeint evaluates the force at every one of its 6 stages
  row.n_per_t = n_per_t;
  row.step = 1.0 / n_per_t;
  row.trajectories = o.trajectories;
  row.guard = step_guard(energy, row.step, 1, 1).value;
  row.unsafe = step_guard(energy, row.step, 1, 1).refused();
  const std::size_t n = init.size() / 6;
  const double h = 2 * M_PI * row.step;
  const int steps_per_sample = static_cast<int>(std::lround(o.energy_every * n_per_t));
  const int samples = static_cast<int>(std::lround(o.energy_horizon / o.energy_every));
  const int traj_steps = static_cast<int>(std::lround(o.traj_horizon * n_per_t));
  std::vector<double> demax(n), dist(n);

  const auto t0 = std::chrono::steady_clock::now();
  const double c0 = cpu_seconds();
#pragma omp parallel for schedule(dynamic, 8)
  for (std::size_t i = 0; i < n; ++i) {
    odeint::symplectic_rkn_sb3a_mclachlan<Vec> stepper;
    Vec x, p;
    for (int c = 0; c < 3; ++c) {
      x[c] = 2 * M_PI * init[6 * i + c];
      p[c] = init[6 * i + 3 + c];
    }
    const double e0 = energy_d(x, p);
    double m = 0;
    for (int k = 0; k < samples; ++k) {
      for (int j = 0; j < steps_per_sample; ++j) stepper.do_step(OdeintForce(), std::make_pair(std::ref(x), std::ref(p)), 0.0, h);
      m = std::max(m, std::fabs(energy_d(x, p) - e0));
    }
    demax[i] = m;
  }
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  row.cpu_seconds = cpu_seconds() - c0;
  row.traj_steps = static_cast<double>(n) * samples * steps_per_sample;

#pragma omp parallel for schedule(dynamic, 8)
  for (std::size_t i = 0; i < n; ++i) {
    odeint::symplectic_rkn_sb3a_mclachlan<Vec> stepper;
    Vec x, p;
    for (int c = 0; c < 3; ++c) {
      x[c] = 2 * M_PI * init[6 * i + c];
      p[c] = init[6 * i + 3 + c];
    }
    for (int j = 0; j < traj_steps; ++j) stepper.do_step(OdeintForce(), std::make_pair(std::ref(x), std::ref(p)), 0.0, h);
    StateL s;
    for (int c = 0; c < 3; ++c) {
      s.x[c] = x[c];
      s.p[c] = p[c];
    }
    dist[i] = distance(s, ref.final[i]);
  }
  row.max_de = *std::max_element(demax.begin(), demax.end());
  row.median_de = median(demax);
  double sum = 0, mean = 0;
  for (double d : dist) sum += d * d;
  for (double d : demax) mean += d;
  row.mean_de = mean / n;
  row.traj_max = *std::max_element(dist.begin(), dist.end());
  row.traj_median = median(dist);
  row.traj_rms = std::sqrt(sum / n);
  return row;
}

// A ladder of steps for one configuration: from the coarsest the guard
// accepts, finer until the error is small, stops falling, or costs too much.
template <class Point>
void run_ladder(const Options& o, double energy, int stages, Point point, FILE* out, const char* what) {
  const std::vector<int> ns = ladder();
  int falls = 0;
  double prev = INFINITY;
  for (int n : ns) {
    if (step_guard(energy, 1.0 / n, 1, 1).refused()) continue;
    if (static_cast<double>(n) * stages > o.max_forces_per_t) break;
    const Row r = point(n);
    write_row(out, r, o);
    std::fprintf(stderr, "  %-34s T/%-5d max|dE| %.2e  traj %.2e  %.3f s\n", what, n, r.max_de, r.traj_median,
                 r.seconds);
    if (r.max_de < o.min_error) break;
    falls = (r.max_de > prev / 1.3) ? falls + 1 : 0;  // round-off: no longer falling
    if (falls >= 2) break;
    prev = std::min(prev, r.max_de);
  }
}

// How far round-off carries two converged solutions apart: Kahan-Li s15 and
// Yoshida-8D at T/2000 (double, portable, cpu) after 1, 2, 5, 10 T. Where
// they part, trajectory errors measure chaos, not the integrator.
void horizon_check(const Options& o) {
  auto cpu = open_backend("cpu");
  std::printf("# horizon check: distance between kahan-li-s15 and yoshida8d at T/2000 (double, cpu), "
              "%llu trajectories\n", static_cast<unsigned long long>(o.trajectories));
  std::printf("energy,horizon_T,median,p90,max\n");
  for (double energy : o.energies)
    for (double horizon : {1.0, 2.0, 5.0, 10.0}) {
      Result r[2];
      const char* m[2] = {"kahan-li-s15", "yoshida8d"};
      for (int k = 0; k < 2; ++k) {
        Scene s = base_scene(energy, o.trajectories, "double", "portable");
        s.seed = 20261121;
        s.method = m[k];
        s.step = 1.0 / 2000;
        s.average = s.duration = horizon;
        s.final_states = true;
        r[k] = run(make_plan(s), *cpu);
      }
      std::vector<double> d;
      for (std::size_t i = 0; i < o.trajectories; ++i) {
        StateL a, b;
        for (int c = 0; c < 3; ++c) {
          a.x[c] = kTwoPiL * (static_cast<long double>(r[0].ints("final_states")[4 * i + c]) + r[0].reals("final_states")[6 * i + c]);
          b.x[c] = kTwoPiL * (static_cast<long double>(r[1].ints("final_states")[4 * i + c]) + r[1].reals("final_states")[6 * i + c]);
          a.p[c] = r[0].reals("final_states")[6 * i + 3 + c];
          b.p[c] = r[1].reals("final_states")[6 * i + 3 + c];
        }
        d.push_back(distance(a, b));
      }
      std::sort(d.begin(), d.end());
      std::printf("%g,%g,%.2e,%.2e,%.2e\n", energy, horizon, median(d), d[d.size() * 9 / 10], d.back());
    }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (a == "--energies") {
      o.energies.clear();
      for (const auto& e : split(value())) o.energies.push_back(std::stod(e));
    } else if (a == "--devices") o.devices = split(value());
    else if (a == "--precisions") o.precisions = split(value());
    else if (a == "--maths") o.maths = split(value());
    else if (a == "--methods") o.methods = split(value());
    else if (a == "--trajectories") o.trajectories = std::stoull(value());
    else if (a == "--energy-horizon") o.energy_horizon = std::stod(value());
    else if (a == "--traj-horizon") o.traj_horizon = std::stod(value());
    else if (a == "--min-error") o.min_error = std::stod(value());
    else if (a == "--max-forces-per-t") o.max_forces_per_t = std::stod(value());
    else if (a == "--no-odeint") o.odeint = false;
    else if (a == "--horizon-check") o.horizon_check = true;
    else if (a == "--calibration-seconds") o.calibration_seconds = std::stod(value());
    else if (a == "--csv") o.csv = value();
    else {
      std::fprintf(stderr,
                   "usage: %s [--energies 15,400] [--devices cpu,opencl:0] [--precisions double,float]\n"
                   "          [--maths portable,native] [--methods a,b] [--trajectories 256]\n"
                   "          [--energy-horizon 5] [--traj-horizon 1] [--min-error 1e-11]\n"
                   "          [--max-forces-per-t 30000] [--calibration-seconds 0.1] [--no-odeint]\n"
                   "          [--horizon-check] [--csv FILE]\n",
                   argv[0]);
      return 2;
    }
  }
  if (o.horizon_check) {
    horizon_check(o);
    return 0;
  }
  FILE* out = o.csv.empty() ? stdout : std::fopen(o.csv.c_str(), "w");
  if (!out) {
    std::perror(o.csv.c_str());
    return 1;
  }
  const auto t_start = std::chrono::steady_clock::now();
  std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::localtime(&now));
  std::fprintf(out, "# arnoldweb_work_precision %s, %d OpenMP threads;", date, omp_get_max_threads());
  for (int i = 1; i < argc; ++i) std::fprintf(out, " %s", argv[i]);
  std::fprintf(out, "\n");

  std::vector<const Method*> ms;
  for (const Method& m : methods())
    if (o.methods.empty() || std::find(o.methods.begin(), o.methods.end(), m.name) != o.methods.end())
      ms.push_back(&m);

  std::map<std::string, std::unique_ptr<Backend>> backends;
  for (const auto& id : o.devices) {
    backends[id] = open_backend(id);
    const DeviceInfo& d = backends[id]->info();
    std::fprintf(out, "# device %s: %s (%s, %s), %u compute units\n", id.c_str(), d.name.c_str(), d.vendor.c_str(),
                 d.version.c_str(), d.compute_units);
  }

  // cost per force evaluation of every kernel, measured once (it does not
  // depend on the energy or the step)
  std::map<std::string, double> s_per_force;
  auto key = [](const std::string& id, const std::string& p, const std::string& m, const std::string& meth) {
    return id + "/" + p + "/" + m + "/" + meth;
  };
  for (const auto& id : o.devices)
    for (const auto& prec : o.precisions)
      for (const auto& math : o.maths)
        for (const Method* m : ms) {
          const double t = calibrate(*backends[id], prec, math, *m, o.calibration_seconds);
          s_per_force[key(id, prec, math, m->name)] = t;
          std::fprintf(out, "# cost %s %s %s %s: %.4g core-seconds per force evaluation (%.4g force "
                       "evaluations per core-second)\n", id.c_str(), prec.c_str(), math.c_str(), m->name.c_str(), t, 1 / t);
          std::fprintf(stderr, "cost %s %s %s %-13s %.3g force evaluations per core-second\n", id.c_str(), prec.c_str(),
                       math.c_str(), m->name.c_str(), 1 / t);
        }

  bool header = false;
  for (double energy : o.energies) {
    for (const auto& prec : o.precisions) {
      const std::vector<double> init = initial_states(energy, o.trajectories, prec);
      const auto t0 = std::chrono::steady_clock::now();
      const Reference ref = make_reference(init, o.traj_horizon, energy);
      std::fprintf(out, "# reference E = %g, %s initial states: long double Kahan-Li s15odr8, %lld steps over %g T; "
                   "max distance to the same at half the steps %.2e; %.1f s\n",
                   energy, prec.c_str(), ref.steps, o.traj_horizon, ref.self_error,
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      std::fprintf(stderr, "E = %g, %s: reference (%lld steps, self-check %.1e)\n", energy, prec.c_str(), ref.steps,
                   ref.self_error);
      if (!header) {
        write_header(out);
        header = true;
      }
      for (const auto& id : o.devices)
        for (const auto& math : o.maths) {
          Backend& b = *backends[id];
          for (const Method* m : ms) {
            // warm-up: compile (and cache) this kernel before anything is timed
            {
              Scene w = base_scene(energy, 8, prec, math);
              w.method = m->name;
              w.step = 0.25;
              w.average = w.duration = 0.25;
              w.energy_error = true;
              w.energy_every = 0.25;
              run(make_plan(w), b);
              w.energy_error = false;
              w.final_states = true;
              run(make_plan(w), b);
            }
            const std::string what = id + " " + prec + " " + math + " " + m->name;
            const double spf = s_per_force[key(id, prec, math, m->name)];
            run_ladder(o, energy, m->stages,
                       [&](int n) {
                         Row r = library_point(b, o, energy, prec, math, *m, n, ref);
                         r.s_per_force = spf;
                         return r;
                       },
                       out, what.c_str());
            if (m->name == "yoshida6a" && step_guard(energy, 0.01, 1, 1).refused()) {
              // the paper's own choice, outside the guard: one point, marked unsafe
              Row r = library_point(b, o, energy, prec, math, *m, 100, ref);
              r.s_per_force = spf;
              write_row(out, r, o);
              std::fprintf(stderr, "  %-34s T/100 (unsafe) max|dE| %.2e\n", what.c_str(), r.max_de);
            }
          }
        }
      if (o.odeint && prec == "double") {
        // its cost per force evaluation: the fastest of three T/200 energy runs
        double spf = INFINITY;
        for (int k = 0; k < 3; ++k) {
          const Row cal = odeint_point(o, energy, 200, init, ref);
          spf = std::min(spf, cal.cpu_seconds / (cal.traj_steps * cal.stages));
        }
        std::fprintf(out, "# cost cpu-odeint double libm odeint-sb3a: %.4g core-seconds per force evaluation "
                     "(%.4g force evaluations per core-second)\n", spf, 1 / spf);
        run_ladder(o, energy, 6,
                   [&](int n) {
                     Row r = odeint_point(o, energy, n, init, ref);
                     r.s_per_force = spf;
                     return r;
                   },
                   out, "cpu-odeint double sb3a");
      }
    }
  }
  std::fprintf(out, "# total %.1f s\n",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count());
  if (out != stdout) std::fclose(out);
  return 0;
}
