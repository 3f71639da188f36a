// arnoldweb: which pictures a run gets, and how they are titled.
#include "output/pictures.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/version.hpp"
#include "os/process.hpp"
#include "output/atomic_file.hpp"
#include "output/picture_plugin.hpp"

namespace arnoldweb::detail {
namespace {

std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string title_of(const Plan& p, const Result& r) {
  return "E = " + short_number(p.scene.energy) + ",  N = " + short_number(static_cast<double>(r.binned)) +
         " binned,  dt = " + short_number(p.scene.average) + " T,  " + p.method.name + ",  h = " +
         short_number(p.step) + " T";
}

std::string caption_of(const Result& r) {
  return std::string("arnoldweb ") + ARNOLDWEB_VERSION + " on " + r.device.id + " (" + r.device.name + ")";
}

bool have_ffmpeg() { return !find_program("ffmpeg").empty(); }

// frames.mp4 from frames/frame_NNN.png, written atomically (into a temporary
// that ffmpeg fills, so "-f mp4": the name does not end in .mp4). ffmpeg gets
// its arguments as a vector: no shell, so no directory name can run a command.
void make_movie(const std::string& dir) {
  const std::string movie = dir + "/frames.mp4";
  write_atomically(movie, [&](const std::string& tmp) {
    const ProgramRun run = run_program({"ffmpeg", "-nostdin", "-loglevel", "error", "-y", "-framerate", "2", "-i",
                                        dir + "/frames/frame_%03d.png", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                        "-pix_fmt", "yuv420p", "-f", "mp4", tmp});
    if (run.exit_code != 0 || !std::filesystem::exists(tmp)) {
      std::string why = run.signal ? "killed by signal " + std::to_string(run.signal)
                                   : "exit " + std::to_string(run.exit_code);
      if (!run.output.empty()) why += ": " + run.output.substr(0, 400);
      throw OutputError(movie, "ffmpeg failed (" + why + ")");
    }
  });
}

}  // namespace

RenderOptions picture_options(const Plan& plan, const Result& r) {
  RenderOptions o;
  o.title = title_of(plan, r);
  o.caption = caption_of(r);
  // the circles of the model's own harmonics, or every resonance up to an order (the paper's)
  o.resonances = model_resonances(plan);
  double lon, lat;
  if (initial_centre(plan.scene, &lon, &lat)) {
    o.view_lon = lon;
    o.view_lat = lat;
  }
  return o;
}

bool pictures_available(std::string* why) { return picture_functions(why) != nullptr; }

bool initial_centre(const Scene& s, double* lon, double* lat) {
  if (s.initial == "cap") {
    *lon = s.cap_center[0];
    *lat = s.cap_center[1];
  } else if (s.initial == "box") {
    *lon = 0.5 * (s.box_lon[0] + s.box_lon[1]);
    *lat = 0.5 * (s.box_lat[0] + s.box_lat[1]);
  } else if (s.initial == "gaussian") {
    *lon = std::atan2(s.gaussian_mean[1], s.gaussian_mean[0]) * 180 / M_PI;
    *lat = 0;
  } else {
    return false;
  }
  return true;
}

void write_pictures(const Plan& plan, const Result& r, const std::string& dir, std::vector<std::string>& out) {
  const PictureFunctions* draw = picture_functions();
  if (!draw) return;  // the plan said so (plan_job's warning)
  const RenderOptions o = picture_options(plan, r);
  if (plan.scene.velocity_map) {
    draw->sphere(dir + "/map.png", r.map, plan.scene.nside, o);
    out.push_back("map.png");
    draw->mollweide(dir + "/map_mollweide.png", r.map, plan.scene.nside, o);
    out.push_back("map_mollweide.png");
    RenderOptions overlay = o;
    overlay.resonance_order = 2;
    overlay.title = o.title + (o.resonances.empty() ? ";  circles m.P = 0, |m_i| <= 2" : ";  circles k.V = 0 of the model's harmonics");
    draw->sphere(dir + "/map_resonances.png", r.map, plan.scene.nside, overlay);
    out.push_back("map_resonances.png");
  }
  if (!r.zoom.empty()) {
    RenderOptions z = o;
    z.resonance_order = 3;
    draw->zoom(dir + "/zoom.png", r.zoom, plan.zoom_resolution, plan.scene.zoom_center, plan.scene.zoom_width, z);
    out.push_back("zoom.png");
  }
  if (!r.frames.empty()) {
    std::filesystem::create_directories(dir + "/frames");
    // one colour scale for the whole movie
    std::vector<std::uint64_t> all;
    for (const auto& f : r.frames) all.insert(all.end(), f.begin(), f.end());
    for (std::size_t k = 0; k < r.frames.size(); ++k) {
      RenderOptions f = o;
      f.title = "E = " + short_number(plan.scene.energy) + ",  windows starting in [" +
                short_number(plan.scene.frame_times[k]) + ", " + short_number(plan.scene.frame_times[k + 1]) + ") T";
      char name[32];
      std::snprintf(name, sizeof name, "frames/frame_%03zu.png", k);
      draw->sphere(dir + "/" + name, r.frames[k], plan.scene.nside, f);
      out.push_back(name);
    }
    if (have_ffmpeg()) {
      make_movie(dir);
      out.push_back("frames.mp4");
    }
  }
  draw->outputs(plan, r, dir, out);
}

}  // namespace arnoldweb::detail

namespace arnoldweb {
namespace {

const detail::PictureFunctions& plugin_for(const std::string& path) {
  std::string why;
  const detail::PictureFunctions* f = detail::picture_functions(&why);
  if (!f) throw OutputError(path, "no pictures: " + why);
  return *f;
}

}  // namespace

void render_sphere_png(const std::string& path, const std::vector<std::uint64_t>& map, int nside,
                       const RenderOptions& o) {
  plugin_for(path).sphere(path, map, nside, o);
}

void render_mollweide_png(const std::string& path, const std::vector<std::uint64_t>& map, int nside,
                          const RenderOptions& o) {
  plugin_for(path).mollweide(path, map, nside, o);
}

void render_figure_png(const std::string& path, const Plan& plan, const Result& result,
                       const std::vector<FigurePanel>& panels, const RenderOptions& o) {
  plugin_for(path).figure(path, plan, result, panels, o);
}

std::string write_figure(const std::string& dir, const Plan& plan, const Result& result,
                         const std::vector<FigurePanel>& panels) {
  if (!detail::pictures_available() || !plan.scene.images || !plan.scene.velocity_map) return "";
  RenderOptions o = detail::picture_options(plan, result);
  o.width = 1400;
  o.resonance_order = 1;
  // look at the panels' regions
  if (!panels.empty() && panels.front().plan) {
    o.view_lon = panels.front().plan->scene.zoom_center[0];
    o.view_lat = panels.front().plan->scene.zoom_center[1];
  }
  const std::string path = dir + "/figure.png";
  render_figure_png(path, plan, result, panels, o);
  return path;
}

}  // namespace arnoldweb
