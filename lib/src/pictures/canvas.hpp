// arnoldweb: drawing helpers over cairo shared by the pictures: pixel images
// from a colour function, a logarithmic colour bar, text, PNG files written
// atomically.
#pragma once

#include <cairo.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace arnoldweb::detail {

// Maps counts to [0, 1] on a log scale between the smallest positive count
// and the largest; 0 counts map to 0 (the colour map's black).
struct LogScale {
  double lo = 0, hi = 1;  // log10 of the smallest positive and the largest count
  explicit LogScale(const std::vector<std::uint64_t>& counts);
  double operator()(std::uint64_t count) const;
};

class Canvas {
 public:
  Canvas(int width, int height);  // dark background
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  cairo_t* cr() { return cr_; }

  // Colours every pixel of the rectangle for which value(px, py) >= 0 with the
  // colour map at that value; -1 leaves the background. `samples` per axis
  // antialias the edges.
  void paint(int x0, int y0, int w, int h, const std::function<double(double, double)>& value, int samples = 1);
  void colour_bar(double x, double y, double w, double h, const LogScale& scale, const std::string& label);
  void text(double x, double y, const std::string& s, double size, double r = 0.92, double g = 0.92,
            double b = 0.92, bool centred = false);
  // Writes a PNG atomically (OutputError on failure).
  void save(const std::string& path);

 private:
  int width_, height_;
  cairo_surface_t* surface_;
  cairo_t* cr_;
};

}  // namespace arnoldweb::detail
