// arnoldweb: access to the embedded kernel sources.
#include "backends/kernel_sources.hpp"

#include <algorithm>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace arnoldweb::detail {
namespace {

std::string dirname_of(const std::string& name) {
  auto p = name.rfind('/');
  return p == std::string::npos ? std::string() : name.substr(0, p + 1);
}

using Extra = std::vector<std::pair<std::string, std::string>>;

const std::string* extra_file(const std::string& name, const Extra& extra) {
  for (const auto& [n, text] : extra)
    if (n == name) return &text;
  return nullptr;
}

// The embedded (or extra) name an include refers to, or "" if there is none.
std::string resolve(const std::string& target, const std::string& from, const Extra& extra) {
  for (const std::string& candidate :
       {dirname_of(from) + target, target, "Random123/" + target}) {
    if (extra_file(candidate, extra)) return candidate;
    for (const auto& [name, text] : embedded_kernel_sources())
      if (candidate == name) return candidate;
  }
  return "";
}

// `open`: the files whose expansion is in progress, outermost first. An include
// of one of them is left out: every header guards itself from its first line,
// so including it again from within yields nothing (the effect headers and
// aw_params.h include each other through the generated
// effects/aw_effect_declarations.h: a cycle the preprocessor's guards end).
void flatten_into(const std::string& name, std::ostringstream& out, std::vector<std::string>& open,
                  const Extra& extra) {
  if (open.size() > 32) throw std::runtime_error("kernel sources: include nesting too deep at " + name);
  open.push_back(name);
  static const std::regex include_re(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"].*$)");
  const std::string* own = extra_file(name, extra);
  std::istringstream in{own ? *own : std::string(embedded_file(name))};
  std::string line;
  out << "#line 1 \"" << name << "\"\n";
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    std::smatch m;
    if (std::regex_match(line, m, include_re)) {
      const std::string target = resolve(m[1].str(), name, extra);
      if (!target.empty()) {
        if (std::find(open.begin(), open.end(), target) == open.end()) {
          flatten_into(target, out, open, extra);
          out << "#line " << lineno + 1 << " \"" << name << "\"\n";
        } else {
          out << '\n';  // the line numbers go on
        }
        continue;
      }
    }
    out << line << '\n';
  }
  open.pop_back();
}

}  // namespace

std::string_view embedded_file(const std::string& name) {
  for (const auto& [n, text] : embedded_kernel_sources())
    if (name == n) return text;
  throw std::out_of_range("no embedded kernel source named " + name);
}

std::string flatten_source(const std::string& name) { return flatten_source(name, {}); }

std::string flatten_source(const std::string& name, const Extra& extra) {
  std::ostringstream out;
  std::vector<std::string> open;
  flatten_into(name, out, open, extra);
  return out.str();
}

std::vector<std::pair<std::string, std::string>> nvrtc_headers() {
  std::vector<std::pair<std::string, std::string>> h;
  for (const auto& [name, text] : embedded_kernel_sources()) {
    std::string n = name;
    h.emplace_back(n, std::string(text));
    // Random123 includes its headers relative to their own directory.
    if (n.rfind("Random123/", 0) == 0) {
      std::string rel = n.substr(10);
      h.emplace_back(rel, std::string(text));
      auto slash = rel.find('/');
      if (slash != std::string::npos) h.emplace_back(rel.substr(slash + 1), std::string(text));
    }
  }
  const char* empty = "";
  h.emplace_back("stddef.h", "typedef unsigned long size_t; typedef long ptrdiff_t;");
  h.emplace_back("algorithm", empty);
  h.emplace_back("stdexcept", empty);
  h.emplace_back("iterator", empty);
  h.emplace_back("limits", empty);
  h.emplace_back("iostream",
                 "namespace std {\n"
                 "struct ostream { template <class T> ostream& operator<<(const T&) { return *this; } };\n"
                 "struct istream { template <class T> istream& operator>>(T&) { return *this; } };\n"
                 "}\n");
  return h;
}

}  // namespace arnoldweb::detail
