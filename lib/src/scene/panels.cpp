// arnoldweb scene layer: [[panel]] tables: further runs of the same scene
// with overrides (job.hpp). Read as whole tables; their keys are documented
// as panel.* rows of the key table.
#include "scene/reader.hpp"

namespace arnoldweb::scene_detail {

void read_panels(const toml::table& root, Problems& problems, Scene& s) {
  if (const toml::node* n = root.get("panel"); n && n->is_array()) {
    for (const toml::node& e : *n->as_array()) {
      const toml::table* t = e.as_table();
      if (!t) continue;  // reported by check_structure
      Scene::Panel panel;
      const toml::node* name = t->get("name");
      if (s.panels.empty())  // positions of the first panel's keys
        for (auto&& [k, v] : *t) {
          SourcePos p;
          p.line = static_cast<int>(k.source().begin.line);
          p.column = static_cast<int>(k.source().begin.column);
          s.where["panel." + std::string(k.str())] = p;
        }
      const std::string at = "panel";
      if (!name || !name->is_string() || name->as_string()->get().empty() ||
          name->as_string()->get().find_first_not_of(
              "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_") != std::string::npos) {
        problems.at("panel.name", name ? name->source() : e.source(),
                    "must be " + find_spec("panel.name")->must);
        continue;
      }
      panel.name = name->as_string()->get();
      for (const Scene::Panel& other : s.panels)
        if (other.name == panel.name) problems.at("panel.name", name->source(), "names panel \"" + panel.name + "\" twice");
      if (const toml::node* title = t->get("title")) {
        if (title->is_string()) panel.title = title->as_string()->get();
        else problems.at("panel.title", title->source(), "must be a string");
      }
      if (const toml::node* set = t->get("set")) {
        const toml::array* a = set->as_array();
        bool good = a != nullptr;
        if (a)
          for (const toml::node& x : *a) {
            if (!x.is_string() || x.as_string()->get().find('=') == std::string::npos) good = false;
            else {
              panel.sets.push_back(x.as_string()->get());
              panel.set_origins.push_back(s.file + ":" + std::to_string(x.source().begin.line) + ":" +
                                          std::to_string(x.source().begin.column));
            }
          }
        if (!good) problems.at("panel.set", set->source(), "must be " + find_spec("panel.set")->must);
      }
      s.panels.push_back(std::move(panel));
    }
  }
}

}  // namespace arnoldweb::scene_detail
