// arnoldweb: the CUDA device. The kernels for a plan are compiled at run time
// by NVRTC from the embedded sources (kernels_cu/ensemble.cu over lib/device)
// with the plan's -D options (nvrtc_compiler.cpp), cached in memory and on
// disk (kernel_cache.cpp), and loaded with the runtime's library API
// (cudaLibraryLoadData). The runtime is linked statically and loads the
// driver itself: no libcuda at link time. One trajectory per thread; blocks
// of 128 threads.
#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "arnoldweb/errors.hpp"
#include "aw_params.h"
#include "backends/backends.hpp"
#include "backends/compute_device.hpp"
#include "backends/cuda/cuda_device.hpp"
#include "backends/cuda/cuda_error.hpp"
#include "backends/cuda/cuda_resources.hpp"
#include "backends/cuda/kernel_cache.hpp"
#include "backends/cuda/nvrtc_compiler.hpp"

namespace arnoldweb::detail {
namespace {

constexpr unsigned kBlock = 128;     // threads per block (a power of two: aw_group_reduce)
constexpr unsigned kFoldBlock = 256;
constexpr unsigned kFreqBlock = 128;  // threads per block of aw_frequencies (4 warps: 4 trajectories)

class CudaMemory final : public DeviceMemory {
 public:
  CudaMemory(std::size_t bytes, const std::string& device, const char* what)
      : DeviceMemory(bytes), buffer(bytes, device, what) {}
  DeviceBuffer buffer;
};

void* dptr(DeviceMemory* m) { return m ? static_cast<CudaMemory*>(m)->buffer.get() : nullptr; }
const void* dptr(const DeviceMemory& m) { return static_cast<const CudaMemory&>(m).buffer.get(); }

class CudaDevice final : public ComputeDevice {
 public:
  explicit CudaDevice(int ordinal) : ordinal_(ordinal) {
    info_ = cuda_describe(ordinal);
    cc_ = cuda_compute_capability(ordinal);
    select();
    // Wait for the GPU by blocking, not spinning: the host's cores stay free.
    // Only possible before the device's context exists; otherwise keep it.
    if (cudaSetDeviceFlags(cudaDeviceScheduleBlockingSync) != cudaSuccess) cudaGetLastError();
    stream_ = Stream(info_.id);
  }

  ~CudaDevice() override {
    // Free on this backend's device; members release themselves quietly.
    if (cudaSetDevice(ordinal_) != cudaSuccess) cudaGetLastError();
  }

  const DeviceInfo& info() const override { return info_; }

  std::uint64_t free_memory() const override {
    std::size_t free_b = 0, total_b = 0;
    // this device's memory, whichever device the calling thread had selected
    if (cudaSetDevice(ordinal_) != cudaSuccess) cudaGetLastError();
    if (cudaMemGetInfo(&free_b, &total_b) != cudaSuccess) {
      cudaGetLastError();
      return 0;
    }
    return free_b;
  }

  void compile(const KernelConfig& config) override {
    select();
    real_size_ = config.precision == Precision::Float ? sizeof(float) : sizeof(double);
    defines_ = config.defines();
    frequencies_ = (config.features & AW_F_FREQUENCIES) != 0;
    model_source_ = config.model_source;
    target_ = nvrtc_target(cc_, label());
    load();
  }

  std::string kernel_description() const override {
    std::string d = "CUDA NVRTC " + target_.name() + ": " + options_;
    if (!target_.cubin) d += " (PTX, compiled by the driver for compute " + std::to_string(cc_ / 10) +
                             "." + std::to_string(cc_ % 10) + ")";
    return d + "; block " + std::to_string(block_);
  }
  std::string kernel_origin() const override { return origin_; }

  std::unique_ptr<DeviceMemory> allocate(std::size_t bytes, const char* what) override {
    select();
    return std::make_unique<CudaMemory>(bytes, info_.id, what);
  }
  void upload(DeviceMemory& to, const void* from, std::size_t bytes) override {
    if (bytes) cuda_check(cudaMemcpy(dptr(&to), from, bytes, cudaMemcpyHostToDevice), info_.id, "cudaMemcpy");
  }
  void download(const DeviceMemory& from, void* to, std::size_t bytes) override {
    if (bytes) cuda_check(cudaMemcpy(to, dptr(from), bytes, cudaMemcpyDeviceToHost), info_.id, "cudaMemcpy");
  }
  // Large read-backs go into memory locked while the kernels run: a copy into
  // pageable memory goes through the driver's staging at ~11 GB/s (84 MB of
  // frequency records: 7.9 ms of a 0.25 s run on an H200). Unlocking took
  // 1.8 ms for the 43 MB of one launch's records: the handle unlocks when the
  // records it travels with are freed, with the runtime alone (the device may
  // be gone by then). Where locking fails, the copy is the pageable one.
  std::shared_ptr<void> hold_for_download(void* to, std::size_t bytes) override {
    if (bytes < kLockFrom) return nullptr;
    select();
    if (cudaHostRegister(to, bytes, cudaHostRegisterDefault) != cudaSuccess) {
      cudaGetLastError();
      return nullptr;
    }
    return std::shared_ptr<void>(to, [](void* p) {
      if (cudaHostUnregister(p) != cudaSuccess) cudaGetLastError();
    });
  }
  void zero(DeviceMemory& m) override {
    cuda_check(cudaMemsetAsync(dptr(&m), 0, m.bytes(), stream_.get()), info_.id, "cudaMemsetAsync");
  }

