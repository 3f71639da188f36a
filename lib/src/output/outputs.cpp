// arnoldweb: the output directory of a run. Files are produced in a staging
// directory beside it and moved into place at the end, so an output directory
// is either absent or complete; what was computed is never lost.
#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "arnoldweb/analysis.hpp"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "output/pictures.hpp"

namespace arnoldweb {
namespace fs = std::filesystem;

void check_output_dir(const std::string& dir, bool force) {
  if (dir.empty()) throw OutputError(dir, "no output directory given");
  std::error_code ec;
  const fs::path p(dir);
  if (fs::exists(p, ec)) {
    if (!force) throw OutputError(dir, "exists; use --force to replace it, or choose another with --out");
    if (!fs::is_directory(p, ec)) throw OutputError(dir, "exists and is not a directory");
  }
  // missing parents are created when the results are written (mkdir -p); here
  // the nearest existing ancestor must be a writable directory
  fs::path ancestor = fs::absolute(p, ec).parent_path();
  while (!ancestor.empty() && !fs::exists(ancestor, ec) && ancestor != ancestor.parent_path())
    ancestor = ancestor.parent_path();
  if (!fs::is_directory(ancestor, ec))
    throw OutputError(dir, ancestor.string() + " is not a directory, so the output directory cannot be made");
  if (::access(ancestor.c_str(), W_OK | X_OK) != 0)
    throw OutputError(dir, "cannot create it: " + ancestor.string() + " is not writable (" +
                               std::strerror(errno) + ")");
}

std::vector<std::string> write_outputs(const Plan& plan, const Result& result, const std::string& dir,
                                       bool force) {
  check_output_dir(dir, force);
  const fs::path final_dir(dir);
  const fs::path staging = final_dir.string() + ".partial-" + std::to_string(::getpid());
  std::error_code ec;
  if (final_dir.has_parent_path()) fs::create_directories(final_dir.parent_path(), ec);
  fs::remove_all(staging, ec);
  if (!fs::create_directories(staging, ec))
    throw OutputError(staging.string(), "cannot create the staging directory: " + ec.message());

  std::vector<std::string> names;
  std::string failure;
  auto attempt = [&](const std::string& name, auto&& write) {
    if (!failure.empty()) return;
    try {
      write((staging / name).string());
      names.push_back(name);
    } catch (const Error& e) {
      failure = e.what();
    }
  };
  attempt("summary.json", [&](const std::string& p) { write_text_file(p, summary_json(plan, result)); });
  if (!result.map.empty() || !result.zoom.empty())
    attempt("map.h5", [&](const std::string& p) { write_map_hdf5(p, plan, result); });
  if (!result.initial_r.empty() || !result.final_r.empty())
    attempt("states.h5", [&](const std::string& p) { write_states_hdf5(p, plan, result); });
  double lon, lat;
  if (!result.frames.empty() && detail::initial_centre(plan.scene, &lon, &lat))
    attempt("frames_spread.csv", [&](const std::string& p) {
      const Vec3 c = direction(lon, lat);
      std::string csv = "t_from,t_to,spread\n";
      for (std::size_t k = 0; k < result.frames.size(); ++k)
        csv += std::to_string(plan.scene.frame_times[k]) + "," + std::to_string(plan.scene.frame_times[k + 1]) + "," +
               std::to_string(2 * plan.scene.energy * direction_spread(result.frames[k], plan.scene.nside, c)) + "\n";
      write_text_file(p, csv);
    });
  if (plan.scene.images && failure.empty()) {
    try {
      for (const auto& n : detail::write_pictures(plan, result, staging.string())) names.push_back(n);
    } catch (const Error& e) {
      failure = e.what();
    }
  }

  if (names.empty()) {  // nothing complete: leave no directory behind
    fs::remove_all(staging, ec);
    throw OutputError(dir, "writing failed: " + failure);
  }

  // move into place; without --force never over a directory that appeared meanwhile
  const fs::path old = final_dir.string() + ".old-" + std::to_string(::getpid());
  const bool replacing = fs::exists(final_dir, ec);
  if (replacing) {
    if (!force) throw OutputError(dir, "appeared while the run was computing; the results are in " + staging.string());
    fs::rename(final_dir, old, ec);
    if (ec) throw OutputError(dir, "cannot move the existing directory aside: " + ec.message() +
                                       " (the results are in " + staging.string() + ")");
  }
  int rc = ::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, final_dir.c_str(), RENAME_NOREPLACE);
  if (rc != 0 && errno == EINVAL) rc = std::rename(staging.c_str(), final_dir.c_str());  // no NOREPLACE here
  if (rc != 0) {
    const std::string why = std::strerror(errno);
    if (replacing) fs::rename(old, final_dir, ec);  // put the old directory back
    throw OutputError(dir, "cannot move the results into place: " + why + " (they are in " + staging.string() + ")");
  }
  fs::remove_all(old, ec);

  std::vector<std::string> written;
  for (const auto& n : names) written.push_back((final_dir / n).string());
  if (!failure.empty())
    throw OutputError(dir, "writing stopped: " + failure + "; the files written before are in " + dir);
  return written;
}

}  // namespace arnoldweb
