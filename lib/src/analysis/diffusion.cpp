// arnoldweb: moments of the action displacement and the diffusion coefficient
// (arnoldweb/diffusion.hpp).
#include "arnoldweb/diffusion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace arnoldweb {
namespace {

[[noreturn]] void bad(const std::string& what) { throw std::invalid_argument("diffusion: " + what); }

void check_samples(const ActionSamples& s) {
  if (s.dim == 0) bad("dim is 0");
  if (s.times < 2) bad("need at least 2 sample times, got " + std::to_string(s.times));
  if (s.t.size() != s.times)
    bad("t has " + std::to_string(s.t.size()) + " times, expected " + std::to_string(s.times));
  if (s.actions.size() != s.trajectories * s.times * s.dim)
    bad("actions has " + std::to_string(s.actions.size()) + " values, expected trajectories x times x dim = " +
        std::to_string(s.trajectories) + " x " + std::to_string(s.times) + " x " + std::to_string(s.dim));
  for (std::size_t k = 0; k < s.times; ++k) {
    if (!std::isfinite(s.t[k])) bad("sample time " + std::to_string(k) + " is not finite");
    if (k > 0 && !(s.t[k] > s.t[k - 1]))
      bad("sample times must increase strictly: t[" + std::to_string(k) + "] = " + std::to_string(s.t[k]) +
          " after " + std::to_string(s.t[k - 1]));
  }
}

// `v` normalised; its name in messages.
std::vector<double> unit(const std::vector<double>& v, std::size_t dim, const char* name) {
  if (v.size() != dim) bad(std::string(name) + " has " + std::to_string(v.size()) + " components, expected " +
                           std::to_string(dim));
  double n2 = 0;
  for (double x : v) {
    if (!std::isfinite(x)) bad(std::string(name) + " has a non-finite component");
    n2 += x * x;
  }
  if (!(n2 > 0)) bad(std::string(name) + " is the zero vector");
  std::vector<double> u(v);
  for (double& x : u) x /= std::sqrt(n2);
  return u;
}

// The trajectories whose actions are all finite.
std::vector<std::size_t> finite_trajectories(const ActionSamples& s) {
  std::vector<std::size_t> out;
  const std::size_t per = s.times * s.dim;
  for (std::size_t i = 0; i < s.trajectories; ++i) {
    bool ok = true;
    for (std::size_t j = 0; j < per && ok; ++j) ok = std::isfinite(s.actions[i * per + j]);
    if (ok) out.push_back(i);
  }
  if (out.size() < 2)
    bad("need at least 2 trajectories with finite actions, got " + std::to_string(out.size()) + " of " +
        std::to_string(s.trajectories));
  return out;
}

double action(const ActionSamples& s, std::size_t i, std::size_t k, std::size_t a) {
  return s.actions[(i * s.times + k) * s.dim + a];
}

// e . (I(t_k) - I(t_0)) for the used trajectories: used x times.
std::vector<double> projections(const ActionSamples& s, const std::vector<std::size_t>& used,
                                const std::vector<double>& e) {
  std::vector<double> p(used.size() * s.times);
  for (std::size_t u = 0; u < used.size(); ++u)
    for (std::size_t k = 0; k < s.times; ++k) {
      double x = 0;
      for (std::size_t a = 0; a < s.dim; ++a) x += e[a] * (action(s, used[u], k, a) - action(s, used[u], 0, a));
      p[u * s.times + k] = x;
    }
  return p;
}

// Least-squares slope and intercept of y against t over indices [first, last].
void line_fit(const std::vector<double>& t, const std::vector<double>& y, std::size_t first, std::size_t last,
              double* slope, double* intercept) {
  const double n = static_cast<double>(last - first + 1);
  double mt = 0, my = 0;
  for (std::size_t k = first; k <= last; ++k) {
    mt += t[k];
    my += y[k];
  }
  mt /= n;
  my /= n;
  double stt = 0, sty = 0;
  for (std::size_t k = first; k <= last; ++k) {
    stt += (t[k] - mt) * (t[k] - mt);
    sty += (t[k] - mt) * (y[k] - my);
  }
  *slope = sty / stt;
  if (intercept) *intercept = my - *slope * mt;
}

double slope_of(const std::vector<double>& t, const std::vector<double>& y, std::size_t first, std::size_t last) {
  double s;
  line_fit(t, y, first, last, &s, nullptr);
  return s;
}

// splitmix64 (Steele, Lea & Flood 2014): the same sequence everywhere.
struct SplitMix {
  std::uint64_t x;
  std::uint64_t next() {
    std::uint64_t z = (x += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  // uniform in [0, n) (Lemire's multiply-shift; a bias below n / 2^64)
  std::size_t below(std::size_t n) {
    return static_cast<std::size_t>((static_cast<unsigned __int128>(next()) * n) >> 64);
  }
};

// Var over the ensemble at each time of the centred projections q (used x
// times), each trajectory counted `count` times (sum of counts = used).
std::vector<double> weighted_variance(const std::vector<double>& q, const std::vector<std::uint32_t>& count,
                                      std::size_t used, std::size_t times, std::size_t first, std::size_t last) {
  // trajectory by trajectory (q's rows are contiguous); each time's sums still add the
  // trajectories in order, so the bits are those of a loop over times outside
  std::vector<double> m1(times, 0.0), m2(times, 0.0), var(times, 0.0);
  for (std::size_t u = 0; u < used; ++u) {
    if (!count[u]) continue;
    const double c = count[u];
    const double* row = &q[u * times];
    for (std::size_t k = first; k <= last; ++k) {
      const double x = row[k];
      m1[k] += c * x;
      m2[k] += c * x * x;
    }
  }
  for (std::size_t k = first; k <= last; ++k) {
    const double a = m1[k] / static_cast<double>(used), b = m2[k] / static_cast<double>(used);
    var[k] = b - a * a;
  }
  return var;
}

// The mean of t over [first, last].
double mean_time(const std::vector<double>& t, std::size_t first, std::size_t last) {
  double m = 0;
  for (std::size_t k = first; k <= last; ++k) m += t[k];
  return m / static_cast<double>(last - first + 1);
}

// The two halves of the fitted times [first, mid], [mid, last] and their mean
// times from t0 (DiffusionFit::alpha); none (mid == first) below 3 times.
struct Halves {
  std::size_t first, mid, last;
  double c1, c2;
  Halves(const std::vector<double>& t, std::size_t f, std::size_t l)
      : first(f), mid(f + (l - f) / 2), last(l), c1(mean_time(t, f, mid) - t[0]), c2(mean_time(t, mid, l) - t[0]) {}
  bool split() const { return mid > first && last > mid; }
  // the slopes of the halves of y (the whole range's where there are no halves)
  void slopes(const std::vector<double>& t, const std::vector<double>& y, double whole, double* s1, double* s2) const {
    *s1 = split() ? slope_of(t, y, first, mid) : whole;
    *s2 = split() ? slope_of(t, y, mid, last) : whole;
  }
  double exponent(double s1, double s2) const {
    if (!split() || !(s1 > 0 && s2 > 0) || !(c1 > 0 && c2 > c1)) return std::numeric_limits<double>::quiet_NaN();
    return 1 + std::log(s2 / s1) / std::log(c2 / c1);
  }
};

// The sample standard deviation (0 for fewer than 2 values).
double standard_deviation(const std::vector<double>& v) {
  if (v.size() < 2) return 0;
  double m = 0;
  for (double x : v) m += x;
  m /= static_cast<double>(v.size());
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size() - 1));
}

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const std::size_t i = static_cast<std::size_t>(pos);
  const double f = pos - static_cast<double>(i);
  return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
}

}  // namespace

