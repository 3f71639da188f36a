// arnoldweb: the pictures of a run (PNG): which ones and how they are titled;
// the drawing is the plugin's (picture_plugin.hpp, lib/src/pictures/).
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
// frames.mp4 when ffmpeg is installed); the grid pictures the output table names,
// frequency_map.png, diffusion_index.png and diffusion.png where the result
// has their data. Without the pictures' plugin: none. Throws OutputError.
void write_pictures(const Plan& plan, const Result& result, const std::string& dir, std::vector<std::string>& names);


// Direction (lon, lat in degrees) the initial distribution is centred on, for
// views of ensembles that start in one place; false for "shell".
bool initial_centre(const Scene& scene, double* lon, double* lat);

// false: the pictures' plugin cannot be opened (built without cairo, or
// cairo's libraries missing on this machine); `why` says which.
bool pictures_available(std::string* why = nullptr);

// Title, caption and view of a run's pictures.
RenderOptions picture_options(const Plan& plan, const Result& result);

}  // namespace arnoldweb::detail
