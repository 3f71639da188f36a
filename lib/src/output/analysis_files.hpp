// arnoldweb: the files of the analyses of a finished run (Result::analyses,
// docs/frequencies.md): diffusion.csv (text) and the pictures
// frequency_map.png, diffusion_index.png and diffusion.png (cairo).
#pragma once

#include <string>
#include <vector>

#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

// The moments of the diffusion analysis, one row per sample time:
// t,along_mean,along_variance,across_variance (empty cells: not finite).
// Empty without a diffusion analysis with moments.
std::string diffusion_csv(const Result& result);

// Writes frequency_map.png and diffusion_index.png (a grid scene) of a run
// with observe.frequencies, and diffusion.png of one with a diffusion
// analysis, into `dir`; appends their names to `names`. Throws OutputError.
void write_analysis_pictures(const Plan& plan, const Result& result, const std::string& dir,
                             std::vector<std::string>& names);

}  // namespace arnoldweb::detail
