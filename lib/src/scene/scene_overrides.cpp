// arnoldweb scene layer: --set key=value overrides, applied onto the parsed
// file before anything is checked, so an override is checked like the file.
#include <algorithm>

#include "arnoldweb/errors.hpp"
#include "scene/scene_internal.hpp"

namespace arnoldweb::scene_detail {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split_dots(const std::string& key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    parts.push_back(key.substr(start, dot == std::string::npos ? dot : dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

// The value of an override: a TOML value if it reads as one, else the text
// itself (so run.device=opencl:0 and output.dir=/tmp/x need no quotes). For
// keys that only take strings the text is used as is (output.dir=2024).
toml::table value_of(const std::string& text, const KeySpec& spec) {
  if (spec.doc.type != "string") {
    try {
      toml::table t = toml::parse("v = " + text);
      if (t.size() == 1 && t.contains("v")) return t;
    } catch (const toml::parse_error&) {
    }
  } else if (!text.empty() && (text.front() == '"' || text.front() == '\'')) {
    try {
      toml::table t = toml::parse("v = " + text);
      if (t.size() == 1 && t["v"].is_string()) return t;
    } catch (const toml::parse_error&) {
    }
  }
  toml::table t;
  t.insert("v", text);
  return t;
}

// Sets root[parts...] = value. Sections that do not exist are created; a
// composite key that is not a table (velocity_map = false) becomes one, so
// --set observe.velocity_map.nside=128 turns the map on.
void set_path(toml::table& root, const std::vector<std::string>& parts, const toml::node& value,
              int index, Origins& origins) {
  toml::table* t = &root;
  std::string dotted;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    dotted += (i ? "." : "") + parts[i];
    auto it = t->find(parts[i]);
    if (it != t->end() && it->second.is_table()) {
      t = it->second.as_table();
      continue;
    }
    if (it != t->end() && i == 0) return;  // [section] is not a table: the file's problem
    if (i > 0) origins.set_of[dotted] = index;
    t = t->insert_or_assign(parts[i], toml::table{}).first->second.as_table();
  }
  t->insert_or_assign(parts.back(), value);
  const std::string key = dotted.empty() ? parts.back() : dotted + "." + parts.back();
  // This override now gives the key and everything under it.
  const std::string below = key + ".";
  auto it = origins.set_of.lower_bound(below);
  while (it != origins.set_of.end() && it->first.compare(0, below.size(), below) == 0)
    it = origins.set_of.erase(it);
  origins.set_of[key] = index;
}

}  // namespace

void apply_overrides(toml::table& root, const std::vector<std::string>& overrides,
                     Origins& origins, Problems& problems) {
  for (const std::string& text : overrides) origins.sets.push_back(text);
  for (std::size_t n = 0; n < overrides.size(); ++n) {
    const int index = static_cast<int>(n) + 1;
    const std::string& text = overrides[n];
    auto problem = [&](const std::string& key, const std::string& message) {
      Problem p;
      p.set_index = index;
      p.key = key;
      p.message = message;
      problems.add(std::move(p));
    };
    if (text.size() > kMaxSceneBytes) {
      problem("", "an override of " + std::to_string(text.size()) + " characters is too long");
      continue;
    }
    const auto eq = text.find('=');
    const std::string key = trim(text.substr(0, eq));
    if (eq == std::string::npos || key.empty()) {
      problem(key, "an override is key=value, e.g. --set integrator.step=0.005");
      continue;
    }
    if (key.size() > kMaxWordLength) {
      problem(key.substr(0, 40) + "...", "a key longer than " + std::to_string(kMaxWordLength) + " characters");
      continue;
    }
    if (static_cast<std::size_t>(std::count(key.begin(), key.end(), '.')) >= kMaxDottedParts) {
      problem(key.substr(0, 40) + "...", "a key with more than " + std::to_string(kMaxDottedParts) + " dotted parts");
      continue;
    }
    const KeySpec* spec = find_spec(key);
    if (!spec) {
      if (is_section(key)) {
        const std::string keys = keys_of(key);
        problem(key, "is a section; --set sets one of its keys (" + keys + "), e.g. --set " +
                         key + "." + keys.substr(0, keys.find(',')) + "=...");
      } else {
        const std::string near = closest_key(key);
        const std::string section = key.substr(0, key.find('.'));
        std::string known;
        if (is_section(section)) {
          known = "keys of [" + section + "]: " + keys_of(section);
        } else {
          for (const std::string& s : sections())
            known += (known.empty() ? "sections: " : ", ") + s;
        }
        problem(key, "unknown key" +
                         (near.empty() ? std::string(" ") : "; did you mean '" + near + "'? ") +
                         "(" + known + ")");
      }
      continue;
    }
    if (!spec->read) {  // the panel.* rows: a [[panel]] table is written in the file, whole
      problem(key, "is a key of the [[panel]] tables; write it in a [[panel]] table of the scene file, "
                   "an override cannot set it");
      continue;
    }
    const std::string value = trim(text.substr(eq + 1));
    if (spec->doc.type != "string") {  // read as TOML: the parser's limits apply
      try {
        check_text_limits(value, "");
      } catch (const SceneError& e) {
        problem(key, e.message());
        continue;
      }
    }
    const toml::table holder = value_of(value, *spec);
    set_path(root, split_dots(key), *holder.get("v"), index, origins);
  }
}

void check_replaced_values(const toml::table& file, const Origins& applied, Problems& problems) {
  Origins file_only;
  file_only.file = applied.file;
  Problems found(file_only);
  Scene scratch;
  read_values(file, file_only, found, scratch);
  for (const Problem& p : found.list())
    if (applied.set_for(p.key) > 0) problems.add(p);
}

}  // namespace arnoldweb::scene_detail

namespace arnoldweb {

std::string string_override(const std::string& key, const std::string& value, const std::string& label) {
  const std::string quoted = scene_detail::toml_string(value);  // U+FFFD for bytes that are not UTF-8
  if (quoted.find("\xEF\xBF\xBD") != std::string::npos && value.find("\xEF\xBF\xBD") == std::string::npos)
    throw SceneError(label, 0, 0, key,
                     "is not UTF-8 text, and a scene (TOML, as summary.json records it) holds only UTF-8: "
                     "give a name in UTF-8");
  return key + "=" + quoted;
}

}  // namespace arnoldweb
