// arnoldweb explorer: a run as the page sees it, read from its output directory through the
// library's checked readers (read_saved_summary, read_saved_maps, read_saved_file): what it
// is (meta, without paths), its map's bytes and its grid fields. Nothing else of the
// directory is read.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "arnoldweb/scene.hpp"

namespace arnoldweb::explorer {

struct RunView {
  std::string dir;                    // as given (never sent to a page)
  std::string id;                     // what the page names it by
  nlohmann::json meta;                // id, title, description, map {nside, dtype}, model, scene
  std::string map_bytes;              // the map, little-endian meta.map.dtype values, RING order
  std::vector<std::uint64_t> counts;  // the same counts (for the chi-square test)
  nlohmann::json fields;              // grid fields and frequencies (run_fields.hpp), {} if none
  Scene scene;                        // the scene as run (summary.json's scene_toml)
};

// SavedRunError naming the file for a directory that is not a readable run.
RunView read_run_view(const std::string& dir, const std::string& id);

// The two-sample chi-square test of two runs' maps (arnoldweb compare), as the page shows it.
nlohmann::json compare_json(const RunView& a, const RunView& b);

// The smallest little-endian type that holds every count: u8, u16, u32 or f64; its bytes.
std::string map_bytes(const std::vector<std::uint64_t>& counts, std::string* dtype);

}  // namespace arnoldweb::explorer
