// arnoldweb: helpers for checking a scene's values together (the planner, the
// accuracy pilot): exact ratios of durations and the error naming a key where
// its value came from.
#pragma once

#include <cstdint>
#include <string>

#include "arnoldweb/scene.hpp"

namespace arnoldweb::detail {

// n if x / unit is within rounding of an integer n >= 1 (and below 9e15), else 0.
std::int64_t exact_ratio(double x, double unit);

// Throws SceneError for `key`, reported where its value came from: the file
// position, or the option or override that gave it.
[[noreturn]] void fail_at(const Scene& s, const std::string& key, const std::string& message);

// A number for messages: 10 significant digits ("%.10g").
std::string show_number(double v);

}  // namespace arnoldweb::detail
