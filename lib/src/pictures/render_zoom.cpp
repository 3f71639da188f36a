// arnoldweb: the zoom pictures: a square of the sphere in gnomonic projection
// (great circles are straight lines), with the resonance lines drawn in.
#include <cmath>
#include <cstdio>

#include "arnoldweb/sphere.hpp"
#include "pictures/canvas.hpp"
#include "pictures/drawing.hpp"
#include "pictures/sphere_view.hpp"

namespace arnoldweb::detail {

void render_zoom_png(const std::string& path, const std::vector<std::uint64_t>& zoom, int res,
                     const std::array<double, 2>& center, double width, const RenderOptions& o) {
  const int w = o.width, h = static_cast<int>(o.width * 0.86);
  Canvas c(w, h);
  const LogScale scale(zoom);
  const double side = 0.74 * h, x0 = 0.1 * w, y0 = 0.11 * h;
  c.paint(static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(side), static_cast<int>(side),
          [&](double px, double py) {
            const int ix = static_cast<int>((px - x0) / side * res);
            const int iy = res - 1 - static_cast<int>((py - y0) / side * res);
            if (ix < 0 || iy < 0 || ix >= res || iy >= res) return -1.0;
            return scale(zoom[static_cast<std::size_t>(iy) * res + ix]);
          });
  // frame and axes: tangent-plane coordinate g maps to the angle atan(g)
  const double half = std::tan(0.5 * width * M_PI / 180);
  cairo_t* cr = c.cr();
  cairo_set_source_rgb(cr, 0.7, 0.7, 0.7);
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, x0 + 0.5, y0 + 0.5, side, side);
  cairo_stroke(cr);
  for (int k = -2; k <= 2; ++k) {
    const double g = half * k / 2, deg = std::atan(g) * 180 / M_PI;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%+.2g", deg);
    const double px = x0 + (g / half + 1) / 2 * side, py = y0 + (1 - (g / half + 1) / 2) * side;
    c.text(px, y0 + side + 16, buf, 10, 0.75, 0.75, 0.75, true);
    c.text(x0 - 34, py + 4, buf, 10, 0.75, 0.75, 0.75);
  }
  c.text(x0 + side / 2, y0 + side + 32, "east of the centre (deg)", 11, 0.75, 0.75, 0.75, true);
  // resonance lines m.(c + gx e1 + gy e2) = 0
  if (o.resonance_order > 0) {
    const TangentFrame f = tangent_frame(center[0], center[1]);
    const Vec3 &cv = f.c, &e1 = f.east, &e2 = f.north;
    cairo_save(cr);
    cairo_rectangle(cr, x0, y0, side, side);
    cairo_clip(cr);
    for (const Resonance& r : detail::circles_of(o)) {
      const double a = r.m[0] * e1[0] + r.m[1] * e1[1] + r.m[2] * e1[2];
      const double b = r.m[0] * e2[0] + r.m[1] * e2[1] + r.m[2] * e2[2];
      const double c0 = r.m[0] * cv[0] + r.m[1] * cv[1] + r.m[2] * cv[2];
      // points of a gx + b gy + c0 = 0 on the square's edges
      std::vector<std::array<double, 2>> pts;
      for (double g : {-half, half}) {
        if (std::fabs(b) > 1e-12) {
          const double gy = -(c0 + a * g) / b;
          if (std::fabs(gy) <= half) pts.push_back({g, gy});
        }
        if (std::fabs(a) > 1e-12) {
          const double gx = -(c0 + b * g) / a;
          if (std::fabs(gx) <= half) pts.push_back({gx, g});
        }
      }
      if (pts.size() < 2) continue;
      auto to_px = [&](const std::array<double, 2>& p) {
        return std::array<double, 2>{x0 + (p[0] / half + 1) / 2 * side, y0 + (1 - (p[1] / half + 1) / 2) * side};
      };
      const auto p0 = to_px(pts.front()), p1 = to_px(pts.back());
      cairo_set_source_rgba(cr, r.order == 1 ? 1.0 : 0.55, r.order == 1 ? 1.0 : 0.85, 1.0,
                            r.order <= 2 ? 0.55 : 0.35);
      cairo_set_line_width(cr, r.order <= 2 ? 1.0 : 0.6);
      cairo_move_to(cr, p0[0], p0[1]);
      cairo_line_to(cr, p1[0], p1[1]);
      cairo_stroke(cr);
      c.text(0.65 * p0[0] + 0.35 * p1[0] + 3, 0.65 * p0[1] + 0.35 * p1[1] - 3, r.label(), 9, 0.85, 0.9, 1.0);
    }
    cairo_restore(cr);
  }
  c.colour_bar(0.9 * w, y0 + 0.05 * side, 0.025 * w, 0.9 * side, scale, "counts");
  char sub[128];
  std::snprintf(sub, sizeof sub, "zoom: %g deg square about lon %g, lat %g (gnomonic)", width, center[0], center[1]);
  c.text(0.03 * w, 0.05 * h, o.title, 15);
  c.text(0.03 * w, 0.085 * h, sub, 11, 0.75, 0.75, 0.75);
  if (!o.caption.empty()) c.text(0.03 * w, 0.98 * h, o.caption, 11, 0.7, 0.7, 0.7);
  c.save(path);
}

}  // namespace arnoldweb::detail
