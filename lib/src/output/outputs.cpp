// arnoldweb: writing a job's output directory (output.hpp). Everything goes
// into a staging directory beside the final one (output_dir.hpp) and is moved
// into place at the end: a directory is either absent or complete, and
// summary.json, written last, lists every file in it with its size and digest
// (file_digest.hpp: taken by the atomic writer of each file).
#include <filesystem>

#include "arnoldweb/analysis.hpp"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/run.hpp"
#include "arnoldweb/output.hpp"
#include "aw_params.h"
#include "output/analysis_files.hpp"
#include "output/file_digest.hpp"
#include "output/output_dir.hpp"
#include "output/pictures.hpp"
#include "plan/plan_params.hpp"

namespace arnoldweb {
namespace fs = std::filesystem;
namespace {

std::string frames_spread_csv(const Plan& plan, const Result& result, double lon, double lat) {
  const Vec3 c = direction(lon, lat);
  std::string csv = "t_from,t_to,spread\n";
  for (std::size_t k = 0; k < result.frames.size(); ++k)
    csv += std::to_string(plan.scene.frame_times[k]) + "," + std::to_string(plan.scene.frame_times[k + 1]) + "," +
           std::to_string(2 * plan.scene.energy * direction_spread(result.frames[k], plan.scene.nside, c)) + "\n";
  return csv;
}

// Writes one run's files into `dir` (summary.json excepted); appends their
// names, relative to `dir`, to `names`. Throws OutputError at the first
// failure (names then holds the files complete before it).
void write_run_files(const Plan& plan, const Result& result, const fs::path& dir, std::vector<std::string>& names) {
  auto file = [&](const std::string& name, auto&& write) {
    write((dir / name).string());
    names.push_back(name);
  };
  if (!result.map.empty() || !result.zoom.empty())
    file("map.h5", [&](const std::string& p) { write_map_hdf5(p, plan, result); });
#if ARNOLDWEB_HAVE_CFITSIO  // else the scene reader refused output.formats "fits"
  if (!result.map.empty() && plan.scene.writes_format("fits"))
    file("map.fits", [&](const std::string& p) { write_map_fits(p, plan, result); });
#endif
  for (const std::string& name : record_files(result))
    file(name, [&](const std::string& p) { write_records_hdf5(p, name, plan, result); });
  double lon, lat;
  if (!result.frames.empty() && detail::initial_centre(plan.scene, &lon, &lat))
    file("frames_spread.csv",
         [&](const std::string& p) { write_text_file(p, frames_spread_csv(plan, result, lon, lat)); });
  if (const std::string csv = detail::diffusion_csv(result); !csv.empty())
    file("diffusion.csv", [&](const std::string& p) { write_text_file(p, csv); });
  if (plan.scene.images) detail::write_pictures(plan, result, dir.string(), names);
}

std::vector<std::string> prefixed(const std::string& sub, const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const auto& n : names) out.push_back(sub.empty() ? n : sub + "/" + n);
  return out;
}

double part_bytes(const Plan& p) {
  const double n = static_cast<double>(p.scene.trajectories);
  double b = 64e3;                                                  // summary.json
  b += 8.0 * static_cast<double>(p.hist_size + (p.frames > 1 ? p.npix : 0)) + 16e3;  // map.h5
  if (p.scene.writes_format("fits")) b += 8.0 * static_cast<double>(p.npix) + 16e3;   // map.fits
  const detail::IntParams& ip = detail::params(p).ints;
  b += n * static_cast<double>(ip.rec_reals + ip.rec_ints) * 8 * 1.5 + 16e3;  // the records' files (and derived datasets)
  if (p.kernel.features & AW_F_TANGENT) b += p.scene.images ? 3e6 : 0;  // the indicators' pictures
  if (p.kernel.features & (AW_F_FREQUENCIES | AW_F_DIFFUSION)) b += (p.scene.images ? 3e6 : 0) + 64e3;  // pictures, diffusion.csv
  if (p.scene.images) b += (p.scene.velocity_map ? 3 : 0) * 1.5e6 + (p.scene.zoom ? 1.5e6 : 0) + p.frames * 1.6e6;
  return b;
}

}  // namespace

