// arnoldweb: the sphere pictures: an orthographic view like the paper's
// figures, a Mollweide view of the whole sphere, and the resonance circles
// m.P = 0 and zoom squares drawn over them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "arnoldweb/output.hpp"
#include "arnoldweb/sphere.hpp"
#include "pictures/canvas.hpp"
#include "pictures/sphere_view.hpp"

namespace arnoldweb::detail {
namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 normalised(const Vec3& a) {
  const double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}

// A polyline of unit vectors, drawn where it faces the viewer.
template <class Point>
void draw_path(cairo_t* cr, const View& view, double cx, double cy, double radius, int n, Point point) {
  bool pen = false;
  for (int k = 0; k <= n; ++k) {
    const Vec3 p = point(k);
    if (view.z(p) <= 0) {
      pen = false;
      continue;
    }
    const double x = cx + radius * view.x(p), y = cy - radius * view.y(p);
    if (pen)
      cairo_line_to(cr, x, y);
    else
      cairo_move_to(cr, x, y);
    pen = true;
  }
  cairo_stroke(cr);
}

}  // namespace

View::View(double lon, double lat) {
  const TangentFrame f = tangent_frame(lon, lat);
  v = f.c;
  e1 = f.east;
  e2 = f.north;
}
double View::x(const Vec3& p) const { return dot(p, e1); }
double View::y(const Vec3& p) const { return dot(p, e2); }
double View::z(const Vec3& p) const { return dot(p, v); }

void paint_sphere(Canvas& c, const std::vector<std::uint64_t>& map, int nside, const View& view, double cx,
                  double cy, double radius, const LogScale& scale) {
  c.paint(static_cast<int>(cx - radius - 1), static_cast<int>(cy - radius - 1), static_cast<int>(2 * radius + 3),
          static_cast<int>(2 * radius + 3),
          [&](double px, double py) {
            const double x = (px - cx) / radius, y = (cy - py) / radius;
            const double rr = x * x + y * y;
            if (rr > 1) return -1.0;
            const double z = std::sqrt(1 - rr);
            const Vec3 d = {x * view.e1[0] + y * view.e2[0] + z * view.v[0],
                            x * view.e1[1] + y * view.e2[1] + z * view.v[1],
                            x * view.e1[2] + y * view.e2[2] + z * view.v[2]};
            return scale(map[vec2pix_ring(nside, d)]);
          },
          2);
}

std::vector<Resonance> circles_of(const RenderOptions& o) {
  if (o.resonances.empty()) return resonances(o.resonance_order);
  std::vector<Resonance> out;
  for (std::array<int, 3> m : o.resonances) {
    const int g = std::gcd(std::gcd(std::abs(m[0]), std::abs(m[1])), std::abs(m[2]));
    if (g == 0) continue;
    for (int& v : m) v /= g;
    const int first = m[0] != 0 ? m[0] : m[1] != 0 ? m[1] : m[2];
    if (first < 0)
      for (int& v : m) v = -v;
    const int order = std::max({std::abs(m[0]), std::abs(m[1]), std::abs(m[2])});
    bool seen = false;
    for (const Resonance& r : out) seen = seen || r.m == m;
    if (!seen) out.push_back({m, order});
  }
  std::sort(out.begin(), out.end(), [](const Resonance& a, const Resonance& b) { return a.order < b.order; });
  return out;
}

void draw_circles(Canvas& c, const View& view, double cx, double cy, double radius, const std::vector<Resonance>& list) {
  cairo_t* cr = c.cr();
  for (const Resonance& r : list) {
    const Vec3 n = normalised({double(r.m[0]), double(r.m[1]), double(r.m[2])});
    const Vec3 helper = std::fabs(n[2]) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    const Vec3 a = normalised(cross(n, helper)), b = cross(n, a);
    auto point = [&](int k) {
      const double t = k * M_PI / 360;
      return Vec3{std::cos(t) * a[0] + std::sin(t) * b[0], std::cos(t) * a[1] + std::sin(t) * b[1],
                  std::cos(t) * a[2] + std::sin(t) * b[2]};
    };
    if (r.order == 1)
      cairo_set_source_rgba(cr, 1, 1, 1, 0.5);
    else
      cairo_set_source_rgba(cr, 0.55, 0.85, 1.0, 0.45);
    cairo_set_line_width(cr, r.order == 1 ? 1.2 : 0.8);
    draw_path(cr, view, cx, cy, radius, 720, point);
    // the label goes where the circle is most face-on, away from the centre
    double best = 0;
    Vec3 at{};
    for (int k = 0; k <= 720; ++k) {
      const Vec3 p = point(k);
      const double z = view.z(p), score = z * (1 - z);
      if (z > 0 && score > best) {
        best = score;
        at = p;
      }
    }
    if (best > 0) c.text(cx + radius * view.x(at) + 3, cy - radius * view.y(at) - 3, r.label(), 9, 0.85, 0.9, 1.0);
  }
}

