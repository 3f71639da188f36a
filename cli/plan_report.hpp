// arnoldweb CLI: the plan of a scene, as `check` and `run` print it.
#pragma once

#include <ostream>
#include <string>

#include "arnoldweb/plan.hpp"

namespace arnoldweb::cli {

void print_plan(std::ostream& out, const Plan& plan, const std::string& device);
std::string short_number(double v);  // 3 significant digits

}  // namespace arnoldweb::cli
