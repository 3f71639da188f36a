// arnoldweb: the files of the analyses of a finished run (Result::analyses,
// docs/frequencies.md): diffusion.csv (text); their pictures are drawn by
// the pictures' plugin (pictures/drawing.hpp).
#pragma once

#include <string>
#include <vector>

#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

// The moments of the diffusion analysis, one row per sample time:
// t,along_mean,along_variance,across_variance, then for along and across the
// fit's D, D_error, D_first_half, D_second_half, alpha, alpha_error (the same
// on every row; empty cells: not finite). Empty without a diffusion analysis
// with moments.
std::string diffusion_csv(const Result& result);

}  // namespace arnoldweb::detail
