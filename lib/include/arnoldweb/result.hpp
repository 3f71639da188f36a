// arnoldweb: what a run produced. Counts are exact 64-bit integers; digests
// identify maps and states bit for bit across devices and chunkings.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "arnoldweb/device.hpp"

namespace arnoldweb {

struct EnergyStats {
  bool tracked = false;
  double max = 0;    // max over binned trajectories of max_t |E(t) - E(0)|
  double mean = 0;   // mean of the same over binned trajectories
  // log2 histogram of max|dE| over all trajectories (AW_EHIST_* layout):
  // bin 0: < 2^-64, bin 1 + 4 (e - 1 + 64) + q: [2^(e-1) (1 + q/4), ...), last: >= 2^16
  std::vector<std::uint64_t> log_hist;
  // Upper edge of the histogram bin holding the q-quantile (q in [0, 1]).
  double quantile(double q) const;
};

struct Result {
  DeviceInfo device;
  std::string kernel;  // compiler options / variant

  std::uint64_t trajectories = 0;  // asked for
  std::uint64_t completed = 0;     // integrated (== trajectories unless interrupted)
  std::uint64_t binned = 0;        // contributed every window to the map
  std::uint64_t flagged_nonfinite = 0;
  std::uint64_t flagged_energy = 0;
  std::uint64_t flagged_initial = 0;
  std::uint64_t flagged() const { return flagged_nonfinite + flagged_energy + flagged_initial; }
  std::uint64_t left_region = 0;   // not binned: left the confinement region (not an error)
  bool interrupted = false;

  EnergyStats energy;
  int nside = 0;
  std::vector<std::uint64_t> map;  // RING order, 12 nside^2 counts (windows binned; all frames)
  std::vector<std::vector<std::uint64_t>> frames;  // one map per frame (observe.frames)
  std::vector<std::uint64_t> zoom;  // R x R counts, row y then column x (observe.zoom)

  // State records of completed trajectories, in index order (when asked for):
  // AW_STATE_REALS reals (u_x, u_y, u_z in turns, p_x, p_y, p_z) and
  // AW_STATE_INTS integers (winding x, y, z, status) per trajectory.
  std::vector<double> initial_r, final_r;
  std::vector<std::int64_t> final_i;
  // Chaos indicators of completed trajectories, in index order (when asked
  // for): AW_IND_REALS reals per trajectory (FLI, MEGNO <Y>, Lyapunov exponent
  // from MEGNO's slope in 1/T, finite-time Lyapunov exponent in 1/T; NaN where
  // not asked or flagged). docs/indicators.md.
  std::vector<double> indicators;

  double wall_seconds = 0;
  double trajectory_steps = 0;  // completed * steps per trajectory
  double rate() const { return wall_seconds > 0 ? trajectory_steps / wall_seconds : 0; }
  std::vector<std::uint64_t> chunks;  // size of every launch, in order
};

// XXH3-128 digests, as 32 hex digits.
std::string digest_map(const Result& r);
std::string digest_initial_states(const Result& r);  // "" if none
std::string digest_final_states(const Result& r);    // "" if none
std::string digest_indicators(const Result& r);      // "" if none

}  // namespace arnoldweb
