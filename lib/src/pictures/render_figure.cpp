// arnoldweb: composite figures: the main sphere with the zoom regions marked
// (a), and the zooms of the panels (b), (c), ... beside it.
#include <cmath>
#include <cstdio>

#include "arnoldweb/output.hpp"
#include "pictures/canvas.hpp"
#include "pictures/sphere_view.hpp"

namespace arnoldweb::detail {

void draw_figure_png(const std::string& path, const Plan& plan, const Result& result,
                     const std::vector<FigurePanel>& panels, const RenderOptions& o) {
  const int h = static_cast<int>(o.width * 0.62), w = static_cast<int>(o.width * (panels.empty() ? 0.7 : 1.0));
  detail::Canvas c(w, h);
  const detail::LogScale scale(result.map);
  const detail::View view(o.view_lon, o.view_lat);
  const double radius = 0.4 * h, cx = 0.06 * o.width + radius, cy = 0.53 * h;
  detail::paint_sphere(c, result.map, plan.scene.nside, view, cx, cy, radius, scale);
  if (o.resonance_order > 0) detail::draw_circles(c, view, cx, cy, radius, detail::circles_of(o));
  c.text(cx - radius, cy - radius - 8, "(a)", 14);
  c.colour_bar(cx + radius + 18, cy - 0.8 * radius, 12, 1.6 * radius, scale, "counts");
  // the panels: their zoom squares on the sphere, their histograms to the right
  const double x0 = cx + radius + 110, top = 0.1 * h;
  const int n = static_cast<int>(panels.size());
  const double side = n ? std::min((h - top - 40.0) / n - 48, w - x0 - 80.0) : 0;
  for (int k = 0; k < n; ++k) {
    const FigurePanel& p = panels[static_cast<std::size_t>(k)];
    const std::string tag = "(" + std::string(1, static_cast<char>('b' + k)) + ")";
    if (!p.plan || !p.result || p.result->zoom.empty()) continue;
    const Scene& ps = p.plan->scene;
    detail::draw_square(c, view, cx, cy, radius, ps.zoom_center, ps.zoom_width);
    const Vec3 at = direction(ps.zoom_center[0], ps.zoom_center[1]);
    if (view.z(at) > 0) c.text(cx + radius * view.x(at) + 8, cy - radius * view.y(at) - 8, tag, 13, 0.5, 1.0, 0.6);
    const double y0 = top + k * (side + 48) + 30;
    const detail::LogScale zs(p.result->zoom);
    const int res = p.plan->zoom_resolution;
    c.paint(static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(side), static_cast<int>(side),
            [&](double px, double py) {
              const int ix = static_cast<int>((px - x0) / side * res);
              const int iy = res - 1 - static_cast<int>((py - y0) / side * res);
              if (ix < 0 || iy < 0 || ix >= res || iy >= res) return -1.0;
              return zs(p.result->zoom[static_cast<std::size_t>(iy) * res + ix]);
            });
    char sub[160];
    std::snprintf(sub, sizeof sub, "%g deg square about lon %g, lat %g;  dt = %g T;  N = %.3g binned", ps.zoom_width,
                  ps.zoom_center[0], ps.zoom_center[1], ps.average, static_cast<double>(p.result->binned));
    c.text(x0, y0 - 20, tag + " " + p.title, 12, 0.9, 0.9, 0.9);
    c.text(x0, y0 - 6, sub, 10, 0.7, 0.7, 0.7);
    c.colour_bar(x0 + side + 10, y0, 10, side, zs, "");
  }
  c.text(0.02 * o.width, 0.045 * h, o.title, 15);
  if (!o.caption.empty()) c.text(0.02 * o.width, 0.985 * h, o.caption, 11, 0.7, 0.7, 0.7);
  c.save(path);
}

}  // namespace arnoldweb::detail
