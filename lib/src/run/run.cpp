// arnoldweb: the chunk driver. A run is a sequence of launches over
// consecutive index ranges; counts are folded into 64-bit totals, energy
// statistics reduced in launch and group order.
#include "arnoldweb/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "aw_params.h"

namespace arnoldweb {
namespace {

constexpr std::uint64_t kMaxChunkStates = 1u << 20;  // trajectories per launch with state records
constexpr std::uint64_t kMaxChunk = 1ull << 30;

}  // namespace

Result run(const Plan& plan, Backend& backend, const RunOptions& options) {
  using clock = std::chrono::steady_clock;
  const std::uint64_t n = plan.scene.trajectories;
  Result r;
  r.device = backend.info();
  r.trajectories = n;
  r.nside = plan.scene.velocity_map ? plan.scene.nside : 0;
  r.energy.tracked = (plan.kernel.features & AW_F_ENERGY) != 0;
  r.energy.log_hist.assign(AW_EHIST_BINS, 0);

  const bool states = (plan.kernel.features & (AW_F_INITIAL_STATES | AW_F_FINAL_STATES)) != 0;
  std::uint64_t max_chunk = states ? kMaxChunkStates : kMaxChunk;
  // 32-bit counts per launch: windows * chunk must stay below 2^32
  max_chunk = std::min<std::uint64_t>(max_chunk, 4000000000ull / static_cast<std::uint64_t>(plan.windows));
  if (plan.scene.chunk) max_chunk = plan.scene.chunk;
  max_chunk = std::max<std::uint64_t>(1, std::min(max_chunk, n));

  const auto t_start = clock::now();
  backend.prepare(plan, max_chunk);
  r.kernel = backend.kernel_description();
  // A launch below one wave of the device takes as long as a full wave (each
  // thread integrates its whole trajectory), so chunks never shrink below it.
  const std::uint64_t min_chunk = std::min(max_chunk, std::max<std::uint64_t>(1, backend.preferred_chunk() / 4));
  std::uint64_t chunk = plan.scene.chunk ? plan.scene.chunk : min_chunk;
  double esum = 0;
  std::uint64_t done = 0;
  ChunkOutput out;
  const auto t_run = clock::now();
  while (done < n) {
    const std::uint64_t count = std::min(chunk, n - done);
    const auto t0 = clock::now();
    backend.run_chunk(done, count, out);
    const double dt = std::chrono::duration<double>(clock::now() - t0).count();
    r.chunks.push_back(count);

    r.binned += out.counters[AW_C_BINNED];
    r.flagged_nonfinite += out.counters[AW_C_FLAG_NONFINITE];
    r.flagged_energy += out.counters[AW_C_FLAG_ENERGY];
    r.flagged_initial += out.counters[AW_C_FLAG_INITIAL];
    r.left_region += out.counters[AW_C_LEFT_REGION];
    for (int b = 0; b < AW_EHIST_BINS; ++b) r.energy.log_hist[b] += out.counters[AW_C_EHIST + b];
    for (std::size_t g = 0; g + 1 < out.group_stats.size(); g += 2) {
      r.energy.max = std::max(r.energy.max, out.group_stats[g]);
      esum += out.group_stats[g + 1];
    }
    r.initial_r.insert(r.initial_r.end(), out.initial_r.begin(), out.initial_r.end());
    r.final_r.insert(r.final_r.end(), out.final_r.begin(), out.final_r.end());
    r.final_i.insert(r.final_i.end(), out.final_i.begin(), out.final_i.end());
    done += count;

    const double elapsed = std::chrono::duration<double>(clock::now() - t_run).count();
    if (options.progress) options.progress->update(done, n, elapsed);
    if (options.stop && options.stop->load() && done < n) {
      r.interrupted = true;
      break;
    }
    if (!plan.scene.chunk && dt > 0) {
      // aim at chunk_seconds per launch; grow at most 4x at a time
      const double target = static_cast<double>(count) * options.chunk_seconds / dt;
      chunk = static_cast<std::uint64_t>(std::clamp(target, 1.0, 4.0 * static_cast<double>(count)));
      chunk = std::clamp<std::uint64_t>(chunk, min_chunk, max_chunk);
    }
  }
  r.completed = done;
  // the device's histograms: F frames of the map, then the zoom
  const std::vector<std::uint64_t> hist = backend.read_histograms();
  const std::uint64_t npix = plan.npix;
  r.map.assign(npix, 0);
  for (int f = 0; f < plan.frames; ++f) {
    const auto first = hist.begin() + static_cast<std::ptrdiff_t>(f * npix);
    if (plan.frames > 1) r.frames.emplace_back(first, first + static_cast<std::ptrdiff_t>(npix));
    for (std::uint64_t i = 0; i < npix; ++i) r.map[i] += first[static_cast<std::ptrdiff_t>(i)];
  }
  r.zoom.assign(hist.begin() + static_cast<std::ptrdiff_t>(plan.frames * npix), hist.end());
  if (!r.energy.tracked) r.energy.log_hist.clear();
  r.energy.mean = r.binned ? esum / static_cast<double>(r.binned) : 0.0;
  r.wall_seconds = std::chrono::duration<double>(clock::now() - t_start).count();
  r.trajectory_steps = static_cast<double>(done) * static_cast<double>(plan.steps_per_trajectory);
  if (options.progress) options.progress->finish(done, n, r.wall_seconds);
  return r;
}

}  // namespace arnoldweb