DiffusionMoments diffusion_moments(const ActionSamples& s, const ResonanceDirections& dirs) {
  check_samples(s);
  const std::vector<double> e = unit(dirs.along, s.dim, "the direction along the resonance");
  std::vector<double> f;
  if (!dirs.across.empty()) {
    f = unit(dirs.across, s.dim, "the direction across the resonance");
    double ef = 0;
    for (std::size_t a = 0; a < s.dim; ++a) ef += e[a] * f[a];
    for (std::size_t a = 0; a < s.dim; ++a) f[a] -= ef * e[a];
    double n2 = 0;
    for (double x : f) n2 += x * x;
    if (!(n2 > 1e-24)) bad("the direction across the resonance is parallel to the one along it");
    for (double& x : f) x /= std::sqrt(n2);
  }
  const std::vector<std::size_t> used = finite_trajectories(s);
  const std::size_t d = s.dim, n = used.size();
  DiffusionMoments m;
  m.dim = d;
  m.used = n;
  m.excluded = s.trajectories - n;
  m.t = s.t;
  m.mean.assign(s.times * d, 0.0);
  m.second.assign(s.times * d * d, 0.0);
  m.covariance.assign(s.times * d * d, 0.0);
  m.along_mean.assign(s.times, 0.0);
  m.along_variance.assign(s.times, 0.0);
  m.along_square.assign(s.times, 0.0);
  m.across_variance.assign(s.times, 0.0);
  std::vector<double> di(d);
  for (std::size_t k = 0; k < s.times; ++k) {
    double* mean = &m.mean[k * d];
    double* second = &m.second[k * d * d];
    for (std::size_t i : used) {
      for (std::size_t a = 0; a < d; ++a) di[a] = action(s, i, k, a) - action(s, i, 0, a);
      for (std::size_t a = 0; a < d; ++a) {
        mean[a] += di[a];
        for (std::size_t b = 0; b < d; ++b) second[a * d + b] += di[a] * di[b];
      }
    }
    for (std::size_t a = 0; a < d; ++a) mean[a] /= static_cast<double>(n);
    for (std::size_t a = 0; a < d * d; ++a) second[a] /= static_cast<double>(n);
    // the covariance from the centred displacements (no cancellation against the mean)
    double* cov = &m.covariance[k * d * d];
    for (std::size_t i : used) {
      for (std::size_t a = 0; a < d; ++a) di[a] = action(s, i, k, a) - action(s, i, 0, a) - mean[a];
      for (std::size_t a = 0; a < d; ++a)
        for (std::size_t b = 0; b < d; ++b) cov[a * d + b] += di[a] * di[b];
    }
    for (std::size_t a = 0; a < d * d; ++a) cov[a] /= static_cast<double>(n);
    auto quad = [d](const double* mat, const std::vector<double>& u) {
      double q = 0;
      for (std::size_t a = 0; a < d; ++a)
        for (std::size_t b = 0; b < d; ++b) q += u[a] * mat[a * d + b] * u[b];
      return q;
    };
    for (std::size_t a = 0; a < d; ++a) m.along_mean[k] += e[a] * mean[a];
    m.along_variance[k] = quad(cov, e);
    m.along_square[k] = quad(second, e);
    if (!f.empty()) {
      m.across_variance[k] = quad(cov, f);
    } else {
      double trace = 0;
      for (std::size_t a = 0; a < d; ++a) trace += cov[a * d + a];
      m.across_variance[k] = trace - m.along_variance[k];
    }
  }
  return m;
}

