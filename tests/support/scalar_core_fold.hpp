// arnoldweb tests: the fold of the scalar reference run (scalar_core.hpp),
// written once for the double and float cores (scalar_core.cpp,
// scalar_core_float.cpp: a translation unit can hold only one of them).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"
#include "aw_params.h"
#include "run/reduction.hpp"

namespace awtest::scalar_detail {

// Every trajectory in one chunk, one per call of the core's aw_ensemble_item
// (AW_LANES = 1); the types are core_d's or core_f's.
template <class Real, class RParams, class IParams, class Outputs, class Lanes, class Config, class Item>
arnoldweb::Result run(const arnoldweb::Plan& plan, const RParams* rp, const IParams* ip, Item item) {
  const std::uint64_t n = plan.scene.trajectories;
  const std::uint32_t features = plan.kernel.features;
  std::vector<std::uint32_t> hist(std::max<std::uint64_t>(plan.hist_size, 1), 0);
  std::vector<std::uint32_t> counters(AW_C_COUNT, 0);
  std::vector<Real> rec_r(n * static_cast<std::uint64_t>(ip->rec_reals));
  std::vector<std::int64_t> rec_i(n * static_cast<std::uint64_t>(ip->rec_ints));
  Outputs out = {hist.data(), counters.data(), rec_r.empty() ? nullptr : rec_r.data(),
                 rec_i.empty() ? nullptr : rec_i.data()};
  const Config cfg = {features, plan.kernel.stages, plan.kernel.kick_first ? 1 : 0, plan.kernel.initial,
                      plan.kernel.gradient ? 1 : 0};
  // One trajectory per call; the calls share the histograms and counters
  // through the core's own atomic increments, as a device's work-items do.
  // Threads only share the work: no lane, block or chunk structure of any
  // backend is reproduced, and the energy statistics are folded in trajectory
  // order below.
  std::vector<Real> item_max(n), item_sum(n);
  const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(dynamic, 64)
  for (std::int64_t t = 0; t < count; ++t) {
    const Lanes l = {static_cast<std::uint64_t>(t), n, 0};
    item(cfg, l, std::int64_t{0}, plan.windows * plan.segments_per_window, rp, ip, out,
         &item_max[static_cast<std::size_t>(t)], &item_sum[static_cast<std::size_t>(t)]);
  }
  double emax = 0, esum = 0;
  for (std::uint64_t t = 0; t < n; ++t) {
    emax = std::max(emax, static_cast<double>(item_max[t]));
    esum += static_cast<double>(item_sum[t]);
  }

  arnoldweb::Result r;
  r.device.id = "scalar core";
  r.device.name = "the device core compiled in the test binary, one lane";
  r.trajectories = r.completed = n;
  r.binned = counters[AW_C_BINNED];
  r.flagged_nonfinite = counters[AW_C_FLAG_NONFINITE];
  r.flagged_energy = counters[AW_C_FLAG_ENERGY];
  r.flagged_initial = counters[AW_C_FLAG_INITIAL];
  r.left_region = counters[AW_C_LEFT_REGION];
  r.energy.tracked = (features & AW_F_ENERGY) != 0;
  if (r.energy.tracked)
    r.energy.log_hist.assign(counters.begin() + AW_C_EHIST, counters.begin() + AW_C_EHIST + AW_EHIST_BINS);
  r.energy.max = emax;
  r.energy.mean = r.binned ? esum / static_cast<double>(r.binned) : 0.0;
  r.nside = plan.scene.velocity_map ? plan.scene.nside : 0;
  const std::uint64_t npix = plan.npix;
  r.map.assign(npix, 0);
  if (plan.hist_size) {
    for (int f = 0; f < plan.frames; ++f) {
      std::vector<std::uint64_t> frame(hist.begin() + static_cast<std::ptrdiff_t>(f * npix),
                                       hist.begin() + static_cast<std::ptrdiff_t>((f + 1) * npix));
      for (std::uint64_t i = 0; i < npix; ++i) r.map[i] += frame[i];
      if (plan.frames > 1) r.frames.push_back(std::move(frame));
    }
    const auto zoom = hist.begin() + static_cast<std::ptrdiff_t>(plan.frames * npix);
    r.zoom.assign(zoom, zoom + static_cast<std::ptrdiff_t>(plan.zoom_resolution) * plan.zoom_resolution);
  }
  r.records = arnoldweb::detail::empty_records(plan);
  arnoldweb::detail::append_records(plan, std::vector<double>(rec_r.begin(), rec_r.end()), rec_i, r.records);
  arnoldweb::detail::picked_from_words(plan, std::vector<std::uint64_t>(hist.begin(), hist.end()), r.records);
  r.chunks = {n};
  return r;
}

}  // namespace awtest::scalar_detail
