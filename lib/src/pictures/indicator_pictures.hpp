// arnoldweb: pictures of per-trajectory values over a grid of initial
// conditions (those the output table names, diffusion_index.png; render_indicators.cpp,
// docs/indicators.md), and what other pictures of values share: a linear
// colour scale between percentiles with its bar.
#pragma once

#include <string>
#include <vector>

#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

class Canvas;

// A linear colour scale between the 1st and 99th percentile of the finite values.
struct LinearScale {
  double lo = 0, hi = 1;
  explicit LinearScale(std::vector<double> v);
  // colour-map position; NaN: -2 (drawn grey by the caller)
  double operator()(double x) const;
};
void linear_bar(Canvas& c, double x, double y, double w, double h, const LinearScale& s, const std::string& label);

// The title and the caption of a run's pictures.
std::string picture_title(const Plan& plan);
std::string picture_caption(const Result& r);

// One value per trajectory of a grid scene (ensemble.initial = "grid"), drawn
// over the grid: Mollweide for a healpix grid, an image with axes otherwise.
void write_grid_picture(const Plan& plan, const Result& r, const std::string& path, const std::vector<double>& values,
                        const std::string& label);

}  // namespace arnoldweb::detail
