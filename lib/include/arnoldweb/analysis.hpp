// arnoldweb: numbers read off velocity maps: how bright a resonance line is
// against its dark zone, how far an ensemble has spread, and whether two maps
// are statistically the same.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "arnoldweb/sphere.hpp"

namespace arnoldweb {

// Mean counts per pixel within `line` radians of the circle m.P = 0, and in
// the band from `gap` to `gap + band` radians on both sides (the dark zone).
struct LineContrast {
  double line_density = 0, zone_density = 0;
  std::uint64_t line_pixels = 0, zone_pixels = 0;
  double ratio() const { return zone_density > 0 ? line_density / zone_density : 0; }
};
// Pixels closer than `exclude` radians to another circle of `others` are left
// out (intersections would count twice).
LineContrast line_contrast(const std::vector<std::uint64_t>& map, int nside, const Resonance& r,
                           double line, double gap, double band,
                           const std::vector<Resonance>& others = {}, double exclude = 0);

// Mean of |d - c|^2 over the map's counts, d the pixel centres (unit
// vectors) and c a unit vector: the spread of the averaged velocities'
// directions about c (times |P|^2 it estimates <|P(t) - P(0)|^2>).
double direction_spread(const std::vector<std::uint64_t>& map, int nside, const Vec3& c);

// Two-sample chi-square test of two histograms of the same bins (two velocity
// maps, two zooms): could both be samples of one distribution? With totals A
// and B (which may differ),
//   chi2 = sum_i (sqrt(B/A) a_i - sqrt(A/B) b_i)^2 / (a_i + b_i)
// over the bins with a_i + b_i > 0, dof = (bins used) - 1, and p = Q(dof/2,
// chi2/2), the regularized upper incomplete gamma function (the chance of a
// chi2 at least this large if both maps sample one distribution). The
// chi-square distribution is the large-count limit of each term: bins whose
// combined count a_i + b_i is below `min_count` are therefore pooled into one
// bin (their a and b summed), which counts as one bin used. Empty bins (both
// counts 0) are left out. A test of counts, so of independent samples: two
// maps of one seed share their trajectories and are not independent.
struct MapComparison {
  double chi2 = 0, dof = 0;
  double p_value = 1;  // 1 when dof = 0 (a single bin used: nothing to compare)
  std::uint64_t total_a = 0, total_b = 0;
  std::size_t bins = 0;         // bins in each map
  std::size_t used_bins = 0;    // terms of the sum: bins at or above min_count, plus the pooled bin
  std::size_t pooled_bins = 0;  // bins below min_count merged into the pooled bin
  std::size_t empty_bins = 0;   // bins with no count in either map (left out)
  double chi2_per_dof() const { return dof > 0 ? chi2 / dof : 0; }
  bool consistent(double alpha) const { return p_value >= alpha; }
};
// Throws std::invalid_argument for maps of different sizes, empty maps, a map
// without counts, or a negative or non-finite min_count.
MapComparison compare_maps(const std::vector<std::uint64_t>& a, const std::vector<std::uint64_t>& b,
                           double min_count = 5);

}  // namespace arnoldweb
