// arnoldweb: the colour map of every picture.
#include <algorithm>
#include <cmath>

#include "pictures/drawing.hpp"

namespace arnoldweb::detail {

std::array<double, 3> cubehelix(double t) {
  // start colour 3.0, +0.5 rotations, saturation 2.2, gamma 1: black through
  // indigo, magenta and orange to cream (close to the look of "magma"), with
  // luminance rising linearly, so log density reads as brightness.
  const double start = 3.0, rotations = 0.5, hue = 2.2;
  t = std::clamp(t, 0.0, 1.0);
  const double phi = 2 * M_PI * (start / 3 + 1 + rotations * t);
  const double amp = hue * t * (1 - t) / 2;
  const double c = std::cos(phi), s = std::sin(phi);
  std::array<double, 3> rgb = {t + amp * (-0.14861 * c + 1.78277 * s), t + amp * (-0.29227 * c - 0.90649 * s),
                               t + amp * (1.97294 * c)};
  for (double& v : rgb) v = std::clamp(v, 0.0, 1.0);
  return rgb;
}

}  // namespace arnoldweb::detail
