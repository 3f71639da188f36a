// arnoldweb: the reduction of a run: what every chunk produced, folded into
// one result. It is exact and mergeable, so the result does not depend on how
// the index range was cut into chunks, in which order they were folded, or how
// many reductions (processes, resumed runs) they were spread over:
//  - counters and histograms are 64-bit integer sums;
//  - the energy statistics are a maximum and an exact sum (exact_sum.hpp) of
//    the devices' group sums (a device's groups are aligned to absolute
//    trajectory indices when chunks start at multiples of kChunkGranule);
//  - the records (the output table's per-trajectory outputs) are kept by
//    chunk and read out in trajectory order, one Records per output;
//  - the trajectories done are a set of index ranges.
// A reduction has a byte image (checkpoints, messages between processes).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "arnoldweb/device.hpp"
#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"
#include "run/exact_sum.hpp"

namespace arnoldweb::detail {

// Chunks start at multiples of this many trajectories (unless the scene sets
// ensemble.chunk): a multiple of every device's group span (cpu 256, OpenCL
// 8 lanes x 16 or 128 items, CUDA 128), so each group's energy sum covers the
// same trajectories however the range is chunked.
constexpr std::uint64_t kChunkGranule = 1024;

struct IndexRange {
  std::uint64_t first = 0, count = 0;
  std::uint64_t end() const { return first + count; }
};

// The per-trajectory outputs of a plan, empty (Result::records), and the
// records of the trajectories of one arena appended to them (an arena holds
// rec_reals reals and rec_ints integers per trajectory, as the kernel writes).
std::vector<Records> empty_records(const Plan& plan);
void append_records(const Plan& plan, const std::vector<double>& reals, const std::vector<std::int64_t>& ints,
                    std::vector<Records>& records);
// The picked rows' records (RecordOutput::picked) from the histogram buffer's words.
void picked_from_words(const Plan& plan, const std::vector<std::uint64_t>& words, std::vector<Records>& records);

// The block of trajectories a time-sliced plan runs per launch.
std::uint64_t slice_block(const Plan& plan);

class Reduction {
 public:
  explicit Reduction(const Plan& plan);

  // The outputs of the chunk of trajectories [first, first + count) run over
  // their whole schedule.
  void add(std::uint64_t first, std::uint64_t count, ChunkOutput& out);
  // The outputs of a launch: over the whole schedule, or one time slice
  // (plan.slices > 1: a slice that does not end the trajectories leaves their
  // carry for the next).
  void add(const ChunkWork& work, ChunkOutput& out);

  // Time slices (plan.slices > 1): the trajectories go in fixed blocks
  // (slice_block), and every block finishes slice s before any begins s + 1
  // (each slice advances every trajectory). The next block and slice, with the
  // records it starts from in rec_r, rec_i (count 0: every slice is done).
  ChunkWork next_slice(std::vector<double>& rec_r, std::vector<std::int64_t>& rec_i) const;
  // Trajectory-slices done, in units of trajectories (progress: N when complete).
  std::uint64_t progress() const;
  // Adds a device's histograms (plan.frames maps of plan.npix pixels, then
  // the zoom), accumulated over the chunks it ran.
  void add_histograms(const std::vector<std::uint64_t>& histograms);
  // Folds another reduction of the same plan in (disjoint chunks).
  void merge(const Reduction& other);

  std::uint64_t completed() const { return completed_; }
  bool complete() const { return completed_ == plan_->scene.trajectories; }
  // The ranges of [0, N) not done yet, in order (within `only`, if restricted).
  std::vector<IndexRange> pending() const;
  // Runs only trajectories `only` (run_range).
  void restrict_to(const IndexRange& only) { only_first_ = only.first, only_end_ = only.end(); }
  // Wall seconds of computing recorded so far (resumed runs add theirs).
  double seconds = 0;
  std::vector<std::uint64_t> chunks;  // sizes of the launches, in the order they were added

  // The result (counts, statistics, maps, states); device, timing and chunk
  // sizes are the runner's to fill in.
  Result result() const;

  // Byte image of everything above; read() checks it against the plan and
  // throws std::runtime_error naming what does not fit.
  std::string image() const;
  static Reduction read(const Plan& plan, const std::string& image);

 private:
  void mark_done(std::uint64_t first, std::uint64_t count);
  const Plan* plan_;
  std::uint64_t completed_ = 0;
  std::uint64_t only_first_ = 0, only_end_ = ~0ull;  // the trajectories to run (all)
  std::map<std::uint64_t, std::uint64_t> done_;  // first -> end, disjoint, not adjacent
  std::vector<std::uint64_t> counters_;  // AW_C_COUNT
  double emax_ = 0;
  ExactSum esum_;
  std::vector<std::uint64_t> histograms_;  // plan.hist_size, or empty while none were added
  struct Arenas {
    std::vector<double> reals;
    std::vector<std::int64_t> ints;
    // the device's on their memory (ChunkOutput::holds): released with them (when arenas are
    // replaced, just after the old ones are freed: letting go of a lock touches no data)
    std::vector<std::shared_ptr<void>> holds;
  };
  std::map<std::uint64_t, Arenas> records_;  // the chunks' record arenas, by first trajectory of the chunk
  // time slices: per block (by its first trajectory), how many slices are done
  // and the carry the last one left (the block's records)
  struct Block {
    std::uint64_t count = 0;
    std::int64_t slices_done = 0;
    Arenas carry;
  };
  std::map<std::uint64_t, Block> blocks_;
};

}  // namespace arnoldweb::detail
