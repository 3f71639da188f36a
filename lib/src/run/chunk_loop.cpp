// arnoldweb: the loop that keeps one device busy (chunk_loop.hpp).
#include "run/chunk_loop.hpp"

#include <algorithm>
#include <chrono>

#include "aw_params.h"
#include "plan/plan_params.hpp"

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
  const std::uint64_t max_chunk = largest_chunk(plan, backend.info());
  backend.prepare(plan, max_chunk);
  const std::uint64_t granule = chunk_granule(plan, max_chunk);
  // A launch below one wave of the device takes as long as a full wave (each
  // thread integrates its whole trajectory), so chunks never shrink below it.
  const std::uint64_t min_chunk =
      std::min(max_chunk, align_up(std::max<std::uint64_t>(1, backend.preferred_chunk() / 4), granule));
  std::uint64_t want = plan.scene.chunk ? std::min(plan.scene.chunk, max_chunk) : min_chunk;
  ChunkWork done{};
  ChunkOutput out;
  backend.startup.first_launch_seconds = 0;  // until this part's first launch
  for (;;) {
    const ChunkWork r = queue.next(done, out, want, backend);
    if (r.count == 0) break;
    const double t0 = now_seconds();
    backend.run_chunk(r, out);
    const double dt = now_seconds() - t0;
    if (!done.count) backend.startup.first_launch_seconds = dt;
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

ChunkWork LocalQueue::next(const ChunkWork& finished, ChunkOutput& out, std::uint64_t want, Backend& backend) {
  const std::uint64_t n = plan_.scene.trajectories;
  if (finished.count) {
    reduction_.add(finished, out);
    if (options_.progress) options_.progress->update(reduction_.progress(), n, seconds());
  }
  const bool stopping = options_.stop && options_.stop->load() && !reduction_.complete();
  if (after_) after_(backend, stopping);
  if (stopping) {
    stopped_ = true;
    return {};
  }
  if (plan_.slices > 1) return reduction_.next_slice(rec_r_, rec_i_);
  return whole_work(plan_, take_range(pending_, want, granule_), rec_r_, rec_i_);
}

void initial_records(const Plan& plan, std::uint64_t first, std::uint64_t count, std::vector<double>& rec_r,
                     std::vector<std::int64_t>& rec_i) {
  const IntParams& ip = params(plan).ints;
  const std::size_t nr = static_cast<std::size_t>(ip.rec_reals), ni = static_cast<std::size_t>(ip.rec_ints);
  rec_r.assign(count * nr, 0.0);
  rec_i.assign(count * ni, 0);
  const StateSet& s = *plan.states;
  const std::size_t cr = static_cast<std::size_t>(ip.rec_col_r[AW_OUT_CARRY]);
  const std::size_t ci = static_cast<std::size_t>(ip.rec_col_i[AW_OUT_CARRY]);
  for (std::uint64_t t = 0; t < count; ++t) {
    const std::size_t i = static_cast<std::size_t>(first + t);
    for (std::size_t c = 0; c < 3; ++c) {
      rec_r[t * nr + cr + c] = s.position_turns[3 * i + c];
      rec_r[t * nr + cr + 3 + c] = s.momentum[3 * i + c];
      rec_i[t * ni + ci + c] = s.winding.empty() ? 0 : s.winding[3 * i + c];
    }
    rec_i[t * ni + ci + 3] = s.status.empty() ? AW_STATUS_OK : s.status[i];
  }
}

ChunkWork whole_work(const Plan& plan, const IndexRange& range, std::vector<double>& rec_r,
                     std::vector<std::int64_t>& rec_i) {
  ChunkWork w;
  w.first = range.first;
  w.count = range.count;
  if (range.count && plan.states) {
    initial_records(plan, range.first, range.count, rec_r, rec_i);
    w.rec_r = &rec_r;
    w.rec_i = &rec_i;
  }
  return w;
}

}  // namespace arnoldweb::detail
