// arnoldweb: pictures of a saved run: the scene and counts come back from
// summary.json, the maps from map.h5.
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "output/pictures.hpp"
#include "output/saved_run.hpp"

namespace arnoldweb {
namespace {

namespace fs = std::filesystem;

struct Saved {
  Plan plan;
  Result result;
};

Saved load(const std::string& dir) {
  const nlohmann::json j = detail::read_summary(dir);
  const std::string summary_path = dir + "/summary.json";
  Saved s;
  s.plan = make_plan(parse_scene(j.at("scene_toml").get<std::string>(), summary_path));
  Result& r = s.result;
  r.trajectories = j.at("trajectories").get<std::uint64_t>();
  r.completed = j.at("completed").get<std::uint64_t>();
  r.binned = j.at("binned").get<std::uint64_t>();
  r.device.id = j.at("device").at("id").get<std::string>();
  r.device.name = j.at("device").at("name").get<std::string>();
  detail::read_map_h5(dir, r);
  return s;
}

// Adds the pictures drawn into an output directory to its summary.json's
// list of files, so that the directory stays recognisably arnoldweb's.
void list_in_summary(const std::string& dir, const std::vector<std::string>& paths) {
  const std::string summary_path = dir + "/summary.json";
  std::ifstream in(summary_path);
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return;
  if (!j.contains("files") || !j["files"].is_array()) return;  // an older directory: names are known
  for (const std::string& p : paths) {
    const std::string rel = fs::path(p).lexically_relative(dir).string();
    bool listed = false;
    for (const auto& f : j["files"]) listed |= f.is_string() && f.get<std::string>() == rel;
    if (!listed) j["files"].push_back(rel);
  }
  write_text_file(summary_path, j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
}

}  // namespace

std::vector<std::string> render_saved(const std::string& dir) {
  if (!detail::pictures_available())
    throw OutputError(dir, "this build has no pictures (cairo was not found when it was configured)");
  std::vector<std::string> written;
  const Saved main = load(dir);
  std::vector<std::string> names;
  detail::write_pictures(main.plan, main.result, dir, names);
  for (const auto& n : names) written.push_back(dir + "/" + n);
  std::vector<Saved> panels;
  std::vector<FigurePanel> figure_panels;
  for (const auto& p : main.plan.scene.panels) {
    const std::string pdir = dir + "/panel-" + p.name;
    if (!fs::exists(pdir + "/summary.json")) continue;
    panels.push_back(load(pdir));
    std::vector<std::string> pnames;
    detail::write_pictures(panels.back().plan, panels.back().result, pdir, pnames);
    std::vector<std::string> ppaths;
    for (const auto& n : pnames) ppaths.push_back(pdir + "/" + n);
    list_in_summary(pdir, ppaths);
    written.insert(written.end(), ppaths.begin(), ppaths.end());
  }
  for (std::size_t k = 0, i = 0; k < main.plan.scene.panels.size() && i < panels.size(); ++k)
    if (fs::exists(dir + "/panel-" + main.plan.scene.panels[k].name + "/summary.json")) {
      figure_panels.push_back({main.plan.scene.panels[k].name, main.plan.scene.panels[k].title, &panels[i].plan,
                               &panels[i].result});
      ++i;
    }
  if (!figure_panels.empty()) {
    const std::string fig = write_figure(dir, main.plan, main.result, figure_panels);
    if (!fig.empty()) written.push_back(fig);
  }
  list_in_summary(dir, written);
  return written;
}

}  // namespace arnoldweb
