// arnoldweb: the pictures live in a plugin, libarnoldweb_pictures.so
// (lib/src/pictures/, the only code that links cairo), opened at run time
// from beside this library. Where it cannot be opened (a build without cairo,
// or a machine without cairo's X11 libraries, such as a headless GPU node
// that installed the Python wheel) every number is still computed and
// written, and a run says that it drew no pictures and why
// (docs/design.md, "Pictures as a plugin").
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "arnoldweb/output.hpp"
#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

// What the plugin offers (lib/src/pictures/plugin_entry.cpp fills it). The
// plugin is built with this library, from this header: `version` must equal
// ARNOLDWEB_VERSION and `size` sizeof(PictureFunctions).
struct PictureFunctions {
  const char* version;
  std::size_t size;
  void (*sphere)(const std::string& path, const std::vector<std::uint64_t>& map, int nside, const RenderOptions& o);
  void (*mollweide)(const std::string& path, const std::vector<std::uint64_t>& map, int nside,
                    const RenderOptions& o);
  void (*zoom)(const std::string& path, const std::vector<std::uint64_t>& zoom, int resolution,
               const std::array<double, 2>& center, double width, const RenderOptions& o);
  void (*figure)(const std::string& path, const Plan& plan, const Result& result,
                 const std::vector<FigurePanel>& panels, const RenderOptions& o);
  // the pictures the output table names (its datasets' grid pictures, its rows' `pictures`: rows of the
  // plugin's picture table, lib/src/pictures/picture_table.hpp), into `dir`, their names appended to `names`
  void (*outputs)(const Plan& plan, const Result& result, const std::string& dir, std::vector<std::string>& names);
  // whether the picture table has a row of this name
  bool (*draws)(const std::string& picture);
};

// The name of the plugin's entry point: const PictureFunctions* (void).
inline constexpr const char* kPictureEntryPoint = "arnoldweb_picture_functions";

// The plugin of this process, opened on first use: $ARNOLDWEB_PICTURES when
// set, else libarnoldweb_pictures.so in this library's folder. nullptr, with
// `why` set, when there is none or it cannot be opened (the loader's message:
// which library is missing).
const PictureFunctions* picture_functions(std::string* why = nullptr);

// Opens the plugin at `path` (kept open when it is one): nullptr with `why`.
const PictureFunctions* open_picture_plugin(const std::string& path, std::string* why);

}  // namespace arnoldweb::detail
