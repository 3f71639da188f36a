#include "plan/checks.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "arnoldweb/errors.hpp"

namespace arnoldweb::detail {

namespace {

// Whether `text` names `key` as a whole key ("integrator.step", not "integrator.step_x").
bool names_key(const std::string& text, const std::string& key) {
  auto part_of_key = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1)) {
    const std::size_t end = at + key.size();
    const bool starts = at == 0 || !(part_of_key(text[at - 1]) || text[at - 1] == '.');
    const bool ends = end == text.size() || !(part_of_key(text[end]) ||
                                              (text[end] == '.' && end + 1 < text.size() && part_of_key(text[end + 1])));
    if (starts && ends) return true;
  }
  return false;
}

}  // namespace

void fail_at(const Scene& s, const std::string& key, const std::string& message) {
  const SourcePos p = s.pos(key);
  if (p.set_index > 0) throw SceneError(s.origin(key), 0, 0, key, message);
  // Values wrong together, where the message names another key that an override
  // (--set, Scene.set) gave: the error is placed at the latest such override,
  // and says where `key`'s own value comes from.
  const std::string* set_key = nullptr;
  int latest = 0;
  for (const auto& [other, at] : s.where)
    if (at.set_index > latest && other != key && names_key(message, other)) {
      latest = at.set_index;
      set_key = &other;
    }
  if (set_key)
    throw SceneError(s.origin(*set_key), 0, 0, key,
                     message + " (" + key + " " + (p.line > 0 ? "as written at " + s.origin(key) : "by default") + ")");
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
