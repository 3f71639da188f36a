// arnoldweb scene layer: the shape of a scene: its sections, every key known
// (with the nearest known key for a typo), and the allowed values of the
// enumerated keys.
#include <algorithm>
#include <cctype>

#include "scene/reader.hpp"

namespace arnoldweb::scene_detail {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string parent_of(const std::string& k) {
  const auto dot = k.rfind('.');
  return dot == std::string::npos ? std::string() : k.substr(0, dot);
}

std::string leaf_of(const std::string& k) {
  const auto dot = k.rfind('.');
  return dot == std::string::npos ? k : k.substr(dot + 1);
}

std::string join(const std::string& prefix, std::string_view key) {
  return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
}

std::string suggestion(const std::string& dotted) {
  const std::string near = closest_key(dotted);
  return near.empty() ? std::string(" ") : "; did you mean '" + near + "'? ";
}

void check_table(const toml::table& t, const std::string& prefix, Problems& problems) {
  std::string section_list;
  for (const std::string& s : sections()) section_list += (section_list.empty() ? "" : ", ") + s;
  for (auto&& [k, v] : t) {
    const std::string dotted = join(prefix, k.str());
    if (prefix.empty() && dotted == "panel") {
      // [[panel]]: an array of tables with the keys panel.*
      const toml::array* panels = v.as_array();
      if (!panels || !panels->is_array_of_tables()) {
        problems.at(dotted, v.source(), "must be written as [[panel]] tables (an array of tables)");
        continue;
      }
      for (const toml::node& panel : *panels) check_table(*panel.as_table(), "panel", problems);
      continue;
    }
    if (prefix.empty()) {
      if (!is_section(dotted)) {
        problems.at(dotted, k.source(),
                    v.is_table() ? "unknown section" + suggestion(dotted) + "(sections: " +
                                       section_list + ")"
                                 : "unknown key" + suggestion(dotted) +
                                       "(every key belongs to a section: " + section_list + ")");
      } else if (!v.is_table()) {
        problems.at(dotted, v.source(),
                    std::string("must be a table (the section [") + dotted + "]), got " +
                        type_name(v.type()) + " " + show(v));
      } else {
        check_table(*v.as_table(), dotted, problems);
      }
      continue;
    }
    const KeySpec* spec = find_spec(dotted);
    if (!spec) {
      const bool in_section = is_section(prefix);
      problems.at(dotted, k.source(),
                  "unknown key" + suggestion(dotted) + "(keys of " +
                      (in_section ? "[" + prefix + "]" : prefix) + ": " + keys_of(prefix) + ")");
    } else if (spec->shape == Shape::Composite && v.is_table()) {
      check_table(*v.as_table(), dotted, problems);
    }
  }
}

}  // namespace

const std::vector<std::string>& sections() {
  static const std::vector<std::string> s = {"model", "ensemble", "integrator",
                                             "run",   "observe",  "output"};
  return s;
}

bool is_section(const std::string& name) {
  const auto& s = sections();
  return std::find(s.begin(), s.end(), name) != s.end();
}

std::string closest_key(const std::string& unknown) {
  const std::string u = lower(unknown);
  const std::string u_parent = parent_of(u), u_leaf = leaf_of(u);
  // A typo scores its edit distance; the right name in the wrong section
  // scores 2 more than the distance of the last parts.
  std::vector<std::string> candidates;
  if (u_parent.empty()) candidates = sections();
  for (const KeySpec& s : key_specs()) candidates.push_back(s.doc.key);
  std::string best;
  std::size_t best_score = std::max<std::size_t>(2, u_leaf.size() / 2) + 1;
  for (const std::string& c : candidates) {
    std::size_t score = edit_distance(u, c);
    if (parent_of(c) != u_parent)
      score = std::min(score, edit_distance(u_leaf, leaf_of(c)) + 2);
    if (score < best_score) {
      best_score = score;
      best = c;
    }
  }
  return best == unknown ? std::string() : best;
}

std::string closest_word(const std::string& word, const std::vector<std::string>& words) {
  std::string best;
  std::size_t best_score = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string& w : words) {
    const std::size_t score = edit_distance(lower(word), lower(w));
    if (score < best_score) {
      best_score = score;
      best = w;
    }
  }
  return best;
}

std::string keys_of(const std::string& parent) {
  std::string s;
  for (const KeySpec& k : key_specs())
    if (parent_of(k.doc.key) == parent) s += (s.empty() ? "" : ", ") + leaf_of(k.doc.key);
  return s;
}

const std::vector<std::string>& initial_kinds() {
  static const std::vector<std::string> k = {"shell", "cap", "box", "gaussian", "grid", "file"};
  return k;
}

const std::vector<PrecisionName>& precision_names() {
  static const std::vector<PrecisionName> n = {{"double", Precision::Double},
                                               {"float", Precision::Float}};
  return n;
}

const std::vector<MathName>& math_names() {
  static const std::vector<MathName> n = {{"portable", MathMode::Portable},
                                          {"native", MathMode::Native}};
  return n;
}

void check_structure(const toml::table& root, Problems& problems) { check_table(root, "", problems); }

}  // namespace arnoldweb::scene_detail
