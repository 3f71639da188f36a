// arnoldweb: the pictures of the analyses (analysis_files.hpp,
// docs/frequencies.md) and of the picked orbits, each registered here as a row
// of the picture table (picture_table.hpp).
//  frequency_map.png  every trajectory as a point (nu_x, nu_y) of its first
//                     window, coloured by its diffusion index log10 |dnu|;
//                     where points share a pixel the largest index shows, so
//                     that the chaotic layers of the resonances stand out.
//  diffusion_index.png the index over the grid of initial conditions.
//  diffusion.png      Var[e . dI](t) along and across the resonance with the
//                     fitted line sigma0^2 + 2 D t, D with its error bar, and
//                     the growth's linearity: the halves' D, the exponent
//                     alpha (in red where the fit is not diffusive).
//  trajectories.png   the picked orbits (observe.trajectories): each one's
//                     momentum in action space (p_x, p_y), its direction on
//                     the sphere (longitude, latitude of P / |P|), and
//                     log10 |E(t) - E(0)| against t.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "aw_params.h"
#include "pictures/drawing.hpp"
#include "pictures/canvas.hpp"
#include "pictures/indicator_pictures.hpp"
#include "pictures/picture_table.hpp"
#include "plan/plan_params.hpp"

namespace arnoldweb::detail {
namespace {

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

// The value range of the finite values between two quantiles, widened by 3 %.
std::array<double, 2> quantile_range(std::vector<double> v, double q) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return {0, 1};
  std::sort(v.begin(), v.end());
  double lo = v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
  double hi = v[static_cast<std::size_t>((1 - q) * static_cast<double>(v.size() - 1))];
  if (!(hi > lo)) lo -= 0.5, hi += 0.5;
  const double m = 0.03 * (hi - lo);
  return {lo - m, hi + m};
}

void frame(Canvas& c, double x0, double y0, double w, double h, const std::array<double, 2>& rx,
           const std::array<double, 2>& ry, const std::string& x_label, const std::string& y_label) {
  cairo_t* cr = c.cr();
  cairo_set_source_rgb(cr, 0.7, 0.7, 0.7);
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, x0 + 0.5, y0 + 0.5, w, h);
  cairo_stroke(cr);
  for (int k = 0; k <= 4; ++k) {
    const double f = k / 4.0, tx = x0 + f * w, ty = y0 + h - f * h;
    cairo_move_to(cr, tx, y0 + h);
    cairo_line_to(cr, tx, y0 + h + 5);
    cairo_move_to(cr, x0 - 5, ty);
    cairo_line_to(cr, x0, ty);
    cairo_stroke(cr);
    c.text(tx, y0 + h + 18, fmt(rx[0] + f * (rx[1] - rx[0])), 11, 0.8, 0.8, 0.8, true);
    c.text(x0 - 62, ty + 4, fmt(ry[0] + f * (ry[1] - ry[0])), 11, 0.8, 0.8, 0.8);
  }
  c.text(x0 + w / 2, y0 + h + 38, x_label, 13, 0.9, 0.9, 0.9, true);
  cairo_save(cr);
  cairo_translate(cr, x0 - 72, y0 + h / 2);
  cairo_rotate(cr, -M_PI / 2);
  c.text(0, 0, y_label, 13, 0.9, 0.9, 0.9, true);
  cairo_restore(cr);
}

std::vector<double> diffusion_index(const Records& rec) {
  std::vector<double> v(rec.count());
  for (std::size_t t = 0; t < v.size(); ++t) v[t] = std::log10(rec.reals[t * rec.reals_per + 6]);
  return v;
}

