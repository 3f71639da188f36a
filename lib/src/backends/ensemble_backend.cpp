// arnoldweb: running an ensemble on any device, written once over the device
// layer (compute_device.hpp): the kernel's buffers (AW_BUFFERS), the launch
// of a chunk and the fold of its counts, reading back counters, group
// statistics and the records (converted from float when the kernel computes
// in float). Which outputs the records hold is the output table's business:
// this file only sizes and copies the arenas.
#include <algorithm>
#include <chrono>
#include <cstring>

#include "arnoldweb/errors.hpp"
#include "aw_params.h"
#include "backends/backends.hpp"
#include "backends/compute_device.hpp"
#include "plan/plan_params.hpp"

namespace arnoldweb::detail {
namespace {

std::string mib(double bytes) { return std::to_string(static_cast<long long>(bytes / 1048576.0)) + " MiB"; }

class EnsembleBackend final : public Backend {
 public:
  explicit EnsembleBackend(std::unique_ptr<ComputeDevice> device) : dev_(std::move(device)) {}
  const DeviceInfo& info() const override { return dev_->info(); }

  void prepare(const Plan& plan, std::uint64_t max_chunk) override {
    require_fp64(plan, info());
    check_device_memory(plan, info(), max_chunk, dev_->max_allocation());
    release();
    const auto t0 = std::chrono::steady_clock::now();
    dev_->compile(plan.kernel);
    const auto t1 = std::chrono::steady_clock::now();
    float_ = plan.kernel.precision == Precision::Float;
    frequencies_ = (plan.kernel.features & AW_F_FREQUENCIES) != 0;
    hist_size_ = plan.hist_size;
    segments_ = plan.windows * plan.segments_per_window;
    rec_reals_ = static_cast<std::uint64_t>(params(plan).ints.rec_reals);
    rec_ints_ = static_cast<std::uint64_t>(params(plan).ints.rec_ints);
    max_chunk_ = max_chunk;
    allocate(plan);
    startup.kernel_seconds = std::chrono::duration<double>(t1 - t0).count();
    startup.kernel_from = dev_->kernel_origin();
    startup.buffers_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  }

  void run_chunk(const ChunkWork& w, ChunkOutput& out) override {
    const std::uint64_t first = w.first, count = w.count;
    if (!b_[AW_BUF_COUNTERS]) throw DeviceError(info().id, "", 0, "run_chunk before prepare");
    if (count > max_chunk_)
      throw DeviceError(info().id, "", 0,
                        "chunk of " + std::to_string(count) + " trajectories exceeds the prepared " +
                            std::to_string(max_chunk_));
    const LaunchShape shape = dev_->shape(count);
    dev_->zero(*b_[AW_BUF_COUNTERS]);
    if (w.rec_r && rec_reals_) write_reals(*b_[AW_BUF_RECORDS_R], *w.rec_r, count * rec_reals_);
    if (w.rec_i && rec_ints_) {
      if (w.rec_i->size() < count * rec_ints_) throw DeviceError(info().id, "", 0, "records in shorter than the chunk");
      dev_->upload(*b_[AW_BUF_RECORDS_I], w.rec_i->data(), count * rec_ints_ * 8);
    }
    const LaunchRange range{first, count, w.seg_first, w.seg_end < 0 ? segments_ : w.seg_end};
    if (count > 0) dev_->launch_ensemble(range, shape, b_);
    // no time slices with frequencies (the planner refuses them): every launch ends both windows
    if (count > 0 && frequencies_) dev_->launch_frequencies(range, shape, b_);
    if (hist_size_) dev_->launch_fold(*map64_, *b_[AW_BUF_HIST], hist_size_);
    // The host's memory for what comes back, while the device works: fresh
    // memory costs its first touch (~30 ms for the 84 MB of records of 1.5
    // million trajectories with frequencies), which a GPU's launches hide.
    out.holds.clear();  // an earlier launch's, before its memory is reused
    out.counters.assign(AW_C_COUNT, 0);
    out.group_stats.assign(AW_GROUP_STATS * shape.groups, 0.0);
    out.rec_r.assign(count * rec_reals_, 0.0);
    out.rec_i.assign(count * rec_ints_, 0);
    if (!float_) out.holds.push_back(dev_->hold_for_download(out.rec_r.data(), out.rec_r.size() * sizeof(double)));
    out.holds.push_back(dev_->hold_for_download(out.rec_i.data(), out.rec_i.size() * sizeof(std::int64_t)));
    dev_->finish("trajectories [" + std::to_string(first) + ", " + std::to_string(first + count) + ")");

    dev_->download(*b_[AW_BUF_COUNTERS], out.counters.data(), AW_C_COUNT * 4);
    read_reals(*b_[AW_BUF_GROUP_STATS], out.group_stats);
    if (rec_reals_) read_reals(*b_[AW_BUF_RECORDS_R], out.rec_r);
    if (rec_ints_) dev_->download(*b_[AW_BUF_RECORDS_I], out.rec_i.data(), count * rec_ints_ * 8);
  }

  std::vector<std::uint64_t> read_histograms() override {
    std::vector<std::uint64_t> m(hist_size_);
    if (hist_size_) dev_->download(*map64_, m.data(), hist_size_ * 8);
    return m;
  }

