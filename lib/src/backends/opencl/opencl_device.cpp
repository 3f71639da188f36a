// arnoldweb: the OpenCL device, through Boost.Compute. Kernels are built at
// run time from the embedded sources with the plan's -D options and cached per
// context. CPU devices (PoCL) run AW_LANES trajectories per work-item on
// explicit vector types, which PoCL vectorises; GPUs run one per work-item.
#include <boost/compute/core.hpp>
#include <boost/compute/utility/program_cache.hpp>

#include <algorithm>
#include <cstdlib>
#include <mutex>

#include "arnoldweb/errors.hpp"
#include "aw_params.h"
#include "backends/backends.hpp"
#include "backends/compute_device.hpp"
#include "backends/kernel_sources.hpp"
#include "os/quit_signal.hpp"

namespace compute = boost::compute;

namespace arnoldweb::detail {
namespace {

const char* kInstallHint =
    "install an OpenCL driver: for CPUs, PoCL (Debian/Ubuntu: apt-get install pocl-opencl-icd); "
    "for NVIDIA GPUs, the driver's OpenCL ICD (libnvidia-opencl / nvidia-opencl-icd)";

std::vector<compute::device> cl_devices() {
  std::vector<compute::device> out;
  for (const auto& platform : compute::system::platforms())
    for (const auto& d : platform.devices()) out.push_back(d);
  return out;
}

DeviceInfo describe(const compute::device& d, int index) {
  DeviceInfo info;
  info.id = "opencl:" + std::to_string(index);
  info.backend = "opencl";
  info.name = d.name();
  info.vendor = d.vendor();
  info.version = d.version() + ", driver " + d.driver_version() + ", platform " + d.platform().name();
  info.fp64 = d.supports_extension("cl_khr_fp64");
  info.compute_units = d.compute_units();
  info.memory = d.global_memory_size();
  info.max_allocation = d.get_info<cl_ulong>(CL_DEVICE_MAX_MEM_ALLOC_SIZE);
  info.is_cpu = (d.type() & compute::device::cpu) != 0;
  return info;
}

[[noreturn]] void rethrow(const DeviceInfo& dev, const char* call, const compute::opencl_error& e) {
  if (e.error_code() == CL_MEM_OBJECT_ALLOCATION_FAILURE || e.error_code() == CL_OUT_OF_RESOURCES ||
      e.error_code() == CL_OUT_OF_HOST_MEMORY)
    throw DeviceError(dev.id, call, e.error_code(),
                      std::string("out of device memory or resources (") + e.error_string() +
                          "); use a smaller ensemble.chunk or nside");
  throw DeviceError(dev.id, call, e.error_code(), e.error_string());
}

const std::string& ensemble_source() {
  static const std::string src = flatten_source("ensemble.cl");
  return src;
}

// The program's source: the embedded one, or with an expression model's header.
std::string ensemble_source(const KernelConfig& config) {
  if (config.model_source.empty()) return ensemble_source();
  return flatten_source("ensemble.cl", {{expression_model_header(), config.model_source}});
}

std::mutex build_mutex;  // program_cache is not thread-safe

class ClMemory final : public DeviceMemory {
 public:
  ClMemory(compute::buffer b, std::size_t bytes) : DeviceMemory(bytes), buffer(std::move(b)) {}
  compute::buffer buffer;
};

const compute::buffer& cl(const DeviceMemory& m) { return static_cast<const ClMemory&>(m).buffer; }

class OpenclDevice final : public ComputeDevice {
 public:
  explicit OpenclDevice(int index) {
    auto devs = cl_devices();
    device_ = devs.at(static_cast<std::size_t>(index));
    info_ = describe(device_, index);
    try {
      context_ = compute::context(device_);
      queue_ = compute::command_queue(context_, device_);
      dummy_ = compute::buffer(context_, 64);
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clCreateContext", e);
    }
  }

  const DeviceInfo& info() const override { return info_; }
  std::uint64_t max_allocation() const override {
    return device_.get_info<cl_ulong>(CL_DEVICE_MAX_MEM_ALLOC_SIZE);
  }