  LaunchShape shape(std::uint64_t count) const override {
    LaunchShape s;
    s.groups = (count + block_ - 1) / block_;
    s.group_size = block_;
    s.items = s.groups * block_;
    return s;
  }

  void launch_ensemble(const LaunchRange& r, const LaunchShape& s, const EnsembleBuffers& b) override {
    if (!ensemble_) throw DeviceError(info_.id, "", 0, "launch before compile");
    if (s.groups > static_cast<std::uint64_t>(INT_MAX))
      throw DeviceError(info_.id, "", 0, "chunk too large for one launch; set ensemble.chunk smaller");
    select();
    unsigned long long chunk_first = r.first, chunk_end = r.first + r.count;
    long long seg_first = r.seg_first, seg_end = r.seg_end;
    void* buffers[AW_BUF_COUNT];
    void* args[4 + AW_BUF_COUNT] = {&chunk_first, &chunk_end, &seg_first, &seg_end};
    buffer_args(b, buffers, args + 4);
    cuda_check(cudaLaunchKernel(reinterpret_cast<const void*>(ensemble_), dim3(static_cast<unsigned>(s.groups)),
                                dim3(block_), args, 2 * block_ * real_size_, stream_.get()),
               info_.id, "cudaLaunchKernel",
               "aw_ensemble over trajectories [" + std::to_string(r.first) + ", " + std::to_string(r.first + r.count) + ")");
  }

  void launch_frequencies(const LaunchRange& r, const LaunchShape&, const EnsembleBuffers& b) override {
    if (!frequencies_kernel_) throw DeviceError(info_.id, "", 0, "launch before compile");
    select();
    unsigned long long chunk_first = r.first, chunk_end = r.first + r.count;
    void* buffers[AW_BUF_COUNT];
    void* args[2 + AW_BUF_COUNT] = {&chunk_first, &chunk_end};
    buffer_args(b, buffers, args + 2);
    // a warp per trajectory (kernels_cu/ensemble.cu: blocks of kFreqBlock threads)
    const std::uint64_t groups = (r.count * AW_NAFF_TEAM + kFreqBlock - 1) / kFreqBlock;
    if (groups > static_cast<std::uint64_t>(INT_MAX))
      throw DeviceError(info_.id, "", 0, "chunk too large for one launch; set ensemble.chunk smaller");
    cuda_check(cudaLaunchKernel(reinterpret_cast<const void*>(frequencies_kernel_),
                                dim3(static_cast<unsigned>(groups)), dim3(kFreqBlock), args, 0, stream_.get()),
               info_.id, "cudaLaunchKernel",
               "aw_frequencies over trajectories [" + std::to_string(r.first) + ", " +
                   std::to_string(r.first + r.count) + ")");
  }

  void launch_fold(DeviceMemory& total, DeviceMemory& part, std::uint64_t n) override {
    void* t = dptr(&total);
    void* p = dptr(&part);
    unsigned long long count = n;
    void* args[] = {&t, &p, &count};
    const unsigned fg = static_cast<unsigned>((n + kFoldBlock - 1) / kFoldBlock);
    cuda_check(cudaLaunchKernel(reinterpret_cast<const void*>(fold_), dim3(fg), dim3(kFoldBlock), args, 0,
                                stream_.get()),
               info_.id, "cudaLaunchKernel", "aw_fold");
  }

  // Errors inside the kernels surface here.
  void finish(const std::string& what) override {
    cuda_check(cudaStreamSynchronize(stream_.get()), info_.id, "cudaStreamSynchronize", "running " + what);
  }

  std::uint64_t preferred_chunk() const override {
    // Four full waves of resident blocks (the runner starts at a quarter).
    const std::uint64_t per_sm = std::max(1, blocks_per_sm_);
    return static_cast<std::uint64_t>(std::max(1u, info_.compute_units)) * per_sm * block_ * 4;
  }

 private:
  // The kernels' buffer arguments (AW_BUFFERS, null where the plan needs none): the device
  // pointers into `buffers`, their addresses into `args`.
  static void buffer_args(const EnsembleBuffers& b, void** buffers, void** args) {
    for (int i = 0; i < AW_BUF_COUNT; ++i) {
      buffers[i] = dptr(b.at[i]);
      args[i] = &buffers[i];
    }
  }

