// arnoldweb: geometry on the sphere of directions: HEALPix pixels (RING
// order) and the resonance circles m.P = 0 of the model.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace arnoldweb {

using Vec3 = std::array<double, 3>;

// Pixel of a direction (need not be normalised), as the kernels compute it.
std::uint64_t vec2pix_ring(int nside, const Vec3& v);
// Unit vector to the centre of a pixel.
Vec3 pix2vec_ring(int nside, std::uint64_t pix);

// The orthonormal frame at longitude lon and latitude lat (degrees): the
// direction c, and the tangent vectors east (of growing longitude) and north.
struct TangentFrame {
  Vec3 c, east, north;
};
TangentFrame tangent_frame(double lon_deg, double lat_deg);

// Unit vector of longitude lon and latitude lat, in degrees (tangent_frame().c).
Vec3 direction(double lon_deg, double lat_deg);

// A resonance m.P = 0: a great circle of the momentum sphere.
struct Resonance {
  std::array<int, 3> m;  // coprime, first non-zero component positive
  int order = 0;         // max |m_i|
  std::string label() const;  // "(1,-1,2)"
};

// Every resonance with max |m_i| <= max_order, lowest order first.
std::vector<Resonance> resonances(int max_order);

// The primary resonances: the Fourier modes of the perturbation
// V = cos x cos y (1 + cos 2z), m = (1,+-1,0) and (1,+-1,+-2), which act at
// first order in V. (Second-order ones, from sums of two modes, are weaker.)
std::vector<Resonance> primary_resonances();

// Angular distance (radians) of a unit direction from the circle m.P = 0.
double distance_to_circle(const Resonance& r, const Vec3& unit);

}  // namespace arnoldweb
