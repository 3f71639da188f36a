#include "plan/checks.hpp"

#include <cmath>
#include <cstdio>

#include "arnoldweb/errors.hpp"

namespace arnoldweb::detail {

std::int64_t exact_ratio(double x, double unit) {
  const double r = x / unit;
  if (!(r < 9.0e15)) return 0;  // beyond exact integers in a double (and NaN)
  const double n = std::nearbyint(r);
  if (n < 1 || std::fabs(r - n) > 1e-9 * n) return 0;
  return static_cast<std::int64_t>(n);
}

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

}  // namespace arnoldweb::detail
