// arnoldweb: the cpu backend: the device core compiled as C++, run over all
// cores with OpenMP.
#include <omp.h>

#include <algorithm>
#include <fstream>
#include <thread>

#include "arnoldweb/errors.hpp"
#include "aw_params.h"
#include "backends/backends.hpp"
#include "backends/cpu/cpu_kernel.hpp"

namespace arnoldweb::detail {
namespace {

std::string cpu_model_name() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
    }
  return "CPU";
}

std::uint64_t physical_memory() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  std::uint64_t kb = 0;
  while (in >> key >> kb)
    if (key == "MemTotal:") return kb * 1024;
  return 0;
}

class CpuBackend final : public Backend {
 public:
  CpuBackend() : info_(cpu_device_info()) {}
  const DeviceInfo& info() const override { return info_; }

  void prepare(const Plan& plan, std::uint64_t max_chunk) override {
    check_device_memory(plan, info_, max_chunk, info_.memory);
    const bool fl = plan.kernel.precision == Precision::Float;
    const bool native = plan.kernel.math == MathMode::Native;
    kernel_ = fl ? (native ? cpu_chunk_float_native : cpu_chunk_float_portable)
                 : (native ? cpu_chunk_double_native : cpu_chunk_double_portable);
    variant_ = std::string("cpu_") + (fl ? "float" : "double") + "_" + (native ? "native" : "portable");
    float_ = fl;
    features_ = plan.kernel.features;
    stages_ = plan.kernel.stages;
    kick_first_ = plan.kernel.kick_first ? 1 : 0;
    rp_d_ = plan.rp;
    rp_f_.assign(plan.rp.begin(), plan.rp.end());
    ip_ = plan.ip;
    map32_.assign(std::max<std::uint64_t>(plan.hist_size, 1), 0);
    map64_.assign(plan.hist_size, 0);
  }

  void run_chunk(std::uint64_t first, std::uint64_t count, ChunkOutput& out) override {
    CpuChunk c;
    c.features = features_;
    c.stages = stages_;
    c.kick_first = kick_first_;
    c.first = first;
    c.end = first + count;
    c.rp = float_ ? static_cast<const void*>(rp_f_.data()) : static_cast<const void*>(rp_d_.data());
    c.ip = ip_.data();
    c.map = map32_.data();
    out.counters.assign(AW_C_COUNT, 0);
    c.counters = out.counters.data();
    const std::uint64_t blocks = (count + kCpuBlock - 1) / kCpuBlock;
    out.group_stats.assign(2 * blocks, 0.0);
    c.group_stats = out.group_stats.data();
    std::vector<float> fi, ff;
    if (features_ & AW_F_INITIAL_STATES) {
      out.initial_r.assign(count * AW_STATE_REALS, 0.0);
      if (float_) fi.assign(count * AW_STATE_REALS, 0.0f);
      c.initial_r = float_ ? static_cast<void*>(fi.data()) : static_cast<void*>(out.initial_r.data());
    }
    if (features_ & AW_F_FINAL_STATES) {
      out.final_r.assign(count * AW_STATE_REALS, 0.0);
      out.final_i.assign(count * AW_STATE_INTS, 0);
      if (float_) ff.assign(count * AW_STATE_REALS, 0.0f);
      c.final_r = float_ ? static_cast<void*>(ff.data()) : static_cast<void*>(out.final_r.data());
      c.final_i = out.final_i.data();
    }
    kernel_(c);
    std::copy(fi.begin(), fi.end(), out.initial_r.begin());
    std::copy(ff.begin(), ff.end(), out.final_r.begin());
    for (std::size_t i = 0; i < map64_.size(); ++i) {
      map64_[i] += map32_[i];
      map32_[i] = 0;
    }
  }

  std::vector<std::uint64_t> read_histograms() override { return map64_; }
  std::uint64_t preferred_chunk() const override { return kCpuBlock * info_.compute_units * 4; }
  std::string kernel_description() const override { return variant_; }

 private:
  DeviceInfo info_;
  CpuKernel kernel_ = nullptr;
  std::string variant_;
  bool float_ = false;
  std::uint32_t features_ = 0;
  int stages_ = 0, kick_first_ = 1;
  std::vector<double> rp_d_;
  std::vector<float> rp_f_;
  std::vector<std::int64_t> ip_;
  std::vector<std::uint32_t> map32_;
  std::vector<std::uint64_t> map64_;
};

}  // namespace

DeviceInfo cpu_device_info() {
  DeviceInfo d;
  d.id = "cpu";
  d.backend = "cpu";
  d.name = cpu_model_name();
  d.vendor = "arnoldweb C++ (OpenMP)";
  d.version = std::to_string(_OPENMP);
  d.fp64 = true;
  d.compute_units = static_cast<unsigned>(std::max(1, omp_get_max_threads()));
  d.memory = physical_memory();
  d.is_cpu = true;
  return d;
}

std::unique_ptr<Backend> make_cpu_backend() { return std::make_unique<CpuBackend>(); }

}  // namespace arnoldweb::detail
