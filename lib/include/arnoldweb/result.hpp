// arnoldweb: what a run produced. Counts are exact 64-bit integers; digests
// identify maps and states bit for bit across devices and chunkings.
#pragma once

#include <cstdint>
#include <map>
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

// One per-trajectory output of a run, in trajectory order: `reals_per` reals
// and `ints_per` integers for every completed trajectory. For example
// "final_states": u_x, u_y, u_z (turns), p_x, p_y, p_z and winding x, y, z,
// status; "indicators": FLI, MEGNO <Y>, the Lyapunov exponent from MEGNO's
// slope and the finite-time Lyapunov exponent (1/T; NaN where not asked or
// flagged). The columns are listed in docs/outputs.md.
struct Records {
  std::string name;
  std::size_t reals_per = 0, ints_per = 0;
  std::vector<double> reals;
  std::vector<std::int64_t> ints;
  std::uint64_t count() const { return reals_per ? reals.size() / reals_per : ints_per ? ints.size() / ints_per : 0; }
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

  // The per-trajectory outputs the plan asked for, one per row of the output
  // table (docs/outputs.md: "initial_states", "final_states", "indicators",
  // ...), in the table's order.
  std::vector<Records> records;
  // The records of an output, or nullptr when the run has none.
  const Records* records_of(const std::string& name) const;
  // Its reals and integers (empty when the run has none).
  const std::vector<double>& reals(const std::string& name) const;
  const std::vector<std::int64_t>& ints(const std::string& name) const;

  // What was computed from the records once the run ended, as JSON by name
  // ("diffusion": the moments and the diffusion coefficients of
  // observe.diffusion); summary.json holds them under "analyses".
  std::map<std::string, std::string> analyses;

  double wall_seconds = 0;
  double trajectory_steps = 0;  // completed * steps per trajectory
  double rate() const { return wall_seconds > 0 ? trajectory_steps / wall_seconds : 0; }
  std::vector<std::uint64_t> chunks;  // size of every launch, in order
  // The start-up, each device's for this part in the order of the devices
  // (the devices of this process; under MPI, rank 0's).
  Startup startup;
};

// XXH3-128 digests, as 32 hex digits: of the map, and of an output's records
// (its reals, then its integers; "" if the run has none).
std::string digest_map(const Result& r);
std::string digest_records(const Result& r, const std::string& name);

}  // namespace arnoldweb