  void compile(const KernelConfig& config) override {
    const bool fl = config.precision == Precision::Float;
    lanes_ = info_.is_cpu ? 8 : 1;
    if (const char* env = std::getenv("ARNOLDWEB_OPENCL_LANES")) lanes_ = std::atoi(env);
    if (lanes_ != 1 && lanes_ != 2 && lanes_ != 4 && lanes_ != 8 && lanes_ != 16)
      throw DeviceError(info_.id, "", 0, "ARNOLDWEB_OPENCL_LANES must be 1, 2, 4, 8 or 16");
    // the frequency analysis: a work-group per trajectory on GPUs (aw_naff.h, "teams"); the same bits either way
    teams_ = !info_.is_cpu;
    if (const char* env = std::getenv("ARNOLDWEB_OPENCL_TEAMS")) teams_ = std::string(env) == "1";
    if (teams_ && lanes_ != 1)
      throw DeviceError(info_.id, "", 0,
                        "ARNOLDWEB_OPENCL_TEAMS=1 (a work-group per trajectory's analysis) needs one lane: "
                        "ARNOLDWEB_OPENCL_LANES=1");
    real_size_ = fl ? sizeof(float) : sizeof(double);
    options_ = config.defines() + " -DAW_LANES=" + std::to_string(lanes_) + (teams_ ? " -DAW_NAFF_TEAM_PARALLEL=1" : "");
    frequencies_ = (config.features & AW_F_FREQUENCIES) != 0;
    // CPU devices: every device function inlined (aw_dialect.h). PoCL 3.1 left the force-gradient
    // kick a call, its lanes' state passed through memory: the default scene 1.25x slower (same bits)
    if (info_.is_cpu) options_ += " -DAW_OPENCL_ALWAYS_INLINE=1";
    source_ = ensemble_source(config);
    if (fl && (device_.get_info<cl_device_fp_config>(CL_DEVICE_SINGLE_FP_CONFIG) & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT))
      options_ += " -cl-fp32-correctly-rounded-divide-sqrt";
    // extra compiler options, for experiments and diagnostics (like ARNOLDWEB_NVRTC_OPTIONS)
    if (const char* extra = std::getenv("ARNOLDWEB_OPENCL_OPTIONS")) options_ += std::string(" ") + extra;
    build();
    try {
      wg_ = info_.is_cpu ? 16 : 128;
      wg_ = std::min<std::size_t>(wg_, ensemble_.get_work_group_info<std::size_t>(device_, CL_KERNEL_WORK_GROUP_SIZE));
      wg_ = floor_pow2(std::max<std::size_t>(wg_, 1));
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clGetKernelWorkGroupInfo", e);
    }
  }
  std::string kernel_description() const override { return "OpenCL C: " + options_; }
  std::string kernel_origin() const override { return origin_; }

  std::unique_ptr<DeviceMemory> allocate(std::size_t bytes, const char*) override {
    try {
      return std::make_unique<ClMemory>(compute::buffer(context_, std::max<std::size_t>(bytes, 1)), bytes);
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clCreateBuffer", e);
    }
  }
  void upload(DeviceMemory& to, const void* from, std::size_t bytes) override {
    try {
      if (bytes) queue_.enqueue_write_buffer(cl(to), 0, bytes, from);
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clEnqueueWriteBuffer", e);
    }
  }
  void download(const DeviceMemory& from, void* to, std::size_t bytes) override {
    try {
      if (bytes) queue_.enqueue_read_buffer(cl(from), 0, bytes, to);
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clEnqueueReadBuffer", e);
    }
  }
  void zero(DeviceMemory& m) override {
    if (!m.bytes()) return;
    try {  // on the device: no host copy of zeros (the frequency series reach gigabytes)
      const unsigned char nothing = 0;
      queue_.enqueue_fill_buffer(cl(m), &nothing, 1, 0, m.bytes());
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clEnqueueFillBuffer", e);
    }
  }

  LaunchShape shape(std::uint64_t count) const override {
    LaunchShape s;
    const std::uint64_t items = (count + lanes_ - 1) / lanes_;
    s.items = (items + wg_ - 1) / wg_ * wg_;
    s.group_size = wg_;
    s.groups = s.items / wg_;
    return s;
  }

  void launch_ensemble(const LaunchRange& r, const LaunchShape& s, const EnsembleBuffers& b) override {
    try {
      compute::kernel& k = ensemble_;
      k.set_arg(2, static_cast<cl_long>(r.seg_first));
      k.set_arg(3, static_cast<cl_long>(r.seg_end));
      set_range_and_buffers(k, r, b, 4);
      k.set_arg(4 + AW_BUF_COUNT, 2 * wg_ * real_size_, nullptr);
      queue_.enqueue_1d_range_kernel(k, 0, s.items, wg_);
      queue_.flush();  // the device starts while the host prepares for the results (EnsembleBackend::run_chunk)
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clEnqueueNDRangeKernel", e);
    }
  }

  void launch_frequencies(const LaunchRange& r, const LaunchShape& s, const EnsembleBuffers& b) override {
    try {
      compute::kernel& k = frequencies_kernel_;
      set_range_and_buffers(k, r, b, 2);
      if (teams_) {
        // the team's scratch (kernels_cl/ensemble.cl)
        k.set_arg(2 + AW_BUF_COUNT, 6 * AW_NAFF_TEAM * real_size_, nullptr);
        queue_.enqueue_1d_range_kernel(k, 0, r.count * AW_NAFF_TEAM, AW_NAFF_TEAM);
      } else
        queue_.enqueue_1d_range_kernel(k, 0, s.items, wg_);
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clEnqueueNDRangeKernel", e);
    }
  }

