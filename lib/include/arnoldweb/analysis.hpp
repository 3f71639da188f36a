// arnoldweb: numbers read off velocity maps: how bright a resonance line is
// against its dark zone, and how far an ensemble has spread.
#pragma once

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

}  // namespace arnoldweb
