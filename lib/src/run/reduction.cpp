// arnoldweb: the reduction of a run (reduction.hpp).
#include "run/reduction.hpp"

#include <algorithm>

#include "aw_params.h"

namespace arnoldweb::detail {

Reduction::Reduction(const Plan& plan) : plan_(plan), counters_(AW_C_COUNT, 0) {}

void Reduction::add(std::uint64_t first, std::uint64_t count, const ChunkOutput& out) {
  for (std::size_t c = 0; c < counters_.size() && c < out.counters.size(); ++c) counters_[c] += out.counters[c];
  for (std::size_t g = 0; g + 1 < out.group_stats.size(); g += AW_GROUP_STATS) {
    emax_ = std::max(emax_, out.group_stats[g]);
    esum_ += out.group_stats[g + 1];
  }
  if (!out.initial_r.empty() || !out.final_r.empty()) states_[first] = {out.initial_r, out.final_r, out.final_i};
  completed_ += count;
}

void Reduction::set_histograms(const std::vector<std::uint64_t>& histograms) { histograms_ = histograms; }

Result Reduction::result() const {
  Result r;
  r.trajectories = plan_.scene.trajectories;
  r.completed = completed_;
  r.nside = plan_.scene.velocity_map ? plan_.scene.nside : 0;
  r.binned = counters_[AW_C_BINNED];
  r.flagged_nonfinite = counters_[AW_C_FLAG_NONFINITE];
  r.flagged_energy = counters_[AW_C_FLAG_ENERGY];
  r.flagged_initial = counters_[AW_C_FLAG_INITIAL];
  r.left_region = counters_[AW_C_LEFT_REGION];
  r.energy.tracked = (plan_.kernel.features & AW_F_ENERGY) != 0;
  if (r.energy.tracked)
    r.energy.log_hist.assign(counters_.begin() + AW_C_EHIST, counters_.begin() + AW_C_EHIST + AW_EHIST_BINS);
  r.energy.max = emax_;
  r.energy.mean = r.binned ? esum_ / static_cast<double>(r.binned) : 0.0;
  // the histograms: F frames of the map, then the zoom
  const std::uint64_t npix = plan_.npix;
  r.map.assign(npix, 0);
  if (histograms_.size() >= static_cast<std::size_t>(plan_.frames) * npix) {
    for (int f = 0; f < plan_.frames; ++f) {
      const auto first = histograms_.begin() + static_cast<std::ptrdiff_t>(f * npix);
      if (plan_.frames > 1) r.frames.emplace_back(first, first + static_cast<std::ptrdiff_t>(npix));
      for (std::uint64_t i = 0; i < npix; ++i) r.map[i] += first[static_cast<std::ptrdiff_t>(i)];
    }
    r.zoom.assign(histograms_.begin() + static_cast<std::ptrdiff_t>(plan_.frames * npix), histograms_.end());
  }
  for (const auto& [first, s] : states_) {
    r.initial_r.insert(r.initial_r.end(), s.initial_r.begin(), s.initial_r.end());
    r.final_r.insert(r.final_r.end(), s.final_r.begin(), s.final_r.end());
    r.final_i.insert(r.final_i.end(), s.final_i.begin(), s.final_i.end());
  }
  return r;
}

}  // namespace arnoldweb::detail
