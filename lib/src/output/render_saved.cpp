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
  if (std::string why; !detail::pictures_available(&why)) throw OutputError(dir, "no pictures: " + why);
  // everything is read and checked before anything is drawn
  const detail::SavedDir main_dir(dir);
  const detail::SavedRun main = detail::read_saved_run(main_dir);
  std::vector<detail::SavedDir> panel_dirs;
  std::vector<detail::SavedRun> panels;
  std::vector<const Scene::Panel*> panel_of;
  for (const Scene::Panel& p : main.plan.scene.panels) {
    const std::string sub = "panel-" + p.name;
    if (!main_dir.holds(sub + "/summary.json")) continue;  // the run stopped before this panel
    panel_dirs.emplace_back(main_dir, sub);
    panels.push_back(detail::read_saved_run(panel_dirs.back()));
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
