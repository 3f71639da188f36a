// arnoldweb: the OpenCL backend, through Boost.Compute. Kernels are built at
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
#include "backends/kernel_sources.hpp"

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

std::mutex build_mutex;  // program_cache is not thread-safe

class OpenclBackend final : public Backend {
 public:
  explicit OpenclBackend(int index) {
    auto devs = cl_devices();
    device_ = devs.at(static_cast<std::size_t>(index));
    info_ = describe(device_, index);
    try {
      context_ = compute::context(device_);
      queue_ = compute::command_queue(context_, device_);
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clCreateContext", e);
    }
  }

  const DeviceInfo& info() const override { return info_; }

  void prepare(const Plan& plan, std::uint64_t max_chunk) override {
    float_ = plan.kernel.precision == Precision::Float;
    require_fp64(plan, info_);
    check_device_memory(plan, info_, max_chunk, device_.get_info<cl_ulong>(CL_DEVICE_MAX_MEM_ALLOC_SIZE));
    features_ = plan.kernel.features;
    hist_size_ = plan.hist_size;  // every histogram: frames of the map, then the zoom
    lanes_ = info_.is_cpu ? 8 : 1;
    if (const char* env = std::getenv("ARNOLDWEB_OPENCL_LANES")) lanes_ = std::atoi(env);
    if (lanes_ != 1 && lanes_ != 2 && lanes_ != 4 && lanes_ != 8 && lanes_ != 16)
      throw DeviceError(info_.id, "", 0, "ARNOLDWEB_OPENCL_LANES must be 1, 2, 4, 8 or 16");
    options_ = plan.kernel.defines() + " -DAW_LANES=" + std::to_string(lanes_);
    if (float_ && (device_.get_info<cl_device_fp_config>(CL_DEVICE_SINGLE_FP_CONFIG) &
                   CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT))
      options_ += " -cl-fp32-correctly-rounded-divide-sqrt";
    // extra compiler options, for experiments and diagnostics (like ARNOLDWEB_NVRTC_OPTIONS)
    if (const char* extra = std::getenv("ARNOLDWEB_OPENCL_OPTIONS")) options_ += std::string(" ") + extra;
    build();
    const std::size_t rs = float_ ? sizeof(float) : sizeof(double);
    try {
      wg_ = info_.is_cpu ? 16 : 128;
      wg_ = std::min<std::size_t>(wg_, ensemble_.get_work_group_info<std::size_t>(device_, CL_KERNEL_WORK_GROUP_SIZE));
      wg_ = floor_pow2(std::max<std::size_t>(wg_, 1));
      const std::size_t max_groups = (max_chunk / lanes_ + wg_) / wg_ + 1;
      std::vector<double> rpd = plan.rp;
      std::vector<float> rpf(plan.rp.begin(), plan.rp.end());
      rp_ = compute::buffer(context_, rpd.size() * rs, compute::buffer::read_only);
      queue_.enqueue_write_buffer(rp_, 0, rpd.size() * rs,
                                  float_ ? static_cast<const void*>(rpf.data()) : static_cast<const void*>(rpd.data()));
      ip_ = compute::buffer(context_, plan.ip.size() * 8, compute::buffer::read_only);
      queue_.enqueue_write_buffer(ip_, 0, plan.ip.size() * 8, plan.ip.data());
      const std::size_t npix = std::max<std::uint64_t>(hist_size_, 1);
      map32_ = zeroed(npix * 4);
      map64_ = zeroed(npix * 8);
      counters_ = compute::buffer(context_, AW_C_COUNT * 4);
      stats_ = compute::buffer(context_, 2 * max_groups * rs);
      dummy_ = compute::buffer(context_, 64);
      initial_ = (features_ & AW_F_INITIAL_STATES) ? compute::buffer(context_, max_chunk * AW_STATE_REALS * rs) : dummy_;
      final_r_ = (features_ & AW_F_FINAL_STATES) ? compute::buffer(context_, max_chunk * AW_STATE_REALS * rs) : dummy_;
      final_i_ = (features_ & AW_F_FINAL_STATES) ? compute::buffer(context_, max_chunk * AW_STATE_INTS * 8) : dummy_;
      queue_.finish();
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clCreateBuffer", e);
    }
  }