void render_frequency_map(const Plan& plan, const Result& r, const Records& rec, const std::string& path) {
  const std::size_t n = rec.count();
  std::vector<double> nx(n), ny(n);
  for (std::size_t t = 0; t < n; ++t) nx[t] = rec.reals[t * rec.reals_per], ny[t] = rec.reals[t * rec.reals_per + 1];
  const std::vector<double> index = diffusion_index(rec);
  const std::array<double, 2> rx = quantile_range(nx, 0.001), ry = quantile_range(ny, 0.001);
  const LinearScale scale(index);
  const int w = 900, h = 960, side = 720;
  const double x0 = 110, y0 = 60;
  std::vector<double> raster(static_cast<std::size_t>(side) * side, -1);
  // a sparse map draws its points larger: about a third of their spacing
  const int dot = std::clamp(static_cast<int>(side / std::sqrt(static_cast<double>(n) + 1) / 3), 1, 4);
  for (std::size_t t = 0; t < n; ++t) {
    if (!std::isfinite(nx[t]) || !std::isfinite(ny[t])) continue;
    const double fx = (nx[t] - rx[0]) / (rx[1] - rx[0]), fy = (ny[t] - ry[0]) / (ry[1] - ry[0]);
    if (fx < 0 || fx >= 1 || fy < 0 || fy >= 1) continue;
    const int pi = static_cast<int>(fx * side), pj = static_cast<int>((1 - fy) * side);
    const double f = std::isfinite(index[t]) ? scale(index[t]) : 0.04;  // no change at all: the scale's foot
    for (int j = pj; j < std::min(pj + dot, side); ++j)
      for (int i = pi; i < std::min(pi + dot, side); ++i) {
        double& at = raster[static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i)];
        at = std::max(at, f);
      }
  }
  Canvas c(w, h);
  c.paint(static_cast<int>(x0), static_cast<int>(y0), side, side, [&](double px, double py) {
    const int i = std::clamp(static_cast<int>(px - x0), 0, side - 1), j = std::clamp(static_cast<int>(py - y0), 0, side - 1);
    return raster[static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i)];
  });
  frame(c, x0, y0, side, side, rx, ry, "nu_x (turns per T, first window)", "nu_y (turns per T, first window)");
  linear_bar(c, x0 + (side - 500) / 2.0, y0 + side + 80, 500, 16, scale, "diffusion index log10 ||nu(2)| - |nu(1)||");
  c.text(20, 28, "frequency map   " + picture_title(plan), 15);
  c.text(20, h - 12, picture_caption(r), 11, 0.7, 0.7, 0.7);
  c.save(path);
}

void curve(Canvas& c, double x0, double y0, double w, double h, const std::array<double, 2>& rx,
           const std::array<double, 2>& ry, const std::vector<double>& x, const std::vector<double>& y) {
  cairo_t* cr = c.cr();
  bool pen = false;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (!std::isfinite(y[k])) {
      pen = false;
      continue;
    }
    const double px = x0 + (x[k] - rx[0]) / (rx[1] - rx[0]) * w, py = y0 + h - (y[k] - ry[0]) / (ry[1] - ry[0]) * h;
    if (pen) cairo_line_to(cr, px, py);
    else cairo_move_to(cr, px, py);
    pen = true;
  }
  cairo_stroke(cr);
}

double number(const nlohmann::json& v) { return v.is_number() ? v.get<double>() : NAN; }

