// arnoldweb: writing results. Every file is written under a temporary name and
// renamed into place, so a failed write (full disk) leaves no partial file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb {

// Write summary.json, map.h5, states.h5 (if states were asked for), map.png and
// map_mollweide.png (if scene.output images) into `dir`.
// An existing `dir` is refused (OutputError) unless `force`. The files are
// produced in a staging directory beside `dir` and moved into place at the
// end; if a write fails, the files already complete are still moved into
// place and OutputError names the one that failed. Returns the paths written.
std::vector<std::string> write_outputs(const Plan& plan, const Result& result,
                                       const std::string& dir, bool force);

// Throws OutputError if `dir` exists and !force, or its parent is not writable.
void check_output_dir(const std::string& dir, bool force);

// The summary as JSON text.
std::string summary_json(const Plan& plan, const Result& result);

// Individual writers (each atomic).
void write_text_file(const std::string& path, const std::string& text);
void write_map_hdf5(const std::string& path, const Plan& plan, const Result& result);
void write_states_hdf5(const std::string& path, const Plan& plan, const Result& result);

struct RenderOptions {
  int width = 900;          // pixels
  double view_lon = 45;     // degrees: longitude of the view direction
  double view_lat = 30;     // degrees: latitude of the view direction
  std::string title;        // first line at the top
  std::string caption;      // small line at the bottom
  int resonance_order = 0;  // draw and label the circles m.P = 0 with max |m_i| <= this (0: none)
};
// Orthographic view of the sphere (like the paper's figures), with colour bar.
void render_sphere_png(const std::string& path, const std::vector<std::uint64_t>& map, int nside,
                       const RenderOptions& options);
// Mollweide full-sphere image, with colour bar.
void render_mollweide_png(const std::string& path, const std::vector<std::uint64_t>& map,
                          int nside, const RenderOptions& options);

// A figure of several runs of one scene: the main run's sphere with the zoom
// regions of its panels marked, and each panel's zoom beside it (the paper's
// Figures 2 and 3).
struct FigurePanel {
  std::string name, title;
  const Plan* plan = nullptr;
  const Result* result = nullptr;
};
void render_figure_png(const std::string& path, const Plan& plan, const Result& result,
                       const std::vector<FigurePanel>& panels, const RenderOptions& options);

// Writes figure.png for a run and its panels into `dir` (nothing if the build
// has no pictures); returns the path written, or "".
std::string write_figure(const std::string& dir, const Plan& plan, const Result& result,
                         const std::vector<FigurePanel>& panels);

// Draws the pictures of an output directory written earlier (from its
// summary.json and map.h5; e.g. a GPU node's run, on a machine with cairo),
// its panels' and figure.png. Returns the paths written.
std::vector<std::string> render_saved(const std::string& dir);

}  // namespace arnoldweb
