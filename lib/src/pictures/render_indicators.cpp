// arnoldweb: pictures of the chaos indicators (docs/indicators.md): fli.png
// and the other pictures of a grid of initial conditions that the output
// table's datasets name (RecordDataset::picture). A healpix grid is drawn on
// the sphere of momentum directions in Mollweide projection; a lonlat or plane
// grid as an image with labelled axes. Linear colour scale between the 1st and
// 99th percentile of the finite values, with a colour bar; NaN (flagged
// trajectories) grey. For a healpix grid with a velocity map, map_and_fli.png
// puts the two views of one web side by side.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "arnoldweb/output.hpp"
#include "arnoldweb/sphere.hpp"
#include "aw_params.h"
#include "output_table/output_table.hpp"
#include "pictures/canvas.hpp"
#include "pictures/indicator_pictures.hpp"
#include "pictures/picture_table.hpp"
#include "pictures/sphere_view.hpp"

namespace arnoldweb::detail {
namespace {

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

void grey_background(Canvas& c, double x, double y, double w, double h) {
  cairo_set_source_rgb(c.cr(), 0.35, 0.35, 0.35);
  cairo_rectangle(c.cr(), x, y, w, h);
  cairo_fill(c.cr());
}

}  // namespace

void linear_bar(Canvas& c, double x, double y, double w, double h, const LinearScale& s, const std::string& label) {
  c.paint(static_cast<int>(x), static_cast<int>(y), static_cast<int>(w), static_cast<int>(h),
          [&](double px, double) { return 0.04 + 0.96 * (px - x) / w; });
  cairo_set_source_rgb(c.cr(), 0.7, 0.7, 0.7);
  cairo_set_line_width(c.cr(), 1);
  cairo_rectangle(c.cr(), x + 0.5, y + 0.5, w, h);
  cairo_stroke(c.cr());
  for (int k = 0; k <= 4; ++k) {
    const double f = k / 4.0, tx = x + w * f;
    cairo_move_to(c.cr(), tx, y + h);
    cairo_line_to(c.cr(), tx, y + h + 5);
    cairo_stroke(c.cr());
    c.text(tx, y + h + 17, fmt(s.lo + f * (s.hi - s.lo)), 11, 0.8, 0.8, 0.8, true);
  }
  c.text(x + w / 2, y - 6, label, 12, 0.9, 0.9, 0.9, true);
}

namespace {

// Real column `c` of every trajectory's record.
std::vector<double> column(const Records& rec, int c) {
  const std::size_t n = rec.count();
  std::vector<double> v(n);
  for (std::size_t t = 0; t < n; ++t) v[t] = rec.reals[t * rec.reals_per + static_cast<std::size_t>(c)];
  return v;
}

void render_healpix(const std::string& path, const std::vector<double>& v, int nside, const std::string& title,
                    const std::string& label, const std::string& caption) {
  const int w = 900, h = static_cast<int>(w * 0.62);
  Canvas c(w, h);
  const LinearScale scale(v);
  const double a = 0.45 * w, cx = 0.5 * w, cy = 0.45 * h;
  paint_mollweide(c, cx, cy, a, [&](const Vec3& d) {
    const double f = scale(v[vec2pix_ring(nside, d)]);
    return f < -1 ? 0.0 : f;
  });
  linear_bar(c, 0.25 * w, 0.86 * h, 0.5 * w, 0.025 * h, scale, label);
  c.text(0.03 * w, 0.06 * h, title, 15);
  c.text(0.03 * w, 0.985 * h,
         caption + "   Mollweide, direction of the initial momentum, longitude 0 at the centre, east to the right", 11,
         0.7, 0.7, 0.7);
  c.save(path);
}

void render_plane(const std::string& path, const std::vector<double>& v, int n1, int n2,
                  const std::array<double, 2>& r1, const std::array<double, 2>& r2, const std::string& x_label,
                  const std::string& y_label, const std::string& title, const std::string& label,
                  const std::string& caption) {
  const int w = 900, h = 960;
  Canvas c(w, h);
  const LinearScale scale(v);
  const double x0 = 90, y0 = 60, side = 720;
  const double pw = n1 >= n2 ? side : side * n1 / n2, ph = n1 >= n2 ? side * n2 / n1 : side;
  grey_background(c, x0, y0, pw, ph);
  c.paint(static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(pw), static_cast<int>(ph),
          [&](double px, double py) {
            const int i = std::clamp(static_cast<int>((px - x0) / pw * n1), 0, n1 - 1);
            const int j = std::clamp(static_cast<int>((y0 + ph - py) / ph * n2), 0, n2 - 1);  // row 0 at the bottom
            const double f = scale(v[static_cast<std::size_t>(j) * static_cast<std::size_t>(n1) + static_cast<std::size_t>(i)]);
            return f < -1 ? -1.0 : f;
          });
  cairo_set_source_rgb(c.cr(), 0.7, 0.7, 0.7);
  cairo_set_line_width(c.cr(), 1);
  cairo_rectangle(c.cr(), x0 + 0.5, y0 + 0.5, pw, ph);
  cairo_stroke(c.cr());
  for (int k = 0; k <= 4; ++k) {
    const double f = k / 4.0;
    const double tx = x0 + f * pw, ty = y0 + ph - f * ph;
    cairo_move_to(c.cr(), tx, y0 + ph);
    cairo_line_to(c.cr(), tx, y0 + ph + 5);
    cairo_move_to(c.cr(), x0 - 5, ty);
    cairo_line_to(c.cr(), x0, ty);
    cairo_stroke(c.cr());
    c.text(tx, y0 + ph + 18, fmt(r1[0] + f * (r1[1] - r1[0])), 11, 0.8, 0.8, 0.8, true);
    c.text(x0 - 48, ty + 4, fmt(r2[0] + f * (r2[1] - r2[0])), 11, 0.8, 0.8, 0.8);
  }
  c.text(x0 + pw / 2, y0 + ph + 38, x_label, 13, 0.9, 0.9, 0.9, true);
  cairo_save(c.cr());
  cairo_translate(c.cr(), 22, y0 + ph / 2);
  cairo_rotate(c.cr(), -M_PI / 2);
  c.text(0, 0, y_label, 13, 0.9, 0.9, 0.9, true);
  cairo_restore(c.cr());
  linear_bar(c, x0 + (pw - std::min(pw, 500.0)) / 2, y0 + ph + 80, std::min(pw, 500.0), 16, scale, label);
  c.text(20, 28, title, 15);
  c.text(20, h - 12, caption, 11, 0.7, 0.7, 0.7);
  c.save(path);
}

// The two views of one web: the velocity map (directions of the averaged
// velocity, log counts) beside the FLI of the healpix grid (directions of the
// initial momentum), both in Mollweide projection.
void render_map_and_fli(const std::string& path, const std::vector<std::uint64_t>& map, int map_nside,
                        const std::vector<double>& fli, int grid_nside, const std::string& title,
                        const std::string& caption) {
  const int w = 1600, h = 560;
  Canvas c(w, h);
  const LogScale counts(map);
  const LinearScale scale(fli);
  const double a = 0.235 * w, cy = 0.42 * h;
  paint_mollweide(c, 0.25 * w, cy, a, [&](const Vec3& d) { return counts(map[vec2pix_ring(map_nside, d)]); });
  paint_mollweide(c, 0.75 * w, cy, a, [&](const Vec3& d) {
    const double f = scale(fli[vec2pix_ring(grid_nside, d)]);
    return f < -1 ? 0.0 : f;
  });
  c.colour_bar(0.1 * w, 0.8 * h, 0.3 * w, 0.03 * h, counts, "");
  c.text(0.25 * w, 0.79 * h - 4, "velocity map: counts of averaged-velocity directions (log)", 12, 0.9, 0.9, 0.9, true);
  linear_bar(c, 0.6 * w, 0.8 * h, 0.3 * w, 0.03 * h, scale, "FLI of the initial momentum's direction (grid)");
  c.text(0.02 * w, 0.06 * h, title, 15);
  c.text(0.02 * w, 0.98 * h, caption + "   Mollweide, longitude 0 at the centre, east to the right", 11, 0.7, 0.7,
         0.7);
  c.save(path);
}

const char* momentum_name(double axis) { return axis == 0 ? "p1 (p_x)" : axis == 1 ? "p2 (p_y)" : "p3 (p_z)"; }

}  // namespace

double LinearScale::operator()(double x) const {
  if (!std::isfinite(x)) return -2;
  return 0.04 + 0.96 * std::clamp((x - lo) / (hi - lo), 0.0, 1.0);
}

LinearScale::LinearScale(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return;
  std::sort(v.begin(), v.end());
  lo = v[static_cast<std::size_t>(0.01 * static_cast<double>(v.size() - 1))];
  hi = v[static_cast<std::size_t>(0.99 * static_cast<double>(v.size() - 1))];
  if (!(hi > lo)) hi = lo + 1;
}

std::string picture_title(const Plan& plan) {
  const Scene& s = plan.scene;
  char title[200];
  std::snprintf(title, sizeof title, "E = %g,  t = %g T,  %s,  h = %g T", s.energy, s.duration, plan.method.name.c_str(),
                plan.step);
  return title;
}

std::string picture_caption(const Result& r) { return "arnoldweb on " + r.device.id + " (" + r.device.name + ")"; }

void write_grid_picture(const Plan& plan, const Result& r, const std::string& path, const std::vector<double>& v,
                        const std::string& label) {
  const Scene& s = plan.scene;
  const std::string title = label + "   " + picture_title(plan), caption = picture_caption(r);
  if (s.grid_kind == "healpix") {
    render_healpix(path, v, s.grid_nside, title, label, caption);
  } else if (s.grid_kind == "lonlat") {
    render_plane(path, v, static_cast<int>(s.grid_resolution[0]), static_cast<int>(s.grid_resolution[1]), s.box_lon,
                 s.box_lat, "longitude of P, degrees", "latitude of P, degrees", title, label, caption);
  } else {
    render_plane(path, v, static_cast<int>(s.grid_resolution[0]), static_cast<int>(s.grid_resolution[1]),
                 s.grid_range1, s.grid_range2, momentum_name(s.grid_axes[0]), momentum_name(s.grid_axes[1]), title,
                 label, caption);
  }
}

namespace {
bool draw_map_and_fli(const Plan& plan, const Result& r, const Records& ind, const std::string& path) {
  const Scene& s = plan.scene;
  if (!s.observes("observe.fli") || ind.reals.empty() || s.grid_kind != "healpix" || r.map.empty() || r.nside <= 0)
    return false;
  render_map_and_fli(path, r.map, r.nside, column(ind, AW_IND_FLI), s.grid_nside, picture_title(plan),
                     picture_caption(r));
  return true;
}
}  // namespace

// the velocity map beside the FLI of a healpix grid (observe.fli)
const PictureRegistration map_and_fli_row({"map_and_fli", "map_and_fli.png", true, draw_map_and_fli});

void write_dataset_pictures(const Plan& plan, const Result& r, const std::string& dir, std::vector<std::string>& names) {
  if (plan.scene.initial != "grid") return;
  // every dataset of the output table that names a picture, where the run wrote it, drawn as its
  // file holds it (output_datasets: a log10 dataset as its logarithm; non-finite values are left blank)
  const std::vector<OutputDataset> written = output_datasets(plan, r);
  for (const RecordOutput* row : records_reported(plan.kernel.features))
    for (const RecordDataset& d : row->datasets) {
      if (d.picture.empty() || d.integers) continue;
      const auto o = std::find_if(written.begin(), written.end(),
                                  [&](const OutputDataset& w) { return w.output == row->name && w.name == d.name; });
      if (o == written.end() || o->reals.empty()) continue;
      write_grid_picture(plan, r, dir + "/" + d.picture, o->reals, d.picture_label);
      names.push_back(d.picture);
    }
}

}  // namespace arnoldweb::detail
