// arnoldweb: running an ensemble on any device, written once over the device
// layer (compute_device.hpp): the buffers a plan needs, the launch of a chunk
// and the fold of its counts, reading back counters, group statistics and
// state records (converted from float when the kernel computes in float).
#include <algorithm>
#include <cstring>

#include "arnoldweb/errors.hpp"
#include "aw_params.h"
#include "backends/backends.hpp"
#include "backends/compute_device.hpp"
#include "plan/kernel_params.hpp"

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
    dev_->compile(plan.kernel);
    float_ = plan.kernel.precision == Precision::Float;
    features_ = plan.kernel.features;
    hist_size_ = plan.hist_size;
    max_chunk_ = max_chunk;
    allocate(plan);
  }

  void run_chunk(std::uint64_t first, std::uint64_t count, ChunkOutput& out) override {
    if (!b_.counters) throw DeviceError(info().id, "", 0, "run_chunk before prepare");
    if (count > max_chunk_)
      throw DeviceError(info().id, "", 0,
                        "chunk of " + std::to_string(count) + " trajectories exceeds the prepared " +
                            std::to_string(max_chunk_));
    const LaunchShape shape = dev_->shape(count);
    dev_->zero(*b_.counters);
    if (count > 0) dev_->launch_ensemble(first, count, shape, b_);
    if (hist_size_) dev_->launch_fold(*map64_, *b_.counts, hist_size_);
    dev_->finish("trajectories [" + std::to_string(first) + ", " + std::to_string(first + count) + ")");

    out.counters.assign(AW_C_COUNT, 0);
    dev_->download(*b_.counters, out.counters.data(), AW_C_COUNT * 4);
    read_reals(*b_.group_stats, AW_GROUP_STATS * shape.groups, out.group_stats);
    out.initial_r.clear();
    out.final_r.clear();
    out.final_i.clear();
    out.indicators.clear();
    if (features_ & AW_F_TANGENT) read_reals(*b_.indicators, count * AW_IND_REALS, out.indicators);
    if (features_ & AW_F_INITIAL_STATES) read_reals(*b_.initial_r, count * AW_STATE_REALS, out.initial_r);
    if (features_ & AW_F_FINAL_STATES) {
      read_reals(*b_.final_r, count * AW_STATE_REALS, out.final_r);
      out.final_i.assign(count * AW_STATE_INTS, 0);
      dev_->download(*b_.final_i, out.final_i.data(), count * AW_STATE_INTS * 8);
    }
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
    const std::size_t state_r = (features_ & AW_F_INITIAL_STATES) ? max_chunk_ * AW_STATE_REALS * rs : 0;
    const std::size_t final_r = (features_ & AW_F_FINAL_STATES) ? max_chunk_ * AW_STATE_REALS * rs : 0;
    const std::size_t final_i = (features_ & AW_F_FINAL_STATES) ? max_chunk_ * AW_STATE_INTS * 8 : 0;
    const std::size_t indicators = (features_ & AW_F_TANGENT) ? max_chunk_ * AW_IND_REALS * rs : 0;
    const double need = static_cast<double>(reals.size() + sizeof(IntParams) + hist * 12 + AW_C_COUNT * 4 +
                                            AW_GROUP_STATS * groups * rs + state_r + final_r + final_i +
                                            indicators);
    const std::uint64_t free = dev_->free_memory();
    if (free && need > static_cast<double>(free))
      throw DeviceError(info().id, "", 0,
                        "out of device memory: the run needs " + mib(need) + " on " + info().id + " (" + info().name +
                            "), " + mib(static_cast<double>(free)) +
                            " are free; set ensemble.chunk smaller (state records) or "
                            "observe.velocity_map.nside smaller (map)");
    b_.reals = make(reals.size(), "the real parameters");
    dev_->upload(*b_.reals, reals.data(), reals.size());
    b_.ints = make(sizeof(IntParams), "the integer parameters");
    dev_->upload(*b_.ints, &kp.ints, sizeof(IntParams));
    b_.counts = make(hist * 4, "the velocity map (32-bit chunk counts)");
    map64_ = make(hist * 8, "the velocity map (64-bit totals)");
    dev_->zero(*b_.counts);
    dev_->zero(*map64_);
    b_.counters = make(AW_C_COUNT * 4, "the counters");
    b_.group_stats = make(AW_GROUP_STATS * groups * rs, "the energy statistics");
    if (state_r) b_.initial_r = make(state_r, "initial states (ensemble.chunk per launch)");
    if (final_r) b_.final_r = make(final_r, "final states (ensemble.chunk per launch)");
    if (final_i) b_.final_i = make(final_i, "final states (ensemble.chunk per launch)");
    if (indicators) b_.indicators = make(indicators, "chaos indicators (ensemble.chunk per launch)");
    dev_->finish("preparing buffers");
  }

  void read_reals(const DeviceMemory& m, std::size_t n, std::vector<double>& out) {
    out.assign(n, 0.0);
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
  bool float_ = false;
  std::uint32_t features_ = 0;
  std::uint64_t hist_size_ = 0, max_chunk_ = 0;
};

}  // namespace

std::unique_ptr<Backend> make_ensemble_backend(std::unique_ptr<ComputeDevice> device) {
  return std::make_unique<EnsembleBackend>(std::move(device));
}

}  // namespace arnoldweb::detail