  void launch_fold(DeviceMemory& total, DeviceMemory& part, std::uint64_t n) override {
    try {
      fold_.set_arg(0, cl(total));
      fold_.set_arg(1, cl(part));
      fold_.set_arg(2, static_cast<cl_ulong>(n));
      queue_.enqueue_1d_range_kernel(fold_, 0, (n + 255) / 256 * 256, 0);
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clEnqueueNDRangeKernel", e);
    }
  }

  void finish(const std::string&) override {
    try {
      queue_.finish();
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clFinish", e);
    }
  }

  std::uint64_t preferred_chunk() const override {
    return static_cast<std::uint64_t>(info_.compute_units) * wg_ * lanes_ * (info_.is_cpu ? 4 : 16);
  }

 private:
  // The arguments both entry points share: the chunk's trajectories first (0, 1), the buffers
  // (AW_BUFFERS) from `buffers_at` on, a dummy where the plan needs none.
  void set_range_and_buffers(compute::kernel& k, const LaunchRange& r, const EnsembleBuffers& b, int buffers_at) {
    k.set_arg(0, static_cast<cl_ulong>(r.first));
    k.set_arg(1, static_cast<cl_ulong>(r.first + r.count));
    for (int i = 0; i < AW_BUF_COUNT; ++i) k.set_arg(buffers_at + i, b.at[i] ? cl(*b.at[i]) : dummy_);
  }

  void build() {
    std::lock_guard<std::mutex> lock(build_mutex);
    auto cache = compute::program_cache::get_global_cache(context_);
    const std::string key = "arnoldweb.ensemble." + std::to_string(std::hash<std::string>()(source_));
    auto cached = cache->get(key, options_);
    compute::program program;
    origin_ = cached ? "memory" : "driver";
    if (cached) {
      program = *cached;
    } else {
      try {
        program = compute::program::create_with_source(source_, context_);
      } catch (const compute::opencl_error& e) {
        rethrow(info_, "clCreateProgramWithSource", e);
      }
      try {
        const detail::KeepQuitSignal keep;  // PoCL's LLVM may take SIGQUIT (os/quit_signal.hpp)
        program.build(options_);
      } catch (const compute::opencl_error& e) {
        std::string log;
        try {
          log = program.build_log();
        } catch (...) {
          log = "(no build log available)";
        }
        throw BuildError(info_.id + " (" + info_.name + ")", options_, log);
      }
      cache->insert(key, options_, program);
    }
    try {
      ensemble_ = program.create_kernel("aw_ensemble");
      fold_ = program.create_kernel("aw_fold");
      if (frequencies_) frequencies_kernel_ = program.create_kernel("aw_frequencies");
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clCreateKernel", e);
    }
  }

  compute::device device_;
  DeviceInfo info_;
  compute::context context_;
  compute::command_queue queue_;
  compute::kernel ensemble_, fold_, frequencies_kernel_;
  bool frequencies_ = false;
  compute::buffer dummy_;
  std::string options_, origin_;
  std::string source_;  // the program text (ensemble.cl flattened, with an expression model's header)
  std::size_t real_size_ = 8;
  int lanes_ = 1;
  bool teams_ = false;  // the frequency analysis by teams of work-items (ARNOLDWEB_OPENCL_TEAMS)
  std::size_t wg_ = 1;
};

}  // namespace

std::vector<DeviceInfo> opencl_devices(std::vector<std::string>& problems) {
  std::vector<DeviceInfo> out;
  try {
    auto devs = cl_devices();
    for (std::size_t i = 0; i < devs.size(); ++i) out.push_back(describe(devs[i], static_cast<int>(i)));
    if (compute::system::platforms().empty())
      problems.push_back(std::string("opencl: no OpenCL platform found (the ICD loader lists none); ") + kInstallHint);
    else if (devs.empty())
      problems.push_back(std::string("opencl: no OpenCL device found; ") + kInstallHint);
  } catch (const compute::opencl_error& e) {
    problems.push_back(std::string("opencl: no OpenCL platform found (clGetPlatformIDs returned ") +
                       std::to_string(e.error_code()) + "); " + kInstallHint);
  }
  return out;
}

std::unique_ptr<Backend> make_opencl_backend(int index) {
  return make_ensemble_backend(std::make_unique<OpenclDevice>(index));
}

}  // namespace arnoldweb::detail
