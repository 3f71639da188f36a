// arnoldweb: the cpu backend's device: the device core compiled as C++
// (cpu_kernel.hpp), run over all cores with OpenMP, on buffers in host memory.
#include <omp.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "arnoldweb/errors.hpp"
#include "aw_params.h"
#include "backends/backends.hpp"
#include "backends/compute_device.hpp"
#include "backends/cpu/cpu_isa.hpp"
#include "backends/cpu/cpu_kernel.hpp"
#include "backends/cpu/cpu_runtime_kernel.hpp"

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

// A line of /proc/meminfo ("MemAvailable:   123456 kB"), in bytes; 0 if absent.
std::uint64_t meminfo(const std::string& key) {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, key.size(), key) == 0) return std::strtoull(line.c_str() + key.size(), nullptr, 10) * 1024;
  return 0;
}

class HostMemory final : public DeviceMemory {
 public:
  HostMemory(std::size_t bytes, const std::string& device, const char* what) : DeviceMemory(bytes) {
    try {
      data_.resize((std::max<std::size_t>(bytes, 1) + 7) / 8);  // 8-byte aligned
    } catch (const std::bad_alloc&) {
      throw DeviceError(device, "", 0,
                        "out of memory allocating " + std::to_string(bytes) + " bytes for " + what);
    }
  }
  void* data() { return data_.data(); }
  const void* data() const { return data_.data(); }

 private:
  std::vector<std::uint64_t> data_;
};

HostMemory& host(DeviceMemory& m) { return static_cast<HostMemory&>(m); }
const HostMemory& host(const DeviceMemory& m) { return static_cast<const HostMemory&>(m); }

class CpuDevice final : public ComputeDevice {
 public:
  CpuDevice() : info_(cpu_device_info()) {}
  const DeviceInfo& info() const override { return info_; }
  std::uint64_t free_memory() const override { return meminfo("MemAvailable:"); }

  void compile(const KernelConfig& k) override {
    const bool fl = k.precision == Precision::Float;
    const bool native = k.math == MathMode::Native;
    const CpuIsa& isa = cpu_isa_selected();  // the best compiled set this CPU runs, or ARNOLDWEB_CPU_ISA
    const std::string lanes = std::to_string(fl ? isa.lanes_float : isa.lanes_double) + " lanes";
    if (!k.model_source.empty()) {  // an expression model: compiled now, for the same set (docs/models.md)
      const CpuRuntimeKernel rk = cpu_expression_kernel(k.model_source, fl, native);
      kernel_ = rk.kernel;
      variant_ = rk.variant + " (" + isa.name + ", " + lanes + "; compiled at run time by " + rk.compiler + "; " +
                 rk.origin + ")";
      origin_ = rk.origin;
    } else {
      kernel_ = cpu_kernel_for(k.model, fl, native, isa);
      if (!kernel_)
        throw DeviceError(info_.id, "", 0, "this build has no cpu kernel for model " + std::to_string(k.model));
      origin_ = "built in";
      variant_ = std::string("cpu_") + (fl ? "float" : "double") + "_" + (native ? "native" : "portable") + " (" +
                 isa.name + ", " + lanes + ")";
    }
    config_ = k;
  }
  std::string kernel_description() const override { return variant_; }
  std::string kernel_origin() const override { return origin_; }

  std::unique_ptr<DeviceMemory> allocate(std::size_t bytes, const char* what) override {
    return std::make_unique<HostMemory>(bytes, info_.id, what);
  }
  void upload(DeviceMemory& to, const void* from, std::size_t bytes) override {
    std::memcpy(host(to).data(), from, bytes);
  }
  void download(const DeviceMemory& from, void* to, std::size_t bytes) override {
    std::memcpy(to, host(from).data(), bytes);
  }
  void zero(DeviceMemory& m) override { std::memset(host(m).data(), 0, m.bytes()); }

  LaunchShape shape(std::uint64_t count) const override {
    LaunchShape s;
    s.groups = (count + kCpuBlock - 1) / kCpuBlock;
    s.group_size = kCpuBlock;
    s.items = s.groups * kCpuBlock;
    return s;
  }

  void launch_ensemble(const LaunchRange& r, const LaunchShape&, const EnsembleBuffers& b) override {
    kernel_(chunk(r, b, false));
  }

  void launch_frequencies(const LaunchRange& r, const LaunchShape&, const EnsembleBuffers& b) override {
    kernel_(chunk(r, b, true));
  }

  void launch_fold(DeviceMemory& total, DeviceMemory& part, std::uint64_t n) override {
    auto* t = static_cast<std::uint64_t*>(host(total).data());
    auto* p = static_cast<std::uint32_t*>(host(part).data());
    for (std::uint64_t i = 0; i < n; ++i) {
      t[i] += p[i];
      p[i] = 0;
    }
  }

  void finish(const std::string&) override {}
  std::uint64_t preferred_chunk() const override { return kCpuBlock * info_.compute_units * 4; }

 private:
  CpuChunk chunk(const LaunchRange& r, const EnsembleBuffers& b, bool frequencies) const {
    CpuChunk c;
    c.frequencies = frequencies;
    c.features = config_.features;
    c.stages = config_.stages;
    c.kick_first = config_.kick_first ? 1 : 0;
    c.gradient = config_.gradient ? 1 : 0;
    c.initial = config_.initial;
    c.first = r.first;
    c.end = r.first + r.count;
    c.seg_first = r.seg_first;
    c.seg_end = r.seg_end;
    for (int i = 0; i < AW_BUF_COUNT; ++i) c.buffers[i] = b.at[i] ? host(*b.at[i]).data() : nullptr;
    return c;
  }

  DeviceInfo info_;
  KernelConfig config_;
  CpuKernel kernel_ = nullptr;
  std::string variant_, origin_;
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
  d.memory = meminfo("MemTotal:");
  d.is_cpu = true;
  return d;
}

std::unique_ptr<Backend> make_cpu_backend() { return make_ensemble_backend(std::make_unique<CpuDevice>()); }

}  // namespace arnoldweb::detail
