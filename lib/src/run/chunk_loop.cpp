// arnoldweb: the loop that keeps one device busy (chunk_loop.hpp).
#include "run/chunk_loop.hpp"

#include <algorithm>
#include <chrono>

namespace arnoldweb::detail {
namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::uint64_t align_up(std::uint64_t v, std::uint64_t g) { return (v + g - 1) / g * g; }

}  // namespace

std::uint64_t chunk_granule(const Plan& plan, std::uint64_t max_chunk) {
  const std::uint64_t g = plan.scene.chunk ? plan.scene.chunk : kChunkGranule;
  return std::max<std::uint64_t>(1, std::min(g, max_chunk));
}

IndexRange take_range(std::vector<IndexRange>& pending, std::uint64_t want, std::uint64_t granule) {
  while (!pending.empty() && pending.front().count == 0) pending.erase(pending.begin());
  if (pending.empty()) return {};
  IndexRange& p = pending.front();
  std::uint64_t end = p.first + std::max<std::uint64_t>(want, 1);
  if (end >= p.end()) {
    end = p.end();
  } else if (end / granule * granule > p.first) {
    end = end / granule * granule;
  }
  const IndexRange r{p.first, end - p.first};
  p.first = end;
  p.count -= r.count;
  if (p.count == 0) pending.erase(pending.begin());
  return r;
}

void drive_device(const Plan& plan, Backend& backend, WorkQueue& queue, const RunOptions& options) {
  const std::uint64_t max_chunk = largest_chunk(plan);
  backend.prepare(plan, max_chunk);
  const std::uint64_t granule = chunk_granule(plan, max_chunk);
  // A launch below one wave of the device takes as long as a full wave (each
  // thread integrates its whole trajectory), so chunks never shrink below it.
  const std::uint64_t min_chunk =
      std::min(max_chunk, align_up(std::max<std::uint64_t>(1, backend.preferred_chunk() / 4), granule));
  std::uint64_t want = plan.scene.chunk ? std::min(plan.scene.chunk, max_chunk) : min_chunk;
  IndexRange done{};
  ChunkOutput out;
  for (;;) {
    const IndexRange r = queue.next(done, out, want, backend);
    if (r.count == 0) break;
    const double t0 = now_seconds();
    backend.run_chunk(r.first, r.count, out);
    const double dt = now_seconds() - t0;
    done = r;
    if (!plan.scene.chunk && dt > 0) {
      // aim at chunk_seconds per launch; grow at most 4x at a time
      const double target = static_cast<double>(r.count) * options.chunk_seconds / dt;
      const double c = std::clamp(target, 1.0, 4.0 * static_cast<double>(r.count));
      want = std::clamp<std::uint64_t>(align_up(static_cast<std::uint64_t>(c), granule), min_chunk, max_chunk);
    }
  }
}

LocalQueue::LocalQueue(const Plan& plan, Reduction& reduction, const RunOptions& options, After after)
    : plan_(plan),
      reduction_(reduction),
      options_(options),
      after_(std::move(after)),
      pending_(reduction.pending()),
      granule_(chunk_granule(plan, largest_chunk(plan))),
      start_(now_seconds()) {}

double LocalQueue::seconds() const { return now_seconds() - start_; }

IndexRange LocalQueue::next(const IndexRange& finished, const ChunkOutput& out, std::uint64_t want,
                            Backend& backend) {
  const std::uint64_t n = plan_.scene.trajectories;
  if (finished.count) {
    reduction_.add(finished.first, finished.count, out);
    if (options_.progress) options_.progress->update(reduction_.completed(), n, seconds());
  }
  const bool stopping = options_.stop && options_.stop->load() && !reduction_.complete();
  if (after_) after_(backend, stopping);
  if (stopping) {
    stopped_ = true;
    return {};
  }
  return take_range(pending_, want, granule_);
}

}  // namespace arnoldweb::detail
