// arnoldweb: the reduction of a run: what every chunk produced, folded into
// one result. Counters are 64-bit sums, the energy statistics a maximum and
// a sum taken in chunk and group order, state records kept in trajectory
// order, the histograms (folded on the device) split into the map, its frames
// and the zoom. One place for all of it, used by the runner (and by several
// processes later: a reduction can be merged with another's).
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "arnoldweb/device.hpp"
#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

class Reduction {
 public:
  explicit Reduction(const Plan& plan);

  // The outputs of the chunk of trajectories [first, first + count).
  void add(std::uint64_t first, std::uint64_t count, const ChunkOutput& out);
  // The device's histograms: plan.frames maps of plan.npix pixels, then the zoom.
  void set_histograms(const std::vector<std::uint64_t>& histograms);

  std::uint64_t completed() const { return completed_; }

  // The result (counts, statistics, maps, states); device, timing and chunk
  // sizes are the runner's to fill in.
  Result result() const;

 private:
  const Plan& plan_;
  std::uint64_t completed_ = 0;
  std::vector<std::uint64_t> counters_;  // AW_C_COUNT
  double emax_ = 0, esum_ = 0;
  std::vector<std::uint64_t> histograms_;
  struct States {
    std::vector<double> initial_r, final_r;
    std::vector<std::int64_t> final_i;
  };
  std::map<std::uint64_t, States> states_;  // by first trajectory of the chunk
};

}  // namespace arnoldweb::detail
