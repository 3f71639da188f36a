// arnoldweb: what is computed from a run's records once it has ended
// (Result::analyses): the diffusion analysis of observe.diffusion (the moments
// of the action displacement along and across the resonance at every sample
// time, the diffusion coefficients with their bootstrap error bars;
// arnoldweb/diffusion.hpp), as JSON for summary.json, the CSV and the picture.
#pragma once

#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

// Fills result.analyses for the analyses the plan asks for (none: nothing).
void analyse(const Plan& plan, Result& result);

}  // namespace arnoldweb::detail
