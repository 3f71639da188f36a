// arnoldweb: pictures of a saved run: the scene and counts come back from
// summary.json, the maps from map.h5, both read and checked by SavedDir
// (saved_run.hpp) before anything is drawn.
#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "output/file_digest.hpp"
#include "output/pictures.hpp"
#include "output/saved_run.hpp"

namespace arnoldweb {
namespace {

namespace fs = std::filesystem;

struct Saved {
  Plan plan;
  Result result;
};

// The scene as run must declare the maps that map.h5 holds: the pictures are
// drawn with the scene's nside, frames and zoom.
void check_declared(const detail::SavedDir& saved, const Plan& plan) {
  const auto differs = [&](const char* field, std::uint64_t declared, const std::string& key, std::uint64_t asked) {
    if (declared != asked)
      throw SavedRunError(saved.summary_path(), "scene_toml gives " + key + " = " + std::to_string(asked) + ", but " +
                                                    field + " = " + std::to_string(declared) +
                                                    ": the summary does not describe its map.h5");
  };
  differs("maps.nside", saved.count("/maps/nside"), "observe.velocity_map.nside",
          plan.scene.velocity_map ? static_cast<std::uint64_t>(plan.scene.nside) : 0);
  differs("maps.frames", saved.count("/maps/frames"), "the number of frames", static_cast<std::uint64_t>(plan.frames));
  differs("maps.zoom_resolution", saved.count("/maps/zoom_resolution"), "observe.zoom.resolution",
          static_cast<std::uint64_t>(plan.zoom_resolution));
}

Saved load(const detail::SavedDir& saved) {
  Saved s;
  s.plan = make_plan(parse_scene(saved.text("/scene_toml"), saved.summary_path()));
  check_declared(saved, s.plan);
  Result& r = s.result;
  r.trajectories = saved.count("/trajectories");
  r.completed = saved.count("/completed");
  r.binned = saved.count("/binned");
  r.device.id = saved.text("/device/id");
  r.device.name = saved.text("/device/name");
  detail::read_saved_map_h5(saved, r);
  return s;
}

// Adds the files drawn into a saved directory to its summary.json: to its
// list of files, so that the directory stays recognisably arnoldweb's, and
// with their new sizes and digests, so that it still reads back checked.
void list_in_summary(const detail::SavedDir& saved, const detail::DigestLedger& ledger,
                     const std::vector<std::string>& names) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(saved.summary_text());
  const bool listed = j.contains("files") && j["files"].is_array();
  if (!listed && !saved.checked()) return;  // an older directory: names are known
  if (listed)
    for (const std::string& name : names)
      if (std::find(j["files"].begin(), j["files"].end(), name) == j["files"].end()) j["files"].push_back(name);
  if (saved.checked())
    for (const auto& [name, digest] : ledger.of(saved.dir(), names))
      j["file_digests"][name] = detail::file_digest_json(digest);
  write_text_file(saved.summary_path(), j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
}

}  // namespace

std::vector<std::string> render_saved(const std::string& dir) {
  if (!detail::pictures_available())
    throw OutputError(dir, "this build has no pictures (cairo was not found when it was configured)");
  // everything is read and checked before anything is drawn
  const detail::SavedDir main_dir(dir);
  const Saved main = load(main_dir);
  std::vector<detail::SavedDir> panel_dirs;
  std::vector<Saved> panels;
  std::vector<const Scene::Panel*> panel_of;
  for (const Scene::Panel& p : main.plan.scene.panels) {
    const std::string sub = "panel-" + p.name;
    if (!main_dir.holds(sub + "/summary.json")) continue;  // the run stopped before this panel
    panel_dirs.emplace_back(main_dir, sub);
    panels.push_back(load(panel_dirs.back()));
    panel_of.push_back(&p);
  }
  std::vector<FigurePanel> figure_panels;
  for (std::size_t i = 0; i < panels.size(); ++i)
    figure_panels.push_back({panel_of[i]->name, panel_of[i]->title, &panels[i].plan, &panels[i].result});

  const detail::DigestLedger ledger;  // the sizes and digests of what is drawn
  std::vector<std::string> names;      // relative to dir
  detail::write_pictures(main.plan, main.result, dir, names);
  for (std::size_t i = 0; i < panels.size(); ++i) {
    std::vector<std::string> pnames;
    detail::write_pictures(panels[i].plan, panels[i].result, panel_dirs[i].dir(), pnames);
    list_in_summary(panel_dirs[i], ledger, pnames);
    const std::string sub = "panel-" + panel_of[i]->name;
    for (const auto& n : pnames) names.push_back(sub + "/" + n);
    names.push_back(sub + "/summary.json");
  }
  if (!figure_panels.empty() && !write_figure(dir, main.plan, main.result, figure_panels).empty())
    names.push_back("figure.png");
  list_in_summary(main_dir, ledger, names);

  std::vector<std::string> written;
  for (const auto& n : names)
    if (fs::path(n).filename() != "summary.json") written.push_back(dir + "/" + n);
  if (!main_dir.note().empty()) written.push_back("note: " + main_dir.note());
  return written;
}

}  // namespace arnoldweb
