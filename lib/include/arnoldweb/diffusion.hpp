// arnoldweb: how fast an ensemble spreads in action space (issue 26): the
// moments of the action displacement at every sample time, projected along a
// resonance and across it, and the diffusion coefficient from the linear
// growth of the variance, with a bootstrap error bar (docs/frequencies.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace arnoldweb {

// The actions of an ensemble at sample times: trajectory i at time t[k] has
// the action vector actions[(i * times + k) * dim + 0 .. dim - 1]. dim is 3
// for the models' momenta, or fewer (e.g. the 2 actions I1, I2 of fgl, whose
// I3 only follows the energy). Trajectories with a non-finite action at any
// time (flagged ones) are left out and counted.
struct ActionSamples {
  std::size_t trajectories = 0, times = 0, dim = 3;
  std::vector<double> t;        // sample times, strictly increasing (T)
  std::vector<double> actions;  // trajectories x times x dim
};

// The moments of dI(t_k) = I(t_k) - I(t_0) over the ensemble, at every sample
// time k (arrays indexed by k first):
//   mean[k][a]        <dI_a>
//   second[k][a][b]   <dI_a dI_b>                (the raw second moment)
//   covariance[k][a][b] <dI_a dI_b> - <dI_a><dI_b>  (over N, not N - 1)
// and projected on the unit vector e along the resonance:
//   along_mean[k] = e . mean,  along_variance[k] = e^T covariance e,
//   along_square[k] = e^T second e = <(e . dI)^2>
// and across it: across_variance[k] = f^T covariance f for a given unit f,
// or, without one, trace(covariance) - along_variance (the whole orthogonal
// complement of e).
struct DiffusionMoments {
  std::size_t dim = 0, used = 0, excluded = 0;  // trajectories used, left out (non-finite)
  std::vector<double> t;
  std::vector<double> mean, second, covariance;  // times x dim, times x dim x dim (twice)
  std::vector<double> along_mean, along_variance, along_square, across_variance;  // times
};

// The direction along the resonance (dim components; normalised here) and,
// optionally, one across it (orthogonalised against `along`, normalised).
struct ResonanceDirections {
  std::vector<double> along;
  std::vector<double> across;  // empty: the orthogonal complement of `along`
};

// Throws std::invalid_argument (naming the problem) for sizes that do not
// match, fewer than 2 times, times not strictly increasing or not finite, a
// zero or wrong-sized direction, `across` parallel to `along`, or fewer than
// 2 trajectories with finite actions.
DiffusionMoments diffusion_moments(const ActionSamples& samples, const ResonanceDirections& directions);

// The diffusion coefficient along a direction: sigma^2(t) = Var[e . dI(t)]
// over the ensemble (centred: a drift common to the ensemble does not count)
// fitted by ordinary least squares as
//     sigma^2(t) = sigma_0^2 + 2 D t
// over the sample times in [t_min, t_max] (D in action^2 per T; the
// one-dimensional Einstein relation; papers that write <dI^2> = D t have
// twice this D). The error bar is a bootstrap over trajectories: `replicates`
// resamplings of the ensemble with replacement (a fixed generator seeded by
// `seed`: the same numbers on every machine), the whole curve refitted each
// time, so that the correlation of sigma^2 between times (the same
// trajectories) is in it.
struct DiffusionOptions {
  double t_min = 0;       // fit from the first sample time >= t_min
  double t_max = 1e300;   // to the last sample time <= t_max
  int replicates = 200;   // bootstrap resamplings (0: no error bar)
  std::uint64_t seed = 26;
};
inline constexpr double kDiffusiveExponent = 0.2;  // |alpha - 1| allowed beyond twice its error (DiffusionFit)
struct DiffusionFit {
  double D = 0;                   // slope / 2
  double slope = 0, intercept = 0;  // of sigma^2(t) (action^2 / T, action^2)
  double drift = 0;               // d<e . dI>/dt by least squares over the same times (action / T)
  double D_error = 0;             // standard deviation of the bootstrap D's (0 without replicates)
  double D_low = 0, D_high = 0;   // their 16th and 84th percentiles (a 68% interval)
  // The slopes of the first and second half of the fitted times (sharing the
  // middle time): about equal for normal diffusion; a ratio > 1 signals
  // ballistic spreading (different drifts, sigma^2 ~ t^2), < 1 saturation or
  // subdiffusion. D_first_half, D_second_half: half of each.
  double slope_first_half = 0, slope_second_half = 0;
  double D_first_half = 0, D_second_half = 0;
  // The growth's exponent alpha of sigma^2 - sigma_0^2 ~ (t - t_0)^alpha (t_0
  // the first sample time, where the displacements start), from the halves'
  // slopes s1, s2 and the mean times c1, c2 of the halves:
  //     alpha = 1 + ln(s2 / s1) / ln((c2 - t_0) / (c1 - t_0))
  // (a least-squares slope over a half is the curve's derivative near the
  // half's mean time, alpha K (c - t_0)^(alpha - 1), free of the intercept;
  // exact for alpha = 1 and 2). NaN where a half's slope is not positive (the
  // variance does not grow there) or fewer than 3 times are fitted.
  // alpha_error: the standard deviation of the bootstrap's alphas (those that
  // are finite; 0 without replicates). diffusive: alpha is finite and
  // |alpha - 1| <= kDiffusiveExponent + 2 alpha_error, the growth linear
  // within 20 % in its exponent (docs/frequencies.md).
  double alpha = 0, alpha_error = 0;
  bool diffusive = false;
  std::size_t first = 0, last = 0;  // sample indices of the fitted range (inclusive)
  std::size_t used = 0, excluded = 0;
  int replicates = 0;
};
// Throws std::invalid_argument as diffusion_moments does, and for fewer than
// 2 sample times in [t_min, t_max] or a negative number of replicates.
DiffusionFit fit_diffusion(const ActionSamples& samples, const std::vector<double>& direction,
                           const DiffusionOptions& options = {});

}  // namespace arnoldweb
