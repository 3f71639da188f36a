// arnoldweb (internal): reading back an output directory written earlier:
// its summary.json and the maps of its map.h5. render_saved and
// read_saved_maps both read through these.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

// <dir>/summary.json, parsed. OutputError naming the directory when it does
// not exist, the file when it cannot be read or is not JSON.
nlohmann::json read_summary(const std::string& dir);

// <dir>/map.h5 into r.map, r.frames (one map per frame), r.zoom and r.nside
// (the map's "nside" attribute). Returns the zoom's resolution (0: none).
// OutputError naming the file when it is missing, unreadable or inconsistent.
int read_map_h5(const std::string& dir, Result& r);

}  // namespace arnoldweb::detail
