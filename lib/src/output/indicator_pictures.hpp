// arnoldweb: pictures of the chaos indicators of a grid (fli.png, megno.png;
// render_indicators.cpp, docs/indicators.md).
#pragma once

#include <string>
#include <vector>

#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

// Writes fli.png and megno.png (those asked for) of a grid scene into `dir`,
// appending their names to `names`. Nothing without a grid. Throws OutputError.
void write_indicator_pictures(const Plan& plan, const Result& result, const std::string& dir,
                              std::vector<std::string>& names);

}  // namespace arnoldweb::detail