DiffusionFit fit_diffusion(const ActionSamples& s, const std::vector<double>& direction,
                           const DiffusionOptions& o) {
  check_samples(s);
  const std::vector<double> e = unit(direction, s.dim, "the direction");
  if (o.replicates < 0) bad("replicates must be >= 0, got " + std::to_string(o.replicates));
  std::size_t first = 0;
  while (first < s.times && s.t[first] < o.t_min) ++first;
  std::size_t last = s.times;
  while (last > 0 && s.t[last - 1] > o.t_max) --last;
  if (first >= s.times || last == 0 || last - 1 <= first)
    bad("need at least 2 sample times in [t_min, t_max] = [" + std::to_string(o.t_min) + ", " +
        std::to_string(o.t_max) + "]");
  last -= 1;
  const std::vector<std::size_t> used = finite_trajectories(s);
  const std::size_t n = used.size(), times = s.times;
  std::vector<double> q = projections(s, used, e);
  // the ensemble's mean projection at each time: the drift; q centred on it
  std::vector<double> mean(times, 0.0);
  for (std::size_t u = 0; u < n; ++u)
    for (std::size_t k = 0; k < times; ++k) mean[k] += q[u * times + k];
  for (double& x : mean) x /= static_cast<double>(n);
  for (std::size_t u = 0; u < n; ++u)
    for (std::size_t k = 0; k < times; ++k) q[u * times + k] -= mean[k];

  DiffusionFit fit;
  fit.first = first;
  fit.last = last;
  fit.used = n;
  fit.excluded = s.trajectories - n;
  fit.replicates = o.replicates;
  std::vector<std::uint32_t> ones(n, 1);
  const std::vector<double> var = weighted_variance(q, ones, n, times, first, last);
  line_fit(s.t, var, first, last, &fit.slope, &fit.intercept);
  fit.D = fit.slope / 2;
  fit.drift = slope_of(s.t, mean, first, last);
  const Halves halves(s.t, first, last);
  halves.slopes(s.t, var, fit.slope, &fit.slope_first_half, &fit.slope_second_half);
  fit.D_first_half = fit.slope_first_half / 2;
  fit.D_second_half = fit.slope_second_half / 2;
  fit.alpha = halves.exponent(fit.slope_first_half, fit.slope_second_half);
  if (o.replicates > 0) {
    // replicate r draws from its own stream (seed, r): the replicates run in parallel and
    // give the same bits whatever the number of threads
    std::vector<double> ds(static_cast<std::size_t>(o.replicates)), alphas(ds.size());
#pragma omp parallel
    {
      std::vector<std::uint32_t> count(n);
#pragma omp for schedule(dynamic)
      for (int r = 0; r < o.replicates; ++r) {
        SplitMix seeder{o.seed + static_cast<std::uint64_t>(r)};
        SplitMix rng{seeder.next()};
        std::fill(count.begin(), count.end(), 0u);
        for (std::size_t j = 0; j < n; ++j) ++count[rng.below(n)];
        const std::vector<double> v = weighted_variance(q, count, n, times, first, last);
        const double slope = slope_of(s.t, v, first, last);
        double s1, s2;
        halves.slopes(s.t, v, slope, &s1, &s2);
        ds[static_cast<std::size_t>(r)] = slope / 2;
        alphas[static_cast<std::size_t>(r)] = halves.exponent(s1, s2);
      }
    }
    fit.D_error = standard_deviation(ds);
    fit.D_low = percentile(ds, 0.16);
    fit.D_high = percentile(ds, 0.84);
    alphas.erase(std::remove_if(alphas.begin(), alphas.end(), [](double a) { return !std::isfinite(a); }),
                 alphas.end());
    fit.alpha_error = standard_deviation(alphas);
  }
  fit.diffusive = std::isfinite(fit.alpha) && std::fabs(fit.alpha - 1) <= kDiffusiveExponent + 2 * fit.alpha_error;
  return fit;
}

}  // namespace arnoldweb
