// arnoldweb: what the pictures' plugin draws (lib/src/pictures/, linked with
// cairo). The library reaches these only through the plugin's table
// (output/picture_plugin.hpp, filled by plugin_entry.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "arnoldweb/output.hpp"
#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

// Perceptual colour map: Green's cubehelix (Bull. Astr. Soc. India 39 (2011)
// 289), luminance rising monotonically from black (t = 0) to white (t = 1).
std::array<double, 3> cubehelix(double t);

// Orthographic view of the sphere (like the paper's figures) and the
// Mollweide full-sphere image, each with its colour bar (render_sphere.cpp).
void draw_sphere_png(const std::string& path, const std::vector<std::uint64_t>& map, int nside,
                     const RenderOptions& options);
void draw_mollweide_png(const std::string& path, const std::vector<std::uint64_t>& map, int nside,
                        const RenderOptions& options);

// The R x R zoom histogram (gnomonic square about `center`, lon/lat degrees,
// full width `width` degrees) with axes in degrees and the resonance lines.
void render_zoom_png(const std::string& path, const std::vector<std::uint64_t>& zoom, int resolution,
                     const std::array<double, 2>& center, double width, const RenderOptions& options);

// The main run's sphere with its panels' regions, and each panel's zoom (render_figure.cpp).
void draw_figure_png(const std::string& path, const Plan& plan, const Result& result,
                     const std::vector<FigurePanel>& panels, const RenderOptions& options);

}  // namespace arnoldweb::detail
