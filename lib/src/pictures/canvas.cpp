#include "pictures/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "arnoldweb/errors.hpp"
#include "output/atomic_file.hpp"
#include "pictures/drawing.hpp"

namespace arnoldweb::detail {

LogScale::LogScale(const std::vector<std::uint64_t>& counts) {
  std::uint64_t smallest = 0, largest = 0;
  for (auto c : counts)
    if (c) {
      smallest = smallest ? std::min(smallest, c) : c;
      largest = std::max(largest, c);
    }
  if (largest) {
    lo = std::log10(static_cast<double>(smallest));
    hi = std::log10(static_cast<double>(largest));
    if (hi - lo < 1e-9) lo = hi - 1;
  }
}

double LogScale::operator()(std::uint64_t count) const {
  if (!count) return 0;
  // positive counts start above black, so an empty pixel stands out
  const double t = (std::log10(static_cast<double>(count)) - lo) / (hi - lo);
  return 0.08 + 0.92 * std::clamp(t, 0.0, 1.0);
}

Canvas::Canvas(int width, int height)
    : width_(width),
      height_(height),
      surface_(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height)),
      cr_(cairo_create(surface_)) {
  cairo_set_source_rgb(cr_, 0.06, 0.06, 0.08);
  cairo_paint(cr_);
}

Canvas::~Canvas() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

void Canvas::paint(int x0, int y0, int w, int h, const std::function<double(double, double)>& value,
                   int samples) {
  cairo_surface_flush(surface_);
  unsigned char* data = cairo_image_surface_get_data(surface_);
  const int stride = cairo_image_surface_get_stride(surface_);
  for (int py = y0; py < y0 + h && py < height_; ++py)
    for (int px = x0; px < x0 + w && px < width_; ++px) {
      double acc[3] = {0, 0, 0};
      int hit = 0;
      for (int sy = 0; sy < samples; ++sy)
        for (int sx = 0; sx < samples; ++sx) {
          const double v = value(px + (sx + 0.5) / samples, py + (sy + 0.5) / samples);
          if (v < 0) continue;
          const auto c = cubehelix(v);
          for (int k = 0; k < 3; ++k) acc[k] += c[k];
          ++hit;
        }
      if (!hit) continue;
      std::uint32_t* pixel = reinterpret_cast<std::uint32_t*>(data + py * stride) + px;
      const double bg[3] = {((*pixel >> 16) & 255) / 255.0, ((*pixel >> 8) & 255) / 255.0, (*pixel & 255) / 255.0};
      const double cover = static_cast<double>(hit) / (samples * samples);
      std::uint32_t out = 0;
      for (int k = 0; k < 3; ++k) {
        const double v = acc[k] / hit * cover + bg[k] * (1 - cover);
        out = (out << 8) | static_cast<std::uint32_t>(std::lround(255 * std::clamp(v, 0.0, 1.0)));
      }
      *pixel = out;
    }
  cairo_surface_mark_dirty(surface_);
}

void Canvas::colour_bar(double x, double y, double w, double h, const LogScale& scale, const std::string& label) {
  const bool horizontal = w > h;
  paint(static_cast<int>(x), static_cast<int>(y), static_cast<int>(w), static_cast<int>(h),
        [&](double px, double py) {
          return 0.08 + 0.92 * (horizontal ? (px - x) / w : 1 - (py - y) / h);
        });
  cairo_set_source_rgb(cr_, 0.7, 0.7, 0.7);
  cairo_set_line_width(cr_, 1);
  cairo_rectangle(cr_, x + 0.5, y + 0.5, w, h);
  cairo_stroke(cr_);
  // ticks at whole decades (and 2x, 5x when the range is short)
  const double span = scale.hi - scale.lo;
  for (int e = static_cast<int>(std::floor(scale.lo)); e <= static_cast<int>(std::ceil(scale.hi)); ++e)
    for (double m : {1.0, 2.0, 5.0}) {
      if (m != 1.0 && span > 2.5) continue;
      const double v = e + std::log10(m);
      if (v < scale.lo - 1e-9 || v > scale.hi + 1e-9) continue;
      const double f = (v - scale.lo) / span;
      char buf[32];
      const double value = m * std::pow(10.0, e);
      if (value >= 1e4)
        std::snprintf(buf, sizeof buf, "%.0e", value);
      else
        std::snprintf(buf, sizeof buf, "%g", value);
      cairo_set_source_rgb(cr_, 0.7, 0.7, 0.7);
      if (horizontal) {
        const double tx = x + w * f;
        cairo_move_to(cr_, tx, y + h);
        cairo_line_to(cr_, tx, y + h + 5);
        cairo_stroke(cr_);
        text(tx, y + h + 17, buf, 11, 0.8, 0.8, 0.8, true);
      } else {
        const double ty = y + h * (1 - f);
        cairo_move_to(cr_, x + w, ty);
        cairo_line_to(cr_, x + w + 5, ty);
        cairo_stroke(cr_);
        text(x + w + 8, ty + 4, buf, 11, 0.8, 0.8, 0.8);
      }
    }
  if (!label.empty()) text(x + w / 2, y - 10, label, 11, 0.8, 0.8, 0.8, true);
}

void Canvas::text(double x, double y, const std::string& s, double size, double r, double g, double b,
                  bool centred) {
  cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr_, size);
  cairo_text_extents_t ext;
  cairo_text_extents(cr_, s.c_str(), &ext);
  cairo_set_source_rgb(cr_, r, g, b);
  cairo_move_to(cr_, centred ? x - ext.width / 2 - ext.x_bearing : x, y);
  cairo_show_text(cr_, s.c_str());
}

void Canvas::save(const std::string& path) {
  // encoded in memory, then written with every write checked (full disk)
  std::string png;
  const cairo_status_t st = cairo_surface_write_to_png_stream(
      surface_,
      [](void* closure, const unsigned char* data, unsigned int length) {
        static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
        return CAIRO_STATUS_SUCCESS;
      },
      &png);
  if (st != CAIRO_STATUS_SUCCESS)
    throw OutputError(path, std::string("cannot encode the PNG: ") + cairo_status_to_string(st));
  write_file_atomically(path, png);
}

}  // namespace arnoldweb::detail