  void run_chunk(std::uint64_t first, std::uint64_t count, ChunkOutput& out) override {
    const std::size_t rs = float_ ? sizeof(float) : sizeof(double);
    const std::size_t items = (count + lanes_ - 1) / lanes_;
    const std::size_t global = (items + wg_ - 1) / wg_ * wg_;
    const std::size_t groups = global / wg_;
    const char* call = "clEnqueueNDRangeKernel";
    try {
      out.counters.assign(AW_C_COUNT, 0);
      call = "clEnqueueWriteBuffer";
      queue_.enqueue_write_buffer(counters_, 0, AW_C_COUNT * 4, out.counters.data());
      compute::kernel& k = ensemble_;
      k.set_arg(0, static_cast<cl_ulong>(first));
      k.set_arg(1, static_cast<cl_ulong>(first + count));
      k.set_arg(2, rp_);
      k.set_arg(3, ip_);
      k.set_arg(4, map32_);
      k.set_arg(5, counters_);
      k.set_arg(6, initial_);
      k.set_arg(7, final_r_);
      k.set_arg(8, final_i_);
      k.set_arg(9, stats_);
      k.set_arg(10, 2 * wg_ * rs, nullptr);
      call = "clEnqueueNDRangeKernel";
      queue_.enqueue_1d_range_kernel(k, 0, global, wg_);
      if (hist_size_) {
        fold_.set_arg(0, map64_);
        fold_.set_arg(1, map32_);
        fold_.set_arg(2, static_cast<cl_ulong>(hist_size_));
        const std::size_t fg = (hist_size_ + 255) / 256 * 256;
        queue_.enqueue_1d_range_kernel(fold_, 0, fg, 0);
      }
      call = "clEnqueueReadBuffer";
      queue_.enqueue_read_buffer(counters_, 0, AW_C_COUNT * 4, out.counters.data());
      read_reals(stats_, 2 * groups, out.group_stats);
      if (features_ & AW_F_INITIAL_STATES) read_reals(initial_, count * AW_STATE_REALS, out.initial_r);
      if (features_ & AW_F_FINAL_STATES) {
        read_reals(final_r_, count * AW_STATE_REALS, out.final_r);
        out.final_i.assign(count * AW_STATE_INTS, 0);
        queue_.enqueue_read_buffer(final_i_, 0, count * AW_STATE_INTS * 8, out.final_i.data());
      }
      call = "clFinish";
      queue_.finish();
    } catch (const compute::opencl_error& e) {
      rethrow(info_, call, e);
    }
  }

  std::vector<std::uint64_t> read_histograms() override {
    std::vector<std::uint64_t> m(hist_size_);
    try {
      if (hist_size_) queue_.enqueue_read_buffer(map64_, 0, hist_size_ * 8, m.data());
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clEnqueueReadBuffer", e);
    }
    return m;
  }

  std::uint64_t preferred_chunk() const override {
    return static_cast<std::uint64_t>(info_.compute_units) * wg_ * lanes_ * (info_.is_cpu ? 4 : 16);
  }

  std::string kernel_description() const override { return "OpenCL C: " + options_; }

 private:
  compute::buffer zeroed(std::size_t bytes) {
    compute::buffer b(context_, bytes);
    std::vector<unsigned char> z(bytes, 0);
    queue_.enqueue_write_buffer(b, 0, bytes, z.data());
    return b;
  }

  void read_reals(const compute::buffer& b, std::size_t n, std::vector<double>& out) {
    out.assign(n, 0.0);
    if (!float_) {
      queue_.enqueue_read_buffer(b, 0, n * 8, out.data());
      return;
    }
    std::vector<float> f(n);
    queue_.enqueue_read_buffer(b, 0, n * 4, f.data());
    std::copy(f.begin(), f.end(), out.begin());
  }

  void build() {
    std::lock_guard<std::mutex> lock(build_mutex);
    auto cache = compute::program_cache::get_global_cache(context_);
    const std::string key = "arnoldweb.ensemble." + std::to_string(std::hash<std::string>()(ensemble_source()));
    auto cached = cache->get(key, options_);
    compute::program program;
    if (cached) {
      program = *cached;
    } else {
      try {
        program = compute::program::create_with_source(ensemble_source(), context_);
      } catch (const compute::opencl_error& e) {
        rethrow(info_, "clCreateProgramWithSource", e);
      }
      try {
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
    } catch (const compute::opencl_error& e) {
      rethrow(info_, "clCreateKernel", e);
    }
  }

  compute::device device_;
  DeviceInfo info_;
  compute::context context_;
  compute::command_queue queue_;
  compute::kernel ensemble_, fold_;
  compute::buffer rp_, ip_, map32_, map64_, counters_, stats_, dummy_, initial_, final_r_, final_i_;
  std::string options_;
  bool float_ = false;
  std::uint32_t features_ = 0;
  std::uint64_t hist_size_ = 0;
  int lanes_ = 1;
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
  return std::make_unique<OpenclBackend>(index);
}

}  // namespace arnoldweb::detail
