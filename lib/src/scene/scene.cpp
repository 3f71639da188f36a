// STUB: replaced by the scene implementation (toml++).
#include "arnoldweb/scene.hpp"
#include "arnoldweb/errors.hpp"

namespace arnoldweb {
const char* to_string(Precision p) { return p == Precision::Float ? "float" : "double"; }
const char* to_string(MathMode m) { return m == MathMode::Native ? "native" : "portable"; }
std::string Scene::to_toml() const { return ""; }
SourcePos Scene::pos(const std::string& key) const {
  auto it = where.find(key);
  return it == where.end() ? SourcePos{} : it->second;
}
Scene load_scene(const std::string& path, const std::vector<std::string>&) {
  Scene s;
  s.file = path;
  return s;
}
Scene parse_scene(const std::string&, const std::string& file, const std::vector<std::string>&) {
  Scene s;
  s.file = file;
  return s;
}
const std::vector<SceneKey>& scene_keys() {
  static std::vector<SceneKey> k;
  return k;
}
}  // namespace arnoldweb