void draw_square(Canvas& c, const View& view, double cx, double cy, double radius, const std::array<double, 2>& centre,
                 double width) {
  const double w = std::tan(0.5 * width * M_PI / 180);
  const TangentFrame f = tangent_frame(centre[0], centre[1]);
  const Vec3 &cv = f.c, &e1 = f.east, &e2 = f.north;
  const double corner[5][2] = {{-w, -w}, {w, -w}, {w, w}, {-w, w}, {-w, -w}};
  cairo_t* cr = c.cr();
  cairo_set_source_rgba(cr, 0.5, 1.0, 0.6, 0.95);
  cairo_set_line_width(cr, 1.6);
  draw_path(cr, view, cx, cy, radius, 160, [&](int k) {
    const int side = std::min(k / 40, 3);
    const double f = (k - 40 * side) / 40.0;
    const double gx = corner[side][0] + f * (corner[side + 1][0] - corner[side][0]);
    const double gy = corner[side][1] + f * (corner[side + 1][1] - corner[side][1]);
    return normalised({cv[0] + gx * e1[0] + gy * e2[0], cv[1] + gx * e1[1] + gy * e2[1], cv[2] + gx * e1[2] + gy * e2[2]});
  });
}

void paint_mollweide(Canvas& c, double cx, double cy, double a, const std::function<double(const Vec3&)>& value) {
  c.paint(static_cast<int>(cx - a - 1), static_cast<int>(cy - a / 2 - 1), static_cast<int>(2 * a + 3),
          static_cast<int>(a + 3),
          [&](double px, double py) {
            const double x = (px - cx) / a * 2 * M_SQRT2, y = (cy - py) / (a / 2) * M_SQRT2;
            if (x * x / 8 + y * y / 2 > 1) return -1.0;
            const double theta = std::asin(std::clamp(y / M_SQRT2, -1.0, 1.0));
            const double lat = std::asin(std::clamp((2 * theta + std::sin(2 * theta)) / M_PI, -1.0, 1.0));
            const double lon = M_PI * x / (2 * M_SQRT2 * std::cos(theta));
            if (std::fabs(lon) > M_PI) return -1.0;
            return value(Vec3{std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)});
          },
          2);
}

}  // namespace arnoldweb::detail

namespace arnoldweb::detail {

void draw_sphere_png(const std::string& path, const std::vector<std::uint64_t>& map, int nside,
                       const RenderOptions& o) {
  const int w = o.width, h = static_cast<int>(o.width * 0.82);
  detail::Canvas c(w, h);
  const detail::LogScale scale(map);
  const detail::View view(o.view_lon, o.view_lat);
  const double radius = 0.42 * h, cx = 0.44 * w, cy = 0.52 * h;
  detail::paint_sphere(c, map, nside, view, cx, cy, radius, scale);
  if (o.resonance_order > 0) detail::draw_circles(c, view, cx, cy, radius, detail::circles_of(o));
  c.colour_bar(0.86 * w, 0.16 * h, 0.025 * w, 0.68 * h, scale, "counts");
  c.text(0.03 * w, 0.05 * h, o.title, 15);
  char view_text[96];
  std::snprintf(view_text, sizeof view_text, "orthographic, view from lon %g, lat %g deg", o.view_lon, o.view_lat);
  c.text(0.03 * w, 0.97 * h, o.caption.empty() ? view_text : o.caption + "   " + view_text, 11, 0.7, 0.7, 0.7);
  c.save(path);
}

void draw_mollweide_png(const std::string& path, const std::vector<std::uint64_t>& map, int nside,
                        const RenderOptions& o) {
  const int w = o.width, h = static_cast<int>(o.width * 0.62);
  detail::Canvas c(w, h);
  const detail::LogScale scale(map);
  const double a = 0.45 * w, cx = 0.5 * w, cy = 0.45 * h;  // semi-axes a and a/2
  paint_mollweide(c, cx, cy, a, [&](const Vec3& d) { return scale(map[vec2pix_ring(nside, d)]); });
  c.colour_bar(0.25 * w, 0.9 * h, 0.5 * w, 0.025 * h, scale, "");
  c.text(0.03 * w, 0.06 * h, o.title, 15);
  c.text(0.03 * w, 0.985 * h,
         (o.caption.empty() ? std::string() : o.caption + "   ") +
             "Mollweide, longitude 0 at the centre, east to the right; colour: counts (log)",
         11, 0.7, 0.7, 0.7);
  c.save(path);
}

}  // namespace arnoldweb::detail
