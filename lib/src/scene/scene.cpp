// arnoldweb scene layer: the entry points. A scene is read in four steps:
// TOML syntax, --set overrides applied on top, every section and key known,
// every value of the right type and range. All problems are collected; the
// first one (in file order, then the overrides in order) is thrown.
#include "arnoldweb/scene.hpp"

#include <algorithm>

#include "arnoldweb/errors.hpp"
#include "os/regular_file.hpp"
#include "output_table/output_table.hpp"
#include "scene/scene_internal.hpp"

namespace arnoldweb {

const char* to_string(Precision p) {
  for (const auto& n : scene_detail::precision_names())
    if (n.value == p) return n.name;
  return "?";
}

const char* to_string(MathMode m) {
  for (const auto& n : scene_detail::math_names())
    if (n.value == m) return n.name;
  return "?";
}

SourcePos Scene::pos(const std::string& key) const {
  auto it = where.find(key);
  return it == where.end() ? SourcePos{} : it->second;
}

bool Scene::writes_format(const std::string& f) const {
  return std::find(formats.begin(), formats.end(), f) != formats.end();
}

std::vector<double> Scene::output_value(const std::string& key) const {
  for (const detail::KeyTable* t : detail::key_tables()) {
    if (t->key == key) return t->on(output_values) ? std::vector<double>{1} : std::vector<double>{};
    for (const detail::TableSubKey& k : t->keys)
      if (t->sub(k.name) == key) return t->value(output_values, k.name);
  }
  if (const detail::DirectionKey* d = detail::find_direction_key(key)) return d->value(output_values);
  return {};
}

std::string Scene::origin(const std::string& key) const {
  const SourcePos p = pos(key);
  if (p.set_index > 0 && static_cast<std::size_t>(p.set_index) <= overrides.size()) {
    const auto i = static_cast<std::size_t>(p.set_index - 1);
    if (i < override_labels.size() && !override_labels[i].empty()) return override_labels[i];
    return "--set " + overrides[i];
  }
  if (p.line > 0) return file + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
  return "default";
}

Scene parse_scene(const std::string& text, const std::string& file,
                  const std::vector<std::string>& overrides, const std::vector<std::string>& labels) {
  using namespace scene_detail;
  Scene scene;
  scene.file = file.empty() ? "<string>" : file;
  scene.overrides = overrides;
  scene.override_labels = labels;
  scene.override_labels.resize(overrides.size());
  scene.text = text;

  check_text_limits(text, scene.file);
  toml::table root;
  try {
    root = toml::parse(text, scene.file);
  } catch (const toml::parse_error& e) {
    throw SceneError(scene.file, static_cast<int>(e.source().begin.line),
                     static_cast<int>(e.source().begin.column), "",
                     "TOML syntax error: " + std::string(e.description()));
  }

  Origins origins;
  origins.file = scene.file;
  origins.labels = scene.override_labels;
  Problems problems(origins);
  apply_overrides(root, overrides, origins, problems);
  check_structure(root, problems);
  read_values(root, origins, problems, scene);
  // the file as written (parsed again: a copy of the tree loses the lines)
  if (!overrides.empty()) check_replaced_values(toml::parse(text, scene.file), origins, problems);
  if (!problems.empty()) problems.throw_first();
  return scene;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides,
                 const std::vector<std::string>& labels) {
  const detail::RegularFile f = detail::read_regular_file(path, scene_detail::kMaxSceneBytes);
  if (!f.why.empty()) throw SceneError(path, 0, 0, "", "cannot read the scene file: " + f.why);
  return parse_scene(f.bytes, path, overrides, labels);
}

}  // namespace arnoldweb
