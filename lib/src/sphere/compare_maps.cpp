// arnoldweb: the two-sample chi-square test of two maps (analysis.hpp).
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

#include "arnoldweb/analysis.hpp"

namespace arnoldweb {
namespace {

// One term of the sum; ra = sqrt(B/A), rb = sqrt(A/B).
double term(double a, double b, double ra, double rb) {
  const double d = ra * a - rb * b;
  return d * d / (a + b);
}

}  // namespace

MapComparison compare_maps(const std::vector<std::uint64_t>& a, const std::vector<std::uint64_t>& b,
                           double min_count) {
  if (a.size() != b.size())
    throw std::invalid_argument("compare_maps: the maps have different sizes (" + std::to_string(a.size()) + " and " +
                                std::to_string(b.size()) + " bins)");
  if (a.empty()) throw std::invalid_argument("compare_maps: the maps are empty (no bins)");
  if (!(min_count >= 0) || !std::isfinite(min_count))
    throw std::invalid_argument("compare_maps: min_count must be a finite number >= 0");
  MapComparison c;
  c.bins = a.size();
  for (std::size_t i = 0; i < a.size(); ++i) {
    c.total_a += a[i];
    c.total_b += b[i];
  }
  if (c.total_a == 0 || c.total_b == 0)
    throw std::invalid_argument(std::string("compare_maps: map ") + (c.total_a == 0 ? "A" : "B") +
                                " has no counts");
  const double A = static_cast<double>(c.total_a), B = static_cast<double>(c.total_b);
  const double ra = std::sqrt(B / A), rb = std::sqrt(A / B);
  double pooled_a = 0, pooled_b = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double ai = static_cast<double>(a[i]), bi = static_cast<double>(b[i]);
    if (ai + bi == 0) {
      ++c.empty_bins;
    } else if (ai + bi < min_count) {
      pooled_a += ai;
      pooled_b += bi;
      ++c.pooled_bins;
    } else {
      c.chi2 += term(ai, bi, ra, rb);
      ++c.used_bins;
    }
  }
  if (c.pooled_bins) {
    c.chi2 += term(pooled_a, pooled_b, ra, rb);
    ++c.used_bins;
  }
  c.dof = static_cast<double>(c.used_bins) - 1;
  // Q(dof/2, chi2/2); far in the tail it underflows to 0 (Boost's default
  // policy for underflow), which is what a caller comparing with alpha wants
  c.p_value = c.dof > 0 ? boost::math::gamma_q(c.dof / 2, c.chi2 / 2) : 1.0;
  return c;
}

}  // namespace arnoldweb
