// arnoldweb scene layer: writing a scene back as TOML (Scene::to_toml) and the
// literals it is made of.
#include <charconv>
#include <cstdio>
#include <sstream>

#include "scene/scene_internal.hpp"

namespace arnoldweb::scene_detail {

std::string show_double(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest that reads back exactly
  return std::string(buf, r.ptr);
}

std::string toml_double(double v) {
  std::string s = show_double(v);
  // "15" would read back as an integer: keep it a float.
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

namespace {

// Length of the valid UTF-8 sequence at s[i], or 0 if the bytes there are not one.
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((b(i + k) & 0xc0) != 0x80) return 0;
  std::uint32_t cp = n == 1 ? c : c & (0x7f >> n);
  for (std::size_t k = 1; k < n; ++k) cp = (cp << 6) | (b(i + k) & 0x3f);
  const std::uint32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < least[n] || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return 0;  // overlong, surrogate
  return n;
}

}  // namespace

// TOML strings are UTF-8: bytes that are not (a path may hold any) are
// written as U+FFFD.
std::string toml_string(const std::string& s) {
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = utf8_length(s, i);
    if (n == 0) {
      out += "\xEF\xBF\xBD";  // U+FFFD, as itself: reading back and writing again gives the same text
      ++i;
      continue;
    }
    if (n > 1) {
      out.append(s, i, n);
      i += n;
      continue;
    }
    const char ch = s[i++];
    const auto c = static_cast<unsigned char>(ch);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\t': out += "\\t"; break;
      case '\n': out += "\\n"; break;
      case '\f': out += "\\f"; break;
      case '\r': out += "\\r"; break;
      default:
        if (c < 0x20 || c == 0x7f) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

namespace {

// Text safe inside a TOML comment (no line breaks or control characters).
std::string comment_text(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = utf8_length(s, i);
    const auto c = static_cast<unsigned char>(s[i]);
    if (n == 0 || (n == 1 && (c < 0x20 || c == 0x7f))) {
      out += '?';
      ++i;
    } else {
      out.append(s, i, n);
      i += n;
    }
  }
  return out;
}

}  // namespace
}  // namespace arnoldweb::scene_detail

namespace arnoldweb {

std::string Scene::to_toml() const {
  using namespace scene_detail;
  std::ostringstream o;
  o << "# arnoldweb scene as run: every key with its effective value, defaults included.\n";
  if (!file.empty()) o << "# read from " << comment_text(file) << "\n";
  for (const std::string& set : overrides) o << "# --set " << comment_text(set) << "\n";
  for (const std::string& section : sections()) {
    o << "\n[" << section << "]\n";
    const std::string prefix = section + ".";
    for (const KeySpec& k : key_specs()) {
      const std::string& key = k.doc.key;
      if (key.compare(0, prefix.size(), prefix) != 0) continue;
      const std::string name = key.substr(prefix.size());
      if (name.find('.') != std::string::npos) continue;  // part of a composite's literal
      const std::string value = k.literal(*this);
      if (value.empty())
        o << "# " << name << " is not set\n";
      else
        o << name << " = " << value << "\n";
    }
  }
  for (const Panel& p : panels) {
    o << "\n[[panel]]\nname = " << toml_string(p.name) << "\ntitle = " << toml_string(p.title)
      << "\nset = [";
    for (std::size_t i = 0; i < p.sets.size(); ++i) o << (i ? ", " : "") << toml_string(p.sets[i]);
    o << "]\n";
  }
  return o.str();
}

}  // namespace arnoldweb

namespace arnoldweb {

std::string Scene::to_json() const {
  // the TOML every key writes, read back and printed as JSON: the JSON echo
  // has exactly the keys and values of the table
  std::ostringstream o;
  o << toml::json_formatter{toml::parse(to_toml())};
  return o.str();
}

}  // namespace arnoldweb
