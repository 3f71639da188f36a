// arnoldweb: the pictures of a run (PNG, through cairo), and the colour map.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "arnoldweb/output.hpp"
#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

// Writes the pictures the result has data for into `dir` and appends their
// names (relative to dir) to `names` as each is complete: map.png,
// map_mollweide.png, map_resonances.png, zoom.png, frames/frame_NNN.png (and
// frames.mp4 when ffmpeg is installed). Without cairo in the build: none.
// Throws OutputError.
void write_pictures(const Plan& plan, const Result& result, const std::string& dir, std::vector<std::string>& names);

// Perceptual colour map: Green's cubehelix (Bull. Astr. Soc. India 39 (2011)
// 289), luminance rising monotonically from black (t = 0) to white (t = 1).
std::array<double, 3> cubehelix(double t);

}  // namespace arnoldweb::detail

namespace arnoldweb::detail {

// The R x R zoom histogram (gnomonic square about `center`, lon/lat degrees,
// full width `width` degrees) with axes in degrees and the resonance lines.
void render_zoom_png(const std::string& path, const std::vector<std::uint64_t>& zoom, int resolution,
                     const std::array<double, 2>& center, double width, const arnoldweb::RenderOptions& options);

// Direction (lon, lat in degrees) the initial distribution is centred on, for
// views of ensembles that start in one place; false for "shell".
bool initial_centre(const Scene& scene, double* lon, double* lat);

bool pictures_available();  // false: built without cairo

// Title, caption and view of a run's pictures.
RenderOptions picture_options(const Plan& plan, const Result& result);

}  // namespace arnoldweb::detail
