// arnoldweb: map statistics (resonance-line contrast, ensemble spread).
#include "arnoldweb/analysis.hpp"

#include <cmath>

namespace arnoldweb {

LineContrast line_contrast(const std::vector<std::uint64_t>& map, int nside, const Resonance& r,
                           double line, double gap, double band, const std::vector<Resonance>& others,
                           double exclude) {
  LineContrast c;
  double line_sum = 0, zone_sum = 0;
  for (std::uint64_t p = 0; p < map.size(); ++p) {
    const Vec3 v = pix2vec_ring(nside, p);
    bool near_other = false;
    for (const Resonance& o : others)
      if (o.m != r.m && distance_to_circle(o, v) < exclude) near_other = true;
    if (near_other) continue;
    const double d = distance_to_circle(r, v);
    if (d < line) {
      line_sum += static_cast<double>(map[p]);
      ++c.line_pixels;
    } else if (d >= gap && d < gap + band) {
      zone_sum += static_cast<double>(map[p]);
      ++c.zone_pixels;
    }
  }
  if (c.line_pixels) c.line_density = line_sum / static_cast<double>(c.line_pixels);
  if (c.zone_pixels) c.zone_density = zone_sum / static_cast<double>(c.zone_pixels);
  return c;
}

double direction_spread(const std::vector<std::uint64_t>& map, int nside, const Vec3& c) {
  double sum = 0, count = 0;
  for (std::uint64_t p = 0; p < map.size(); ++p) {
    if (!map[p]) continue;
    const Vec3 v = pix2vec_ring(nside, p);
    const double d2 = (v[0] - c[0]) * (v[0] - c[0]) + (v[1] - c[1]) * (v[1] - c[1]) + (v[2] - c[2]) * (v[2] - c[2]);
    sum += static_cast<double>(map[p]) * d2;
    count += static_cast<double>(map[p]);
  }
  return count > 0 ? sum / count : 0;
}

}  // namespace arnoldweb