void diffusion_panel(Canvas& c, double x0, double y0, double w, double h, const nlohmann::json& j,
                     const char* variance, const char* fit, const std::string& label) {
  const nlohmann::json& m = j["moments"];
  std::vector<double> t, v;
  for (std::size_t k = 0; k < m["t"].size(); ++k) t.push_back(number(m["t"][k])), v.push_back(number(m[variance][k]));
  std::vector<double> all = v;
  all.push_back(0);
  const std::array<double, 2> rx = {t.front(), t.back()}, ry = quantile_range(all, 0);
  frame(c, x0, y0, w, h, rx, ry, "t (T)", label);
  cairo_save(c.cr());
  cairo_rectangle(c.cr(), x0, y0, w, h);
  cairo_clip(c.cr());
  cairo_set_line_width(c.cr(), 2);
  cairo_set_source_rgb(c.cr(), 0.95, 0.75, 0.3);
  curve(c, x0, y0, w, h, rx, ry, t, v);
  const nlohmann::json& f = j[fit];
  const double t0 = std::max(t.front(), number(j["fit_from"]) + t.front());
  std::vector<double> ft = {t0, t.back()}, fv = {number(f["intercept"]) + number(f["slope"]) * t0,
                                                 number(f["intercept"]) + number(f["slope"]) * t.back()};
  cairo_set_line_width(c.cr(), 1.5);
  cairo_set_source_rgb(c.cr(), 0.4, 0.8, 1.0);
  const double dashes[] = {6, 4};
  cairo_set_dash(c.cr(), dashes, 2, 0);
  curve(c, x0, y0, w, h, rx, ry, ft, fv);
  cairo_restore(c.cr());
  c.text(x0 + 10, y0 + 20, "D = " + fmt(number(f["D"])) + " +- " + fmt(number(f["D_error"])) + "  (fit from t = " +
                               fmt(t0) + ")", 12, 0.4, 0.8, 1.0);
  // the linearity of the growth: the halves' D and the exponent of Var - sigma0^2 ~ t^alpha
  const double alpha = number(f.value("alpha", nlohmann::json()));
  const bool diffusive = f.value("diffusive", true);
  c.text(x0 + 10, y0 + 38,
         "halves: D = " + fmt(number(f.value("D_first_half", nlohmann::json()))) + ", " +
             fmt(number(f.value("D_second_half", nlohmann::json()))) + ";  growth ~ t^" +
             (std::isfinite(alpha) ? fmt(alpha) + " +- " + fmt(number(f.value("alpha_error", nlohmann::json())))
                                   : std::string("? (a half does not grow)")) +
             (diffusive ? "" : "   NOT DIFFUSIVE"),
         12, diffusive ? 0.4 : 1.0, diffusive ? 0.8 : 0.45, diffusive ? 1.0 : 0.35);
}

void render_diffusion(const Plan& plan, const Result& r, const nlohmann::json& j, const std::string& path) {
  const int w = 1400, h = 620;
  Canvas c(w, h);
  diffusion_panel(c, 110, 70, 520, 440, j, "along_variance", "along_fit", "Var[e_along . dI]");
  diffusion_panel(c, 820, 70, 520, 440, j, "across_variance", "across_fit", "Var[e_across . dI]");
  c.text(20, 28,
         "diffusion of the actions along and across the resonance (" + std::to_string(j.value("trajectories", 0)) +
             " trajectories)   " + picture_title(plan),
         15);
  c.text(20, h - 30, "orange: the ensemble's variance at the sample times;  dashed: sigma0^2 + 2 D t by least squares; "
                     "error: bootstrap over trajectories", 11, 0.8, 0.8, 0.8);
  c.text(20, h - 12, picture_caption(r), 11, 0.7, 0.7, 0.7);
  c.save(path);
}

// The colour of orbit k of n.
std::array<double, 3> orbit_colour(std::size_t k, std::size_t n) {
  const double hue = n > 1 ? static_cast<double>(k) / static_cast<double>(n - 1) : 0.0;
  return {0.3 + 0.65 * hue, 0.85 - 0.45 * hue, 1.0 - 0.7 * hue};
}

// The picked orbits as curves (x, y): `samples` values of each, one orbit after the other.
void orbit_panel(Canvas& c, double x0, double y0, double w, double h, std::size_t samples, const std::vector<double>& x,
                 const std::vector<double>& y, const std::string& x_label, const std::string& y_label) {
  const std::array<double, 2> rx = quantile_range(x, 0), ry = quantile_range(y, 0);
  frame(c, x0, y0, w, h, rx, ry, x_label, y_label);
  cairo_save(c.cr());
  cairo_rectangle(c.cr(), x0, y0, w, h);
  cairo_clip(c.cr());
  cairo_set_line_width(c.cr(), 1.5);
  const std::size_t picks = x.size() / samples;
  for (std::size_t k = 0; k < picks; ++k) {
    const std::array<double, 3> colour = orbit_colour(k, picks);
    cairo_set_source_rgb(c.cr(), colour[0], colour[1], colour[2]);
    const auto from = static_cast<std::ptrdiff_t>(k * samples), to = from + static_cast<std::ptrdiff_t>(samples);
    curve(c, x0, y0, w, h, rx, ry, std::vector<double>(x.begin() + from, x.begin() + to),
          std::vector<double>(y.begin() + from, y.begin() + to));
  }
  cairo_restore(c.cr());
}

