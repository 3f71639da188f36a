// arnoldweb: HEALPix pixel geometry (Gorski et al. 2005, RING scheme) and the
// resonance circles of the model.
#include "arnoldweb/sphere.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "aw_healpix.h"

namespace arnoldweb {
namespace {

// floor((1 + sqrt(2 ip - 1)) / 2) for ip >= 1, exact for large ip
std::int64_t cap_ring(std::int64_t ip) {
  std::int64_t r = static_cast<std::int64_t>((1.0 + std::sqrt(2.0 * static_cast<double>(ip) - 1.0)) / 2.0);
  while (2 * r * (r - 1) >= ip) --r;        // ring r holds ip in (2 r (r-1), 2 r (r+1)]
  while (2 * (r + 1) * r < ip) ++r;
  return r;
}

}  // namespace

std::uint64_t vec2pix_ring(int nside, const Vec3& v) {
  return static_cast<std::uint64_t>(aw_vec2pix_ring(nside, v[0], v[1], v[2]));
}

Vec3 pix2vec_ring(int nside, std::uint64_t pixel) {
  const std::int64_t n = nside, p = static_cast<std::int64_t>(pixel);
  const std::int64_t ncap = 2 * n * (n - 1), npix = 12 * n * n;
  double z, phi;
  if (p < ncap) {
    const std::int64_t ip = p + 1, ring = cap_ring(ip);
    const std::int64_t iphi = ip - 2 * ring * (ring - 1);
    z = 1.0 - static_cast<double>(ring * ring) / static_cast<double>(3 * n * n);
    phi = (static_cast<double>(iphi) - 0.5) * M_PI / (2.0 * static_cast<double>(ring));
  } else if (p < npix - ncap) {
    const std::int64_t ip = p - ncap, ring = ip / (4 * n) + n, iphi = ip % (4 * n) + 1;
    const double fodd = 0.5 * static_cast<double>(1 + (ring + n) % 2);
    z = static_cast<double>(2 * n - ring) * 2.0 / static_cast<double>(3 * n);
    phi = (static_cast<double>(iphi) - fodd) * M_PI / (2.0 * static_cast<double>(n));
  } else {
    const std::int64_t ip = npix - p, ring = cap_ring(ip);
    const std::int64_t iphi = 4 * ring + 1 - (ip - 2 * ring * (ring - 1));
    z = -1.0 + static_cast<double>(ring * ring) / static_cast<double>(3 * n * n);
    phi = (static_cast<double>(iphi) - 0.5) * M_PI / (2.0 * static_cast<double>(ring));
  }
  const double st = std::sqrt((1.0 - z) * (1.0 + z));
  return {st * std::cos(phi), st * std::sin(phi), z};
}

TangentFrame tangent_frame(double lon_deg, double lat_deg) {
  constexpr double deg = M_PI / 180.0;
  const double cl = std::cos(lat_deg * deg), sl = std::sin(lat_deg * deg);
  const double co = std::cos(lon_deg * deg), so = std::sin(lon_deg * deg);
  return {{cl * co, cl * so, sl}, {-so, co, 0.0}, {-sl * co, -sl * so, cl}};
}

Vec3 direction(double lon_deg, double lat_deg) { return tangent_frame(lon_deg, lat_deg).c; }

std::string Resonance::label() const {
  return "(" + std::to_string(m[0]) + "," + std::to_string(m[1]) + "," + std::to_string(m[2]) + ")";
}

std::vector<Resonance> resonances(int max_order) {
  std::vector<Resonance> out;
  for (int order = 1; order <= max_order; ++order)
    for (int a = -order; a <= order; ++a)
      for (int b = -order; b <= order; ++b)
        for (int c = -order; c <= order; ++c) {
          if (std::max({std::abs(a), std::abs(b), std::abs(c)}) != order) continue;
          if (std::gcd(std::gcd(std::abs(a), std::abs(b)), std::abs(c)) != 1) continue;
          // canonical sign: first non-zero component positive
          const int first = a != 0 ? a : b != 0 ? b : c;
          if (first < 0) continue;
          out.push_back({{a, b, c}, order});
        }
  return out;
}

std::vector<Resonance> primary_resonances() {
  std::vector<Resonance> out;
  for (const Resonance& r : resonances(2)) {
    const auto& m = r.m;
    if (m[0] == 1 && std::abs(m[1]) == 1 && (m[2] == 0 || std::abs(m[2]) == 2)) out.push_back(r);
  }
  return out;
}

double distance_to_circle(const Resonance& r, const Vec3& u) {
  const double norm = std::sqrt(double(r.m[0] * r.m[0] + r.m[1] * r.m[1] + r.m[2] * r.m[2]));
  const double s = (r.m[0] * u[0] + r.m[1] * u[1] + r.m[2] * u[2]) / norm;  // sin of the distance
  return std::asin(std::min(1.0, std::fabs(s)));
}

}  // namespace arnoldweb
