// arnoldweb: the analyses of a finished run (analyses.hpp).
#include "run/analyses.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <stdexcept>

#include "arnoldweb/diffusion.hpp"
#include "aw_params.h"

namespace arnoldweb::detail {
namespace {

using json = nlohmann::json;

json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json fit_json(const DiffusionFit& f) {
  return {{"D", f.D},
          {"D_error", f.D_error},
          {"D_68", {f.D_low, f.D_high}},
          {"slope", f.slope},
          {"intercept", f.intercept},
          {"drift", f.drift},
          {"slope_first_half", f.slope_first_half},
          {"slope_second_half", f.slope_second_half},
          {"D_first_half", f.D_first_half},
          {"D_second_half", f.D_second_half},
          {"alpha", number_or_null(f.alpha)},
          {"alpha_error", f.alpha_error},
          {"diffusive", f.diffusive},
          {"replicates", f.replicates}};
}

std::string short_number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

// The warning for a fit whose variance does not grow linearly (DiffusionFit::diffusive).
std::string not_diffusive(const char* direction, const DiffusionFit& f, double t_min) {
  const std::string growth = std::isfinite(f.alpha)
                                 ? "grows like t^" + short_number(f.alpha) + " +- " + short_number(f.alpha_error)
                                 : std::string("does not grow in one half of the fit");
  return "observe.diffusion: the variance " + std::string(direction) + " the resonance " + growth +
         " over t >= " + short_number(t_min) + " T (D of the two halves " + short_number(f.D_first_half) +
         " and " + short_number(f.D_second_half) + "): not diffusive (|alpha - 1| > " +
         short_number(kDiffusiveExponent) + " + 2 errors), D " + direction +
         " is not a diffusion coefficient here (docs/frequencies.md)";
}

// The key of the diffusion analysis (the actions row's table key) and a number of its sub-keys.
const std::string kKey = "observe.diffusion";
double value(const Plan& plan, const char* name) { return plan.scene.output_value(kKey + "." + name).at(0); }

// The actions of the trajectories that ended with status ok, at t_k = k every.
// Averaged samples (observe.diffusion.average) start at t_1: the record at
// t = 0 is the instantaneous action, not a mean, and is left out, so that the
// displacements are between means.
ActionSamples samples_of(const Plan& plan, const Records& rec) {
  ActionSamples s;
  s.dim = 3;
  const std::size_t first = value(plan, "average") > 0 ? 1 : 0;
  const std::size_t records = rec.reals_per / 3;
  s.times = records > first ? records - first : 0;
  for (std::size_t k = first; k < records; ++k)
    s.t.push_back(plan.start_time() + static_cast<double>(k) * value(plan, "every"));
  const std::uint64_t n = rec.count();
  for (std::uint64_t i = 0; i < n; ++i) {
    if (rec.ints[i * rec.ints_per] != AW_STATUS_OK) continue;
    const auto row = rec.reals.begin() + static_cast<std::ptrdiff_t>(i * rec.reals_per);
    s.actions.insert(s.actions.end(), row + static_cast<std::ptrdiff_t>(3 * first),
                     row + static_cast<std::ptrdiff_t>(rec.reals_per));
    ++s.trajectories;
  }
  return s;
}

json diffusion(const Plan& plan, const Records& rec) {
  const ActionSamples s = samples_of(plan, rec);
  const std::vector<double> along = plan.scene.output_value(kKey + ".along");
  const std::vector<double> across = plan.scene.output_value(kKey + ".across");
  json j = {{"every", value(plan, "every")},
            {"along", along},
            {"across", across},
            {"fit_from", value(plan, "fit_from")},
            {"average", value(plan, "average")},
            {"average_every", value(plan, "average_every")},
            {"flagged", rec.count() - s.trajectories},
            {"definition", "Var[e . dI](t) = sigma0^2 + 2 D t by least squares over t >= fit_from; D in action^2 per "
                           "T; error: bootstrap over trajectories; linearity: D of the two halves of the fitted "
                           "times, alpha of Var - sigma0^2 ~ t^alpha from their slopes, diffusive where |alpha - 1| "
                           "<= 0.2 + 2 errors"}};
  try {
    const DiffusionMoments m = diffusion_moments(s, {along, across});
    DiffusionOptions o;
    o.t_min = plan.start_time() + value(plan, "fit_from");
    j["trajectories"] = m.used;
    j["excluded"] = m.excluded;
    const DiffusionFit along_fit = fit_diffusion(s, along, o);
    j["along_fit"] = fit_json(along_fit);
    // across: the direction made orthogonal to `along`, as the moments use it
    std::vector<double> f = across;
    double aa = 0, af = 0;
    for (int c = 0; c < 3; ++c) aa += along[c] * along[c], af += along[c] * f[c];
    for (int c = 0; c < 3; ++c) f[c] -= af / aa * along[c];
    const DiffusionFit across_fit = fit_diffusion(s, f, o);
    j["across_fit"] = fit_json(across_fit);
    json warnings = json::array();
    if (!along_fit.diffusive) warnings.push_back(not_diffusive("along", along_fit, o.t_min));
    if (!across_fit.diffusive) warnings.push_back(not_diffusive("across", across_fit, o.t_min));
    j["warnings"] = warnings;
    json t = json::array(), am = json::array(), av = json::array(), cv = json::array();
    for (std::size_t k = 0; k < m.t.size(); ++k) {
      t.push_back(m.t[k]);
      am.push_back(number_or_null(m.along_mean[k]));
      av.push_back(number_or_null(m.along_variance[k]));
      cv.push_back(number_or_null(m.across_variance[k]));
    }
    j["moments"] = {{"t", t}, {"along_mean", am}, {"along_variance", av}, {"across_variance", cv}};
  } catch (const std::invalid_argument& e) {
    j["error"] = e.what();  // too few trajectories left, ...: said, not fatal
  }
  return j;
}

}  // namespace

void analyse(const Plan& plan, Result& result) {
  if (plan.kernel.features & AW_F_DIFFUSION)
    if (const Records* rec = result.records_of("actions"); rec && rec->count() > 0)
      result.analyses["diffusion"] = diffusion(plan, *rec).dump();
}

}  // namespace arnoldweb::detail