std::uint64_t estimate_output_bytes(const Job& job) {
  double b = job.parts.size() > 1 ? 3e6 : 0;  // figure.png
  for (const JobPart& part : job.parts) b += part_bytes(part.plan);
  return static_cast<std::uint64_t>(b);
}

std::vector<std::string> write_job(const Job& job, const JobResult& jr, const OutputOptions& options) {
  const Plan& main = job.main();
  OutputOptions o = options;
  if (o.scene_file.empty()) o.scene_file = main.scene.file;
  detail::Staging staging(main.scene.output_dir, o);
  const fs::path root(staging.path());
  const detail::DigestLedger ledger;  // every file's size and digest, as it is written

  std::vector<std::string> all;  // every file, relative to the job's directory
  std::string failure;
  auto guarded = [&](auto&& step) {
    if (!failure.empty()) return;
    try {
      step();
    } catch (const Error& e) {
      failure = e.what();
    }
  };
  // the main run's files, then each panel (complete with its summary.json)
  if (!jr.results.empty()) guarded([&] { write_run_files(main, jr.results[0], root, all); });
  for (std::size_t k = 1; k < jr.results.size() && failure.empty(); ++k) {
    const JobPart& part = job.parts[k];
    const fs::path sub = root / part.subdir;
    std::vector<std::string> names;
    guarded([&] {
      fs::create_directories(sub);
      write_run_files(part.plan, jr.results[k], sub, names);
    });
    guarded([&] {
      const FileDigests digests = ledger.of(sub.string(), names);
      write_text_file((sub / "summary.json").string(), summary_json(part.plan, jr.results[k], names, &digests));
      names.push_back("summary.json");
    });
    for (const auto& n : prefixed(part.subdir, names)) all.push_back(n);
  }
  // the figure of the main run and its panels, when every panel ran
  if (job.parts.size() > 1 && jr.results.size() == job.parts.size())
    guarded([&] {
      std::vector<FigurePanel> panels;
      for (std::size_t k = 1; k < job.parts.size(); ++k)
        panels.push_back({job.parts[k].name, job.parts[k].title, &job.parts[k].plan, &jr.results[k]});
      if (!write_figure(root.string(), main, jr.results[0], panels).empty()) all.push_back("figure.png");
    });
  // summary.json last: it lists everything, and marks the directory as arnoldweb's
  const std::string summary_failure = failure;
  if (!jr.results.empty()) {
    std::string why;
    try {
      const FileDigests digests = ledger.of(root.string(), all);
      write_text_file((root / "summary.json").string(), summary_json(main, jr.results[0], all, &digests));
    } catch (const Error& e) {
      why = e.what();
    }
    if (failure.empty()) failure = why;
  }
  if (!failure.empty()) {
    const std::string kept = staging.keep(".incomplete-");
    throw OutputError(staging.final_dir(), "writing failed: " + failure + "; what was written is in " + kept +
                                               (fs::exists(staging.final_dir()) ? "; the existing directory was left as it was"
                                                                                 : ""));
  }
  (void)summary_failure;
  const std::string warning = staging.commit();
  std::vector<std::string> written;
  for (const auto& n : all) written.push_back((fs::path(staging.final_dir()) / n).string());
  written.push_back((fs::path(staging.final_dir()) / "summary.json").string());
  if (!warning.empty()) written.push_back("warning: " + warning);
  return written;
}

std::vector<std::string> write_outputs(const Plan& plan, const Result& result, const std::string& dir,
                                       const OutputOptions& options) {
  Job job;
  JobPart part;
  part.plan = plan;
  part.plan.scene.output_dir = dir;
  part.plan.scene.panels.clear();
  job.parts.push_back(std::move(part));
  JobResult jr;
  jr.results.push_back(result);
  jr.interrupted = result.interrupted;
  return write_job(job, jr, options);
}

}  // namespace arnoldweb