  std::uint64_t preferred_chunk() const override { return dev_->preferred_chunk(); }
  std::string kernel_description() const override { return dev_->kernel_description(); }

 private:
  std::size_t real_size() const { return float_ ? sizeof(float) : sizeof(double); }

  void release() {
    b_ = EnsembleBuffers{};
    owned_.clear();
    map64_ = nullptr;
  }

  DeviceMemory* make(std::size_t bytes, const char* what) {
    owned_.push_back(dev_->allocate(bytes, what));
    return owned_.back().get();
  }

  void allocate(const Plan& plan) {
    const std::size_t rs = real_size();
    const KernelParams& kp = params(plan);
    const std::vector<unsigned char> reals = kp.real_bytes(plan.kernel.precision);
    const std::size_t groups = dev_->shape(max_chunk_).groups + 1;
    const std::size_t hist = std::max<std::uint64_t>(hist_size_, 1);
    const std::size_t rec_r = max_chunk_ * rec_reals_ * rs;
    const std::size_t rec_i = max_chunk_ * rec_ints_ * 8;
    // the series hold whole blocks of trajectories (the kernels store and load every lane of a group)
    const std::size_t series_blocks = (max_chunk_ + AW_SERIES_BLOCK - 1) / AW_SERIES_BLOCK;
    const std::size_t series = series_blocks * AW_SERIES_BLOCK * static_cast<std::size_t>(kp.ints.series_reals) * rs;
    const double need = static_cast<double>(reals.size() + sizeof(IntParams) + hist * 12 + AW_C_COUNT * 4 +
                                            AW_GROUP_STATS * groups * rs + rec_r + rec_i + series);
    const std::uint64_t free = dev_->free_memory();
    if (free && need > static_cast<double>(free))
      throw DeviceError(info().id, "", 0,
                        "out of device memory: the run needs " + mib(need) + " on " + info().id + " (" + info().name +
                            "), " + mib(static_cast<double>(free)) +
                            " are free; set ensemble.chunk smaller (state records) or "
                            "observe.velocity_map.nside smaller (map)");
    b_[AW_BUF_RPARAMS] = make(reals.size(), "the real parameters");
    dev_->upload(*b_[AW_BUF_RPARAMS], reals.data(), reals.size());
    b_[AW_BUF_IPARAMS] = make(sizeof(IntParams), "the integer parameters");
    dev_->upload(*b_[AW_BUF_IPARAMS], &kp.ints, sizeof(IntParams));
    b_[AW_BUF_HIST] = make(hist * 4, "the velocity map (32-bit chunk counts)");
    map64_ = make(hist * 8, "the velocity map (64-bit totals)");
    dev_->zero(*b_[AW_BUF_HIST]);
    dev_->zero(*map64_);
    b_[AW_BUF_COUNTERS] = make(AW_C_COUNT * 4, "the counters");
    b_[AW_BUF_GROUP_STATS] = make(AW_GROUP_STATS * groups * rs, "the energy statistics");
    if (rec_r) b_[AW_BUF_RECORDS_R] = make(rec_r, "per-trajectory records (ensemble.chunk per launch)");
    if (rec_i) b_[AW_BUF_RECORDS_I] = make(rec_i, "per-trajectory records (ensemble.chunk per launch)");
    if (series) {
      // not cleared: the analysis clears the windows' padding itself (aw_naff_clear_padding)
      b_[AW_BUF_SERIES] = make(series, "the sampled series of the frequency analysis (ensemble.chunk per launch)");
    }
    dev_->finish("preparing buffers");
  }

  // n reals of `in` into m, in the kernel's precision.
  void write_reals(DeviceMemory& m, const std::vector<double>& in, std::size_t n) {
    if (in.size() < n) throw DeviceError(info().id, "", 0, "records in shorter than the chunk");
    if (!float_) {
      dev_->upload(m, in.data(), n * sizeof(double));
      return;
    }
    const std::vector<float> f(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(n));
    dev_->upload(m, f.data(), n * sizeof(float));
  }

  // out.size() reals of m into out, from the kernel's precision.
  void read_reals(const DeviceMemory& m, std::vector<double>& out) {
    const std::size_t n = out.size();
    if (!float_) {
      dev_->download(m, out.data(), n * sizeof(double));
      return;
    }
    std::vector<float> f(n);
    dev_->download(m, f.data(), n * sizeof(float));
    std::copy(f.begin(), f.end(), out.begin());
  }

  std::unique_ptr<ComputeDevice> dev_;
  std::vector<std::unique_ptr<DeviceMemory>> owned_;
  EnsembleBuffers b_;
  DeviceMemory* map64_ = nullptr;
  bool float_ = false, frequencies_ = false;
  std::uint64_t hist_size_ = 0, max_chunk_ = 0, rec_reals_ = 0, rec_ints_ = 0;
  std::int64_t segments_ = 0;  // of a trajectory's schedule
};

}  // namespace

std::unique_ptr<Backend> make_ensemble_backend(std::unique_ptr<ComputeDevice> device) {
  return std::make_unique<EnsembleBackend>(std::move(device));
}

}  // namespace arnoldweb::detail
