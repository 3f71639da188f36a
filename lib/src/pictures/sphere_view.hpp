// arnoldweb: drawing the sphere in orthographic view, shared by the map
// pictures and the composite figures.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "arnoldweb/sphere.hpp"
#include "pictures/canvas.hpp"

namespace arnoldweb::detail {

// The view: v towards the viewer, e1 to the right (east), e2 up (north).
struct View {
  Vec3 v, e1, e2;
  View(double lon, double lat);
  // screen offsets (right, up) and depth (towards the viewer) of a unit vector
  double x(const Vec3& p) const;
  double y(const Vec3& p) const;
  double z(const Vec3& p) const;
};

// The map on a disc of `radius` pixels about (cx, cy).
void paint_sphere(Canvas& c, const std::vector<std::uint64_t>& map, int nside, const View& view, double cx,
                  double cy, double radius, const LogScale& scale);
// The Mollweide ellipse of semi-axes (a, a/2) about (cx, cy), each pixel the
// colour-map position value(d) of its direction d (-1: background).
void paint_mollweide(Canvas& c, double cx, double cy, double a, const std::function<double(const Vec3&)>& value);
// The circles m.P = 0 with max |m_i| <= max_order, labelled.
void draw_circles(Canvas& c, const View& view, double cx, double cy, double radius, const std::vector<Resonance>& list);
// The circles a picture draws: options.resonances (canonical, coprime) if given, else every
// resonance up to options.resonance_order.
std::vector<Resonance> circles_of(const RenderOptions& options);
// The outline of a gnomonic square (centre lon/lat, full width, degrees).
void draw_square(Canvas& c, const View& view, double cx, double cy, double radius, const std::array<double, 2>& centre,
                 double width);

}  // namespace arnoldweb::detail
