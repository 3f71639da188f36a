// arnoldweb: helpers the planner and the accuracy pilot share when they check
// a scene's values together.
#pragma once

#include <cstdint>
#include <string>

#include "arnoldweb/scene.hpp"

namespace arnoldweb::detail {

// n if x / unit is within rounding of an integer n >= 1, else 0.
std::int64_t exact_ratio(double x, double unit);

// Throws SceneError for `key`, reported where its value came from: the file
// position, or the --set override that gave it.
[[noreturn]] void fail_at(const Scene& s, const std::string& key, const std::string& message);

}  // namespace arnoldweb::detail
