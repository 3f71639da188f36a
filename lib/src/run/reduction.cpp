// arnoldweb: the reduction of a run (reduction.hpp).
#include "run/reduction.hpp"

#include <algorithm>
#include <stdexcept>

#include "aw_params.h"
#include "run/byte_stream.hpp"

namespace arnoldweb::detail {

Reduction::Reduction(const Plan& plan) : plan_(&plan), counters_(AW_C_COUNT, 0) {}

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

void Reduction::add(std::uint64_t first, std::uint64_t count, const ChunkOutput& out) {
  mark_done(first, count);
  for (std::size_t c = 0; c < counters_.size() && c < out.counters.size(); ++c) counters_[c] += out.counters[c];
  for (std::size_t g = 0; g + 1 < out.group_stats.size(); g += AW_GROUP_STATS) {
    if (out.group_stats[g] > emax_) emax_ = out.group_stats[g];
    esum_.add(out.group_stats[g + 1]);
  }
  if (!out.initial_r.empty() || !out.final_r.empty() || !out.indicators.empty())
    states_[first] = {out.initial_r, out.final_r, out.final_i, out.indicators};
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
  for (const auto& [first, s] : o.states_) states_[first] = s;
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
  return p;
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
    r.zoom.assign(histograms_.begin() + static_cast<std::ptrdiff_t>(plan_->frames * npix), histograms_.end());
  }
  for (const auto& [first, s] : states_) {
    r.initial_r.insert(r.initial_r.end(), s.initial_r.begin(), s.initial_r.end());
    r.final_r.insert(r.final_r.end(), s.final_r.begin(), s.final_r.end());
    r.final_i.insert(r.final_i.end(), s.final_i.begin(), s.final_i.end());
    r.indicators.insert(r.indicators.end(), s.indicators.begin(), s.indicators.end());
  }
  r.chunks = chunks;
  r.wall_seconds = seconds;
  return r;
}

namespace {
constexpr std::uint64_t kReductionTag = 0x3230646552574121ull;  // "!AWRed02" (02: indicator arrays)
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
  w.u64(states_.size());
  for (const auto& [first, s] : states_) {
    w.u64(first);
    w.array(s.initial_r);
    w.array(s.final_r);
    w.array(s.final_i);
    w.array(s.indicators);
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
  const std::uint64_t chunks = in.u64();
  for (std::uint64_t k = 0; k < chunks; ++k) {
    const std::uint64_t first = in.u64();
    States s;
    s.initial_r = in.array<double>();
    s.final_r = in.array<double>();
    s.final_i = in.array<std::int64_t>();
    s.indicators = in.array<double>();
    r.states_[first] = std::move(s);
  }
  r.chunks = in.array<std::uint64_t>();
  r.seconds = in.f64();
  if (!in.at_end()) throw std::runtime_error("data after the end");
  return r;
}

}  // namespace arnoldweb::detail
