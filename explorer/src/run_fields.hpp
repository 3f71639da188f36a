// arnoldweb explorer: a run's per-trajectory outputs as the page shows them: every real
// dataset of one value per trajectory of a grid run (FLI, MEGNO, the diffusion index, ...: the
// output table's rows, output_locations()) as a field over the grid, and the first window's
// frequencies (nu_first) of any run for the frequency map. Read from the checked bytes of the
// files (read_saved_file), parsed by HDF5 in memory.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "arnoldweb/scene.hpp"

namespace arnoldweb::explorer {

// {name: {grid: "healpix"|"lonlat"|"plane", shape: [n2, n1] or [n], nside, x: [from, to],
//  y: [from, to], labels, values: [...] (null for NaN)}, "frequencies": {nu1: [...], nu2: [...]}}
// or {} for a run without them. SavedRunError naming a damaged file.
nlohmann::json read_run_fields(const std::string& dir, const nlohmann::json& summary, const Scene& scene);

}  // namespace arnoldweb::explorer
