// arnoldweb: the chunk driver. A run is a sequence of launches over
// consecutive index ranges, sized to about RunOptions::chunk_seconds each;
// their outputs go into the run's reduction (reduction.hpp).
#include "arnoldweb/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "run/reduction.hpp"

namespace arnoldweb {
Result run(const Plan& plan, Backend& backend, const RunOptions& options) {
  using clock = std::chrono::steady_clock;
  const std::uint64_t n = plan.scene.trajectories;
  const std::uint64_t max_chunk = largest_chunk(plan);
  const auto t_start = clock::now();
  backend.prepare(plan, max_chunk);
  // A launch below one wave of the device takes as long as a full wave (each
  // thread integrates its whole trajectory), so chunks never shrink below it.
  const std::uint64_t min_chunk = std::min(max_chunk, std::max<std::uint64_t>(1, backend.preferred_chunk() / 4));
  std::uint64_t chunk = plan.scene.chunk ? plan.scene.chunk : min_chunk;
  detail::Reduction reduction(plan);
  std::vector<std::uint64_t> chunks;
  bool interrupted = false;
  ChunkOutput out;
  const auto t_run = clock::now();
  for (std::uint64_t done = 0; done < n;) {
    const std::uint64_t count = std::min(chunk, n - done);
    const auto t0 = clock::now();
    backend.run_chunk(done, count, out);
    const double dt = std::chrono::duration<double>(clock::now() - t0).count();
    reduction.add(done, count, out);
    chunks.push_back(count);
    done += count;
    const double elapsed = std::chrono::duration<double>(clock::now() - t_run).count();
    if (options.progress) options.progress->update(done, n, elapsed);
    if (options.stop && options.stop->load() && done < n) {
      interrupted = true;
      break;
    }
    if (!plan.scene.chunk && dt > 0) {
      // aim at chunk_seconds per launch; grow at most 4x at a time
      const double target = static_cast<double>(count) * options.chunk_seconds / dt;
      chunk = static_cast<std::uint64_t>(std::clamp(target, 1.0, 4.0 * static_cast<double>(count)));
      chunk = std::clamp<std::uint64_t>(chunk, min_chunk, max_chunk);
    }
  }
  reduction.set_histograms(backend.read_histograms());
  Result r = reduction.result();
  r.device = backend.info();
  r.kernel = backend.kernel_description();
  r.interrupted = interrupted;
  r.chunks = std::move(chunks);
  r.wall_seconds = std::chrono::duration<double>(clock::now() - t_start).count();
  r.trajectory_steps = static_cast<double>(r.completed) * static_cast<double>(plan.steps_per_trajectory);
  if (options.progress) options.progress->finish(r.completed, n, r.wall_seconds);
  return r;
}

}  // namespace arnoldweb
