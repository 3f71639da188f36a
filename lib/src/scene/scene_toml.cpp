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

std::string toml_string(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
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
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    out += (c < 0x20 || c == 0x7f) ? '?' : ch;
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
