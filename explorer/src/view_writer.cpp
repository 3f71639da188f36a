// arnoldweb view: the explorer's page written beside the data of the runs it shows, so that it
// opens from file:// (where a page may load classic scripts beside it but fetch nothing).
#include <filesystem>
#include <regex>
#include <set>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/explorer.hpp"
#include "arnoldweb/output.hpp"
#include "run_view.hpp"
#include "web_files.hpp"

namespace arnoldweb::explorer {
namespace {

namespace fs = std::filesystem;

std::string base64(const std::string& in) {
  static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(in[i]) << 16) | (static_cast<unsigned char>(in[i + 1]) << 8) |
                       static_cast<unsigned char>(in[i + 2]);
    out += {abc[v >> 18], abc[(v >> 12) & 63], abc[(v >> 6) & 63], abc[v & 63]};
  }
  if (i + 1 == in.size()) {
    const unsigned v = static_cast<unsigned char>(in[i]) << 16;
    out += {abc[v >> 18], abc[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == in.size()) {
    const unsigned v = (static_cast<unsigned char>(in[i]) << 16) | (static_cast<unsigned char>(in[i + 1]) << 8);
    out += {abc[v >> 18], abc[(v >> 12) & 63], abc[(v >> 6) & 63], '='};
  }
  return out;
}

// JSON safe inside a <script> file ("</script>" cannot end it early)
std::string script_json(const nlohmann::json& j) {
  std::string s = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  for (std::size_t at = 0; (at = s.find("</", at)) != std::string::npos; at += 3) s.replace(at, 2, "<\\/");
  return s;
}

// `to` may be new, or a view written earlier: only the names this writer writes inside.
void check_view_dir(const fs::path& to) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(to, ec))) return;
  if (fs::is_symlink(fs::symlink_status(to)) || !fs::is_directory(to))
    throw OutputError(to.string(), "exists and is not a directory (give the view another place with --to)");
  std::set<std::string> ours = {"view.html", "data"};
  for (const auto& n : web_file_names()) ours.insert(n);
  static const std::regex data_name(R"((run-[0-9]+|compare)\.js)");
  for (const auto& e : fs::directory_iterator(to)) {
    const std::string name = e.path().filename().string();
    const bool ok = name == "data" ? e.is_directory() && !e.is_symlink() : ours.count(name) && e.is_regular_file() && !e.is_symlink();
    if (!ok)
      throw OutputError(to.string(), "holds " + name + ", which arnoldweb view did not write: the view goes into a "
                                     "new directory or one view wrote (give another with --to)");
    if (name == "data")
      for (const auto& d : fs::directory_iterator(e.path()))
        if (!std::regex_match(d.path().filename().string(), data_name) || !d.is_regular_file() || d.is_symlink())
          throw OutputError(d.path().string(), "was not written by arnoldweb view: the view goes into a new directory "
                                               "or one view wrote (give another with --to)");
  }
}

}  // namespace

std::string default_view_dir(const std::string& first_dir) {
  std::string d = fs::path(first_dir).lexically_normal().string();
  while (d.size() > 1 && d.back() == '/') d.pop_back();
  return d + ".view";
}

std::string write_view(const std::vector<std::string>& dirs, const std::string& to_dir) {
  if (dirs.empty()) throw OutputError("", "no run to view: name one or more output directories");
  std::vector<RunView> runs;  // every run read and checked before anything is written
  for (std::size_t i = 0; i < dirs.size(); ++i) runs.push_back(read_run_view(dirs[i], "r" + std::to_string(i)));
  const fs::path to = to_dir.empty() ? fs::path(default_view_dir(dirs.front())) : fs::path(to_dir);
  for (const auto& d : dirs)
    if (fs::exists(to) && fs::equivalent(to, d))
      throw OutputRefused(to.string(), "is a run's directory: the view goes beside it (--to another place)");
  check_view_dir(to);
  std::error_code ec;
  fs::create_directories(to / "data", ec);
  if (ec) throw OutputError((to / "data").string(), "cannot be made: " + ec.message());

  std::string scripts;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunView& r = runs[i];
    const std::string name = "data/run-" + std::to_string(i) + ".js";
    write_text_file((to / name).string(), "AW.addRun(" + script_json(r.meta) + ",\n\"" + base64(r.map_bytes) + "\",\n" +
                                              script_json(r.fields) + ");\n");
    scripts += "<script src=\"" + name + "\"></script>\n";
  }
  const bool compared = runs.size() == 2 && !runs[0].counts.empty() && runs[0].counts.size() == runs[1].counts.size();
  if (compared) {
    write_text_file((to / "data/compare.js").string(), "AW.compareData = " + script_json(compare_json(runs[0], runs[1])) + ";\n");
    scripts += "<script src=\"data/compare.js\"></script>\n";
  }
  for (const auto& name : web_file_names())
    if (name != "index.html") write_text_file((to / name).string(), std::string(*web_file(name)));
  const std::string page = (to / "view.html").string();
  write_text_file(page, page_with_scripts(scripts));
  return page;
}

}  // namespace arnoldweb::explorer
