// arnoldweb tests: the emitted device code of a potential against its copy in
// tests/physics/expression_golden/, which the tests compile into the host
// program. When the emitter changes, the test writes the new text beside the
// test binary and says which file to replace.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

#include "physics/expression/potential.hpp"

namespace awtest {

inline std::string golden_path(const std::string& name) {
  return std::string(ARNOLDWEB_SOURCE_DIR) + "/tests/physics/expression_golden/" + name;
}

// "" when the file holds exactly `text`; otherwise what to do.
inline std::string golden_mismatch(const std::string& name, const std::string& text) {
  std::ifstream in(golden_path(name), std::ios::binary);
  std::ostringstream held;
  held << in.rdbuf();
  if (in && held.str() == text) return "";
  const std::string fresh = name + ".new";
  std::ofstream(fresh, std::ios::binary) << text;
  return "the emitted code differs from " + golden_path(name) + ": review and copy " + fresh + " over it";
}

}  // namespace awtest
