// arnoldweb: helpers for checking a scene's values together (the planner, the
// accuracy pilot): the error naming a key where its value came from (and
// exact ratios of durations, durations.hpp).
#pragma once

#include <cstdint>
#include <string>

#include "arnoldweb/scene.hpp"
#include "plan/durations.hpp"  // exact_ratio

namespace arnoldweb::detail {

// Throws SceneError for `key`, reported where its value came from: the file
// position, or the option or override that gave it.
[[noreturn]] void fail_at(const Scene& s, const std::string& key, const std::string& message);

// A number for messages: 10 significant digits ("%.10g"); a count: all its digits.
std::string show_number(double v);
std::string show_count(std::uint64_t n);

}  // namespace arnoldweb::detail