void render_trajectories(const Plan& plan, const Result& r, const Records& rec, const std::string& path) {
  const IntParams& ip = params(plan).ints;
  const auto samples = static_cast<std::size_t>(ip.pick_samples) + 1;
  const double every = plan.scene.output_value("observe.trajectories.every").at(0);
  std::vector<double> px, py, lon, lat, t, de;
  for (std::size_t m = 0; m < rec.count(); ++m) {
    const double* v = &rec.reals[m * rec.reals_per];
    const double norm = std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
    px.push_back(v[3]), py.push_back(v[4]);
    lon.push_back(std::atan2(v[4], v[3]) * 180 / M_PI), lat.push_back(std::asin(v[5] / norm) * 180 / M_PI);
    t.push_back(static_cast<double>(m % samples) * every);
    de.push_back(std::log10(std::fabs(v[6])));
  }
  const int w = 1800, h = 640;
  Canvas c(w, h);
  orbit_panel(c, 110, 70, 440, 440, samples, px, py, "p_x", "p_y");
  orbit_panel(c, 700, 70, 440, 440, samples, lon, lat, "longitude of P (degrees)", "latitude of P (degrees)");
  orbit_panel(c, 1290, 70, 440, 440, samples, t, de, "t (T)", "log10 |E(t) - E(0)|");
  const std::vector<std::int64_t> ids(ip.pick_ids, ip.pick_ids + ip.pick_count);
  c.text(20, 28, "orbits of " + std::to_string(ids.size()) + " trajectories, every " + fmt(every) + " T   " +
                     picture_title(plan), 15);
  for (std::size_t k = 0; k < ids.size() && k < 40; ++k) {  // which colour is which trajectory
    const std::array<double, 3> colour = orbit_colour(k, ids.size());
    c.text(110 + 110.0 * static_cast<double>(k % 15), h - 56 + 16.0 * static_cast<double>(k / 15),
           "#" + std::to_string(ids[k]), 12, colour[0], colour[1], colour[2]);
  }
  c.text(20, h - 12, picture_caption(r), 11, 0.7, 0.7, 0.7);
  c.save(path);
}

bool draw_frequency_map(const Plan& plan, const Result& r, const Records& rec, const std::string& path) {
  render_frequency_map(plan, r, rec, path);
  return true;
}

bool draw_diffusion_index(const Plan& plan, const Result& r, const Records& rec, const std::string& path) {
  write_grid_picture(plan, r, path, diffusion_index(rec), "diffusion index log10 ||nu(2)| - |nu(1)||");
  return true;
}

bool draw_diffusion(const Plan& plan, const Result& r, const Records&, const std::string& path) {
  const auto it = r.analyses.find("diffusion");
  if (it == r.analyses.end()) return false;
  const nlohmann::json j = nlohmann::json::parse(it->second);
  if (!j.contains("moments") || !j.contains("along_fit")) return false;
  render_diffusion(plan, r, j, path);
  return true;
}

bool draw_orbits(const Plan& plan, const Result& r, const Records& rec, const std::string& path) {
  render_trajectories(plan, r, rec, path);
  return true;
}

}  // namespace

// every trajectory at its first window's (nu_x, nu_y), coloured by its diffusion index
const PictureRegistration frequency_map_row({"frequency_map", "frequency_map.png", false, draw_frequency_map});
const PictureRegistration diffusion_index_row({"diffusion_index", "diffusion_index.png", true, draw_diffusion_index});
// the variance of the actions along and across the resonance with the fit of D
const PictureRegistration diffusion_row({"diffusion", "diffusion.png", false, draw_diffusion});
// the picked orbits: momentum, direction and energy error
const PictureRegistration orbits_row({"orbits", "trajectories.png", false, draw_orbits});

}  // namespace arnoldweb::detail
