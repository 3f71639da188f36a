#include "plan/checks.hpp"

#include <cmath>
#include <cstdio>

#include "arnoldweb/errors.hpp"

namespace arnoldweb::detail {

void fail_at(const Scene& s, const std::string& key, const std::string& message) {
  const SourcePos p = s.pos(key);
  if (p.set_index > 0) throw SceneError(s.origin(key), 0, 0, key, message);
  throw SceneError(s.file, p.line, p.column, key, message);
}

std::string show_number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string show_count(std::uint64_t n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%llu", static_cast<unsigned long long>(n));
  return buf;
}

}  // namespace arnoldweb::detail
