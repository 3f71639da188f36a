// arnoldweb: the reduction of a run (reduction.hpp).
#include "run/reduction.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "aw_params.h"
#include "output_table/output_table.hpp"
#include "plan/plan_params.hpp"
#include "run/byte_stream.hpp"
#include "run/chunk_loop.hpp"

namespace arnoldweb::detail {

namespace {

// Appends columns [col, col + width) of every record of `arena` (stride reals or integers each) to `out`.
template <class T>
void columns(const std::vector<T>& arena, std::int64_t stride, std::int64_t col, int width, std::vector<T>& out) {
  if (width <= 0 || stride <= 0) return;
  const std::size_t n = arena.size() / static_cast<std::size_t>(stride);
  for (std::size_t t = 0; t < n; ++t) {
    const auto at = arena.begin() + static_cast<std::ptrdiff_t>(t * static_cast<std::size_t>(stride) + static_cast<std::size_t>(col));
    out.insert(out.end(), at, at + width);
  }
}

}  // namespace

std::vector<Records> empty_records(const Plan& plan) {
  const IntParams& ip = params(plan).ints;
  std::vector<Records> records;
  for (const RecordOutput* row : records_reported(plan.kernel.features)) {
    Records& out = records.emplace_back();
    out.name = row->name;
    out.reals_per = static_cast<std::size_t>(row->picked ? row->reals(ip) : ip.rec_width_r[row->slot]);
    out.ints_per = static_cast<std::size_t>(row->picked ? row->ints(ip) : ip.rec_width_i[row->slot]);
  }
  return records;
}

void append_records(const Plan& plan, const std::vector<double>& reals, const std::vector<std::int64_t>& ints,
                    std::vector<Records>& records) {
  const IntParams& ip = params(plan).ints;
  std::size_t k = 0;
  for (const RecordOutput* row : records_reported(plan.kernel.features)) {
    if (row->picked) {  // not in the trajectories' records (picked_from_words)
      ++k;
      continue;
    }
    columns(reals, ip.rec_reals, ip.rec_col_r[row->slot], static_cast<int>(ip.rec_width_r[row->slot]), records.at(k).reals);
    columns(ints, ip.rec_ints, ip.rec_col_i[row->slot], static_cast<int>(ip.rec_width_i[row->slot]), records.at(k).ints);
    ++k;
  }
}

void picked_from_words(const Plan& plan, const std::vector<std::uint64_t>& words, std::vector<Records>& records) {
  const IntParams& ip = params(plan).ints;
  const bool single = plan.kernel.precision == Precision::Float;
  for (Records& rec : records) {
    const RecordOutput* row = find_record_output(rec.name);
    if (!row || !row->picked) continue;
    const std::uint64_t n = picked_records(*row, ip), per = rec.reals_per + rec.ints_per;
    rec.reals.assign(n * rec.reals_per, 0.0);
    rec.ints.assign(n * rec.ints_per, 0);
    const std::uint64_t base = static_cast<std::uint64_t>(ip.pick_base);
    if (words.size() < base + 2 * n * per) continue;  // no launch yet
    // a value's two words (each the sum of one launch's word and zeros: its bits)
    auto bits = [&](std::uint64_t at) { return (words[at] & 0xffffffffu) | (words[at + 1] << 32); };
    for (std::uint64_t m = 0; m < n; ++m) {
      const std::uint64_t at = base + 2 * per * m;
      for (std::size_t c = 0; c < rec.reals_per; ++c) {
        const std::uint64_t b = bits(at + 2 * c);
        double v;
        if (single) {
          float f;
          const auto lo = static_cast<std::uint32_t>(b);
          std::memcpy(&f, &lo, sizeof f);
          v = f;
        } else {
          std::memcpy(&v, &b, sizeof v);
        }
        rec.reals[m * rec.reals_per + c] = v;
      }
      for (std::size_t c = 0; c < rec.ints_per; ++c)
        rec.ints[m * rec.ints_per + c] = static_cast<std::int64_t>(bits(at + 2 * (rec.reals_per + c)));
    }
  }
}

std::uint64_t slice_block(const Plan& plan) { return largest_chunk(plan); }

Reduction::Reduction(const Plan& plan) : plan_(&plan), counters_(AW_C_COUNT, 0) {
  if (plan.slices <= 1) return;
  const std::uint64_t n = plan.scene.trajectories, b = slice_block(plan);
  for (std::uint64_t first = 0; first < n; first += b) blocks_[first].count = std::min(b, n - first);
}

void Reduction::add(const ChunkWork& work, ChunkOutput& out) {
  const std::int64_t segments = plan_->windows * plan_->segments_per_window;
  if (plan_->slices <= 1 || work.seg_end < 0 || work.seg_end >= segments) {
    add(work.first, work.count, out);
    if (plan_->slices > 1) {
      Block& b = blocks_.at(work.first);
      b.slices_done = plan_->slices;
      b.carry = {};
    }
    return;
  }
  Block& b = blocks_.at(work.first);
  if (b.count != work.count || work.seg_first != b.slices_done * plan_->slice_segments)
    throw std::runtime_error("a time slice out of order");
  b.carry = {std::move(out.rec_r), std::move(out.rec_i), std::move(out.holds)};
  ++b.slices_done;
  chunks.push_back(work.count);
}

ChunkWork Reduction::next_slice(std::vector<double>& rec_r, std::vector<std::int64_t>& rec_i) const {
  ChunkWork w;
  const Block* best = nullptr;
  std::uint64_t at = 0;
  for (const auto& [first, b] : blocks_)
    if (b.slices_done < plan_->slices && (!best || b.slices_done < best->slices_done)) {
      best = &b;
      at = first;
    }
  if (!best) return w;
  const std::int64_t segments = plan_->windows * plan_->segments_per_window;
  w.first = at;
  w.count = best->count;
  w.seg_first = best->slices_done * plan_->slice_segments;
  w.seg_end = std::min(segments, w.seg_first + plan_->slice_segments);
  if (best->slices_done > 0) {
    rec_r = best->carry.reals;
    rec_i = best->carry.ints;
  } else if (plan_->states) {
    initial_records(*plan_, at, best->count, rec_r, rec_i);
  } else {
    return w;  // the kernel makes the initial states
  }
  w.rec_r = &rec_r;
  w.rec_i = &rec_i;
  return w;
}

std::uint64_t Reduction::progress() const {
  if (plan_->slices <= 1) return completed_;
  double done = 0;
  for (const auto& [first, b] : blocks_)
    done += static_cast<double>(b.count) * static_cast<double>(b.slices_done) / static_cast<double>(plan_->slices);
  return static_cast<std::uint64_t>(done);
}

void Reduction::mark_done(std::uint64_t first, std::uint64_t count) {
  if (count == 0) return;
  std::uint64_t end = first + count;
  if (end > plan_->scene.trajectories) throw std::runtime_error("a chunk beyond the last trajectory");
  auto next = done_.lower_bound(first);
  if (next != done_.end() && next->first < end) throw std::runtime_error("a chunk that was already done");
  if (next != done_.begin()) {
    auto prev = std::prev(next);
    if (prev->second > first) throw std::runtime_error("a chunk that was already done");
    if (prev->second == first) {
      first = prev->first;
      done_.erase(prev);
    }
  }
  if (next != done_.end() && next->first == end) {
    end = next->second;
    done_.erase(next);
  }
  done_[first] = end;
  completed_ += count;
}

void Reduction::add(std::uint64_t first, std::uint64_t count, ChunkOutput& out) {
  mark_done(first, count);
  for (std::size_t c = 0; c < counters_.size() && c < out.counters.size(); ++c) counters_[c] += out.counters[c];
  for (std::size_t g = 0; g + 1 < out.group_stats.size(); g += AW_GROUP_STATS) {
    if (out.group_stats[g] > emax_) emax_ = out.group_stats[g];
    esum_.add(out.group_stats[g + 1]);
  }
  // the records are taken, not copied (a chunk's can be 100 MB: the copy was a third of the host's
  // time in a frequency run of 1.5 million trajectories on an H100)
  if (!out.rec_r.empty() || !out.rec_i.empty())
    records_[first] = {std::move(out.rec_r), std::move(out.rec_i), std::move(out.holds)};
  chunks.push_back(count);
}

void Reduction::add_histograms(const std::vector<std::uint64_t>& h) {
  if (h.empty()) return;
  if (histograms_.empty()) histograms_.assign(h.size(), 0);
  if (h.size() != histograms_.size()) throw std::runtime_error("histograms of another size");
  for (std::size_t i = 0; i < h.size(); ++i) histograms_[i] += h[i];
}

void Reduction::merge(const Reduction& o) {
  for (const auto& [first, end] : o.done_) mark_done(first, end - first);
  for (std::size_t c = 0; c < counters_.size(); ++c) counters_[c] += o.counters_[c];
  if (o.emax_ > emax_) emax_ = o.emax_;
  esum_.merge(o.esum_);
  add_histograms(o.histograms_);
  for (const auto& [first, s] : o.records_) records_[first] = s;
  for (const auto& [first, b] : o.blocks_)
    if (b.slices_done > blocks_[first].slices_done) blocks_[first] = b;
  chunks.insert(chunks.end(), o.chunks.begin(), o.chunks.end());
  seconds = std::max(seconds, o.seconds);
}

std::vector<IndexRange> Reduction::pending() const {
  std::vector<IndexRange> p;
  std::uint64_t at = 0;
  for (const auto& [first, end] : done_) {
    if (first > at) p.push_back({at, first - at});
    at = end;
  }
  if (at < plan_->scene.trajectories) p.push_back({at, plan_->scene.trajectories - at});
  std::vector<IndexRange> within;  // p within [only_first_, only_end_)
  for (const IndexRange& r : p) {
    const std::uint64_t first = std::max(r.first, only_first_), end = std::min(r.end(), only_end_);
    if (first < end) within.push_back({first, end - first});
  }
  return within;
}

Result Reduction::result() const {
  Result r;
  r.trajectories = plan_->scene.trajectories;
  r.completed = completed_;
  r.nside = plan_->scene.velocity_map ? plan_->scene.nside : 0;
  r.binned = counters_[AW_C_BINNED];
  r.flagged_nonfinite = counters_[AW_C_FLAG_NONFINITE];
  r.flagged_energy = counters_[AW_C_FLAG_ENERGY];
  r.flagged_initial = counters_[AW_C_FLAG_INITIAL];
  r.left_region = counters_[AW_C_LEFT_REGION];
  r.energy.tracked = (plan_->kernel.features & AW_F_ENERGY) != 0;
  if (r.energy.tracked)
    r.energy.log_hist.assign(counters_.begin() + AW_C_EHIST, counters_.begin() + AW_C_EHIST + AW_EHIST_BINS);
  r.energy.max = emax_;
  r.energy.mean = r.binned ? esum_.value() / static_cast<double>(r.binned) : 0.0;
  // the histograms: F frames of the map, then the zoom
  const std::uint64_t npix = plan_->npix;
  r.map.assign(npix, 0);
  if (histograms_.size() >= static_cast<std::size_t>(plan_->frames) * npix) {
    for (int f = 0; f < plan_->frames; ++f) {
      const auto first = histograms_.begin() + static_cast<std::ptrdiff_t>(f * npix);
      if (plan_->frames > 1) r.frames.emplace_back(first, first + static_cast<std::ptrdiff_t>(npix));
      for (std::uint64_t i = 0; i < npix; ++i) r.map[i] += first[static_cast<std::ptrdiff_t>(i)];
    }
    const auto zoom = histograms_.begin() + static_cast<std::ptrdiff_t>(plan_->frames * npix);
    r.zoom.assign(zoom, zoom + static_cast<std::ptrdiff_t>(plan_->zoom_resolution) * plan_->zoom_resolution);
  }
  r.records = empty_records(*plan_);
  for (const auto& [first, chunk] : records_) append_records(*plan_, chunk.reals, chunk.ints, r.records);
  picked_from_words(*plan_, histograms_, r.records);
  r.chunks = chunks;
  r.wall_seconds = seconds;
  return r;
}

namespace {
constexpr std::uint64_t kReductionTag = 0x3430646552574121ull;  // "!AWRed04" (03: record arenas; 04: time slices)
}

std::string Reduction::image() const {
  ByteWriter w;
  w.u64(kReductionTag);
  w.u64(plan_->scene.trajectories);
  w.u64(done_.size());
  for (const auto& [first, end] : done_) {
    w.u64(first);
    w.u64(end);
  }
  w.array(counters_);
  w.f64(emax_);
  w.text(esum_.image());
  w.array(histograms_);
  w.u64(records_.size());
  for (const auto& [first, s] : records_) {
    w.u64(first);
    w.array(s.reals);
    w.array(s.ints);
  }
  w.u64(blocks_.size());
  for (const auto& [first, b] : blocks_) {
    w.u64(first);
    w.u64(b.count);
    w.u64(static_cast<std::uint64_t>(b.slices_done));
    w.array(b.carry.reals);
    w.array(b.carry.ints);
  }
  w.array(chunks);
  w.f64(seconds);
  return std::move(w.bytes());
}

Reduction Reduction::read(const Plan& plan, const std::string& image) {
  ByteReader in(image);
  Reduction r(plan);
  if (in.u64() != kReductionTag) throw std::runtime_error("not a reduction of this version");
  if (in.u64() != plan.scene.trajectories) throw std::runtime_error("a reduction of another number of trajectories");
  const std::uint64_t ranges = in.u64();
  for (std::uint64_t k = 0; k < ranges; ++k) {
    const std::uint64_t first = in.u64(), end = in.u64();
    if (end <= first) throw std::runtime_error("an empty range of trajectories");
    r.mark_done(first, end - first);
  }
  r.counters_ = in.array<std::uint64_t>();
  if (r.counters_.size() != AW_C_COUNT) throw std::runtime_error("counters of another version");
  r.emax_ = in.f64();
  r.esum_ = ExactSum::read(in.text());
  r.histograms_ = in.array<std::uint64_t>();
  if (!r.histograms_.empty() && r.histograms_.size() != plan.hist_size)
    throw std::runtime_error("histograms of another size");
  const IntParams& ip = params(plan).ints;
  const std::uint64_t chunks = in.u64();
  for (std::uint64_t k = 0; k < chunks; ++k) {
    const std::uint64_t first = in.u64();
    Arenas s;
    s.reals = in.array<double>();
    s.ints = in.array<std::int64_t>();
    if ((ip.rec_reals ? s.reals.size() % static_cast<std::size_t>(ip.rec_reals) : s.reals.size()) != 0 ||
        (ip.rec_ints ? s.ints.size() % static_cast<std::size_t>(ip.rec_ints) : s.ints.size()) != 0)
      throw std::runtime_error("records of another layout");
    r.records_[first] = std::move(s);
  }
  const std::uint64_t blocks = in.u64();
  if (blocks != r.blocks_.size()) throw std::runtime_error("time slices of another plan");
  for (std::uint64_t k = 0; k < blocks; ++k) {
    const std::uint64_t first = in.u64();
    auto it = r.blocks_.find(first);
    if (it == r.blocks_.end() || in.u64() != it->second.count) throw std::runtime_error("time slices of another plan");
    const std::uint64_t done = in.u64();
    if (done > static_cast<std::uint64_t>(plan.slices)) throw std::runtime_error("more time slices than the plan's");
    it->second.slices_done = static_cast<std::int64_t>(done);
    it->second.carry.reals = in.array<double>();
    it->second.carry.ints = in.array<std::int64_t>();
  }
  r.chunks = in.array<std::uint64_t>();
  r.seconds = in.f64();
  if (!in.at_end()) throw std::runtime_error("data after the end");
  return r;
}

}  // namespace arnoldweb::detail
