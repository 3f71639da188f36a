// arnoldweb scene layer, internals shared by the files of lib/src/scene.
// The key table (scene_schema.cpp) is the single source of truth for key
// names, types, allowed values and the phrases used in error messages.
#pragma once

#include <toml++/toml.h>

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "arnoldweb/scene.hpp"

namespace arnoldweb::scene_detail {

// What a key's value may be, beyond its own checks.
enum class Shape {
  Value,      // a plain value
  Composite,  // a value or a table of sub-keys (observe.velocity_map, observe.energy_error)
};

class Reader;
// How a row writes its key's value as a TOML literal ("" = not set: the key is
// left out) and how it reads a value into the Scene (recording problems).
using Literal = std::function<std::string(const Scene&)>;
using Read = std::function<void(Reader&, const std::string& key, const toml::node&, Scene&)>;

// One row of the key table (keys.cpp).
struct KeySpec {
  SceneKey doc;      // as published by scene_keys() (default_value from literal)
  std::string must;  // "an integer from 1 to 1e13": completes "must be ..."
  Shape shape = Shape::Value;
  Literal literal;
  Read read;         // null for the panel.* keys (read as whole tables, panels.cpp)
};

// Every key, in the order of to_toml() and the docs.
const std::vector<KeySpec>& key_specs();
// The spec of a dotted key, or nullptr.
const KeySpec* find_spec(const std::string& dotted);
// The sections, in order: model, ensemble, ...
const std::vector<std::string>& sections();
bool is_section(const std::string& name);
// The known key closest to an unknown one (typo, or right name in the wrong
// section), or "" if none is near.
std::string closest_key(const std::string& unknown);
// The word of `words` closest to `word` (a near miss), or "".
std::string closest_word(const std::string& word, const std::vector<std::string>& words);
// The known keys of a section or composite key, comma-separated ("nside").
std::string keys_of(const std::string& parent);

// The allowed values of the enumerated keys (the checks are table-driven).
const std::vector<std::string>& initial_kinds();
struct PrecisionName {
  const char* name;
  Precision value;
};
struct MathName {
  const char* name;
  MathMode value;
};
const std::vector<PrecisionName>& precision_names();
const std::vector<MathName>& math_names();
// The names of a table of {name, value} rows.
template <class Table>
std::vector<std::string> names_of(const Table& t) {
  std::vector<std::string> n;
  for (const auto& e : t) n.push_back(e.name);
  return n;
}
// run.device: "auto", "all", or one or more device ids separated by commas (device_spec.cpp).
bool valid_device(const std::string& device);

// Limits shared by the checks and the key table.
constexpr double kMaxEnergy = 1e6;
constexpr std::int64_t kMaxTrajectories = 10'000'000'000'000;  // 1e13
constexpr double kMaxStep = 1.0;                                // in T
constexpr int kMaxNside = 8192;

// Limits on a scene's text, checked before parsing (scene_limits.cpp).
constexpr std::size_t kMaxSceneBytes = 1u << 20;  // 1 MiB
constexpr int kMaxNesting = 32;                    // arrays and tables inside each other
constexpr std::size_t kMaxWordLength = 256;        // a key path or bare value, outside quotes
constexpr std::size_t kMaxDottedParts = 16;        // parts of a dotted key
// Throws SceneError (file, line, column) if `text` exceeds them.
void check_text_limits(const std::string& text, const std::string& file);

// TOML literals: doubles that read back to the same bits and stay floats,
// strings quoted and escaped.
std::string toml_double(double v);
std::string toml_string(const std::string& s);
// A double for messages: shortest exact form ("0.01", "1e+22", "nan").
std::string show_double(double v);

// Where values came from: the file, or the n-th --set (1-based).
struct Origins {
  std::string file;
  std::vector<std::string> sets;      // the override texts, as given
  std::vector<std::string> labels;    // how each was given ("" : "--set <text>")
  std::map<std::string, int> set_of;  // dotted key -> override index

  // The override that gave `dotted` or one of its parents, 0 if none.
  int set_for(const std::string& dotted) const;
  // The SceneError file for a problem: the file, or "--set key=value".
  std::string source_name(int set_index) const;
};

// A problem found while reading; the earliest (file order, then overrides in
// order) is thrown, so a user fixing one at a time fixes them top-down.
struct Problem {
  int set_index = 0;
  int line = 0, column = 0;
  std::string key, message;
};

class Problems {
 public:
  explicit Problems(const Origins& o) : origins_(o) {}
  void add(Problem p) { list_.push_back(std::move(p)); }
  // At a node of the file, or at the override that gave `key`.
  void at(const std::string& key, const toml::source_region& where, std::string message);
  bool empty() const { return list_.empty(); }
  const std::vector<Problem>& list() const { return list_; }
  [[noreturn]] void throw_first() const;

 private:
  const Origins& origins_;
  std::vector<Problem> list_;
};

// Checks that every section and key of `root` is known (and sections are
// tables); records unknown ones with a suggestion.
void check_structure(const toml::table& root, Problems& problems);

// Parses and applies the overrides onto `root`; records bad ones.
void apply_overrides(toml::table& root, const std::vector<std::string>& overrides,
                     Origins& origins, Problems& problems);
// A wrong value in the file is an error whatever overrides it: reads the
// file's own values (`file`, before the overrides) and records, at their
// place in the file, the problems of the keys that the overrides replaced
// (`applied`: the origins after apply_overrides).
void check_replaced_values(const toml::table& file, const Origins& applied, Problems& problems);

// Reads every known key of `root` into `scene` (and scene.where), row by row
// of the key table; records wrong types and values.
void read_values(const toml::table& root, const Origins& origins, Problems& problems,
                 Scene& scene);
// Reads the [[panel]] tables (panels.cpp).
void read_panels(const toml::table& root, Problems& problems, Scene& scene);

}  // namespace arnoldweb::scene_detail