  void select() { cuda_check(cudaSetDevice(ordinal_), info_.id, "cudaSetDevice"); }
  std::string label() const { return info_.id + " (" + info_.name + ")"; }

  // Compiles (or finds) the image and loads it; a cached image that does not
  // load is forgotten and compiled afresh once.
  void load() {
    ensemble_ = nullptr;
    fold_ = nullptr;
    frequencies_kernel_ = nullptr;
    library_.reset();
    CachedImage img = cuda_ensemble_image(defines_, target_, label(), model_source_);
    cudaError_t e = try_load(*img.image);
    if (e != cudaSuccess && img.origin != "compiled") {
      cuda_forget_image(defines_, target_, model_source_);
      img = cuda_ensemble_image(defines_, target_, label(), model_source_);
      e = try_load(*img.image);
    }
    if (e != cudaSuccess) {
      std::string why = "loading the " + target_.name() + " kernel image (" +
                        std::to_string(img.image->data.size()) + " bytes, NVRTC " + nvrtc_version() + ")";
      if (!jit_log_.empty()) why += "; driver log: " + jit_log_;
      throw_cuda(info_.id, "cudaLibraryLoadData", e, why);
    }
    options_ = img.image->options;
    origin_ = img.origin;

    cudaKernel_t k = nullptr;
    cuda_check(cudaLibraryGetKernel(&k, library_.get(), "aw_ensemble"), info_.id, "cudaLibraryGetKernel",
               "aw_ensemble");
    ensemble_ = k;
    cuda_check(cudaLibraryGetKernel(&k, library_.get(), "aw_fold"), info_.id, "cudaLibraryGetKernel",
               "aw_fold");
    fold_ = k;
    if (frequencies_) {
      cuda_check(cudaLibraryGetKernel(&k, library_.get(), "aw_frequencies"), info_.id, "cudaLibraryGetKernel",
                 "aw_frequencies");
      frequencies_kernel_ = k;
    }

    cudaFuncAttributes attr{};
    cuda_check(cudaFuncGetAttributes(&attr, reinterpret_cast<const void*>(ensemble_)), info_.id,
               "cudaFuncGetAttributes", "aw_ensemble");
    unsigned block = kBlock;
    if (const char* env = std::getenv("ARNOLDWEB_CUDA_BLOCK")) {
      const int b = std::atoi(env);
      if (b < 32 || b > 1024 || (b & (b - 1)) != 0)
        throw DeviceError(info_.id, "", 0, "ARNOLDWEB_CUDA_BLOCK must be a power of two from 32 to 1024");
      block = static_cast<unsigned>(b);
    }
    block_ = static_cast<unsigned>(
        floor_pow2(std::max<std::uint64_t>(1, std::min<std::uint64_t>(block, attr.maxThreadsPerBlock))));
    int per_sm = 0;
    if (cudaOccupancyMaxActiveBlocksPerMultiprocessor(&per_sm, reinterpret_cast<const void*>(ensemble_),
                                                      static_cast<int>(block_),
                                                      2 * block_ * real_size_) != cudaSuccess) {
      cudaGetLastError();
      per_sm = 4;
    }
    blocks_per_sm_ = per_sm > 0 ? per_sm : 1;
  }

  cudaError_t try_load(const CudaImage& img) {
    library_.reset();
    char log[4096] = {0};
    cudaJitOption opts[] = {cudaJitErrorLogBuffer, cudaJitErrorLogBufferSizeBytes};
    void* vals[] = {log, reinterpret_cast<void*>(static_cast<std::uintptr_t>(sizeof log))};
    cudaLibrary_t lib = nullptr;
    const cudaError_t e = cudaLibraryLoadData(&lib, img.data.data(), opts, vals, 2, nullptr, nullptr, 0);
    jit_log_ = log;
    if (e != cudaSuccess) {
      cudaGetLastError();
      return e;
    }
    library_ = KernelLibrary(lib);
    return cudaSuccess;
  }

  static constexpr std::size_t kLockFrom = std::size_t{4} << 20;  // bytes: smaller read-backs stay pageable
  int ordinal_;
  int cc_ = 0;
  DeviceInfo info_;
  Stream stream_;
  KernelLibrary library_;
  cudaKernel_t ensemble_ = nullptr, fold_ = nullptr, frequencies_kernel_ = nullptr;
  bool frequencies_ = false;
  CudaTarget target_;
  std::string defines_, options_, jit_log_, origin_;
  std::string model_source_;  // an expression model's header, or empty
  std::size_t real_size_ = 8;
  unsigned block_ = kBlock;
  int blocks_per_sm_ = 4;
};

}  // namespace

std::unique_ptr<Backend> make_cuda_backend(int index) {
  return make_ensemble_backend(std::make_unique<CudaDevice>(index));
}

}  // namespace arnoldweb::detail
