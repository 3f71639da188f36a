// arnoldweb: the CUDA backend. Mirrors the OpenCL backend: the kernel for a
// plan is compiled at run time by NVRTC from the embedded sources
// (kernels_cu/ensemble.cu over lib/device) with the plan's -D options
// (nvrtc_compiler.cpp), cached in memory and on disk (kernel_cache.cpp), and
// loaded with the runtime's library API (cudaLibraryLoadData). The runtime is
// linked statically and loads the driver itself: no libcuda at link time.
// One trajectory per thread; blocks of 128 threads.
#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "arnoldweb/errors.hpp"
#include "aw_params.h"
#include "backends/backends.hpp"
#include "backends/cuda/cuda_device.hpp"
#include "backends/cuda/cuda_error.hpp"
#include "backends/cuda/cuda_resources.hpp"
#include "backends/cuda/kernel_cache.hpp"
#include "backends/cuda/nvrtc_compiler.hpp"

namespace arnoldweb::detail {
namespace {

constexpr unsigned kBlock = 128;     // threads per block (a power of two: aw_group_reduce)
constexpr unsigned kFoldBlock = 256;

std::string mib(double bytes) { return std::to_string(static_cast<long long>(bytes / 1048576.0)) + " MiB"; }

class CudaBackend final : public Backend {
 public:
  explicit CudaBackend(int ordinal) : ordinal_(ordinal) {
    info_ = cuda_describe(ordinal);
    cc_ = cuda_compute_capability(ordinal);
    select();
    // Wait for the GPU by blocking, not spinning: the host's cores stay free.
    // Only possible before the device's context exists; otherwise keep it.
    if (cudaSetDeviceFlags(cudaDeviceScheduleBlockingSync) != cudaSuccess) cudaGetLastError();
    stream_ = Stream(info_.id);
  }

  ~CudaBackend() override {
    // Free on this backend's device; members release themselves quietly.
    if (cudaSetDevice(ordinal_) != cudaSuccess) cudaGetLastError();
  }

  const DeviceInfo& info() const override { return info_; }

  void prepare(const Plan& plan, std::uint64_t max_chunk) override {
    select();
    check_device_memory(plan, info_, max_chunk, info_.memory);
    float_ = plan.kernel.precision == Precision::Float;
    features_ = plan.kernel.features;
    hist_size_ = plan.hist_size;  // every histogram: frames of the map, then the zoom
    max_chunk_ = max_chunk;
    defines_ = plan.kernel.defines();
    target_ = nvrtc_target(cc_, info_.id + " (" + info_.name + ")");
    load();
    allocate(plan);
  }

  void run_chunk(std::uint64_t first, std::uint64_t count, ChunkOutput& out) override {
    if (!ensemble_) throw DeviceError(info_.id, "", 0, "run_chunk before prepare");
    if (count > max_chunk_)
      throw DeviceError(info_.id, "", 0,
                        "chunk of " + std::to_string(count) + " trajectories exceeds the prepared " +
                            std::to_string(max_chunk_));
    select();
    const std::size_t rs = real_size();
    const std::uint64_t groups64 = (count + block_ - 1) / block_;
    if (groups64 > static_cast<std::uint64_t>(INT_MAX))
      throw DeviceError(info_.id, "", 0, "chunk too large for one launch; set ensemble.chunk smaller");
    const unsigned groups = static_cast<unsigned>(groups64);
    const std::string range =
        "trajectories [" + std::to_string(first) + ", " + std::to_string(first + count) + ")";
    cudaStream_t s = stream_.get();

    out.counters.assign(AW_C_COUNT, 0);
    cuda_check(cudaMemsetAsync(counters_.get(), 0, AW_C_COUNT * 4, s), info_.id, "cudaMemsetAsync");

    if (count > 0) {
      unsigned long long chunk_first = first, chunk_end = first + count;
      void* rp = rp_.get();
      void* ip = ip_.get();
      void* map = map32_.get();
      void* counters = counters_.get();
      void* initial = initial_.get();
      void* final_r = final_r_.get();
      void* final_i = final_i_.get();
      void* stats = stats_.get();
      void* args[] = {&chunk_first, &chunk_end, &rp, &ip, &map, &counters,
                      &initial, &final_r, &final_i, &stats};
      cuda_check(cudaLaunchKernel(reinterpret_cast<const void*>(ensemble_), dim3(groups), dim3(block_),
                                  args, 2 * block_ * rs, s),
                 info_.id, "cudaLaunchKernel", "aw_ensemble over " + range);
    }
    if (hist_size_) {
      void* total = map64_.get();
      void* part = map32_.get();
      unsigned long long n = hist_size_;
      void* args[] = {&total, &part, &n};
      const unsigned fg = static_cast<unsigned>((hist_size_ + kFoldBlock - 1) / kFoldBlock);
      cuda_check(cudaLaunchKernel(reinterpret_cast<const void*>(fold_), dim3(fg), dim3(kFoldBlock),
                                  args, 0, s),
                 info_.id, "cudaLaunchKernel", "aw_fold");
    }
    // Errors inside the kernels surface here.
    cuda_check(cudaStreamSynchronize(s), info_.id, "cudaStreamSynchronize",
               "running aw_ensemble over " + range);

    download(counters_, out.counters.data(), AW_C_COUNT * 4);
    read_reals(stats_, 2 * static_cast<std::size_t>(groups), out.group_stats);
    if (features_ & AW_F_INITIAL_STATES) read_reals(initial_, count * AW_STATE_REALS, out.initial_r);
    if (features_ & AW_F_FINAL_STATES) {
      read_reals(final_r_, count * AW_STATE_REALS, out.final_r);
      out.final_i.assign(count * AW_STATE_INTS, 0);
      download(final_i_, out.final_i.data(), count * AW_STATE_INTS * 8);
    }
  }

  std::vector<std::uint64_t> read_histograms() override {
    std::vector<std::uint64_t> m(hist_size_);
    if (hist_size_) {
      select();
      download(map64_, m.data(), hist_size_ * 8);
    }
    return m;
  }

  std::uint64_t preferred_chunk() const override {
    // Four full waves of resident blocks (the runner starts at a quarter).
    const std::uint64_t per_sm = std::max(1, blocks_per_sm_);
    return static_cast<std::uint64_t>(std::max(1u, info_.compute_units)) * per_sm * block_ * 4;
  }

  std::string kernel_description() const override {
    std::string d = "CUDA NVRTC " + target_.name() + ": " + options_;
    if (!target_.cubin) d += " (PTX, compiled by the driver for compute " + std::to_string(cc_ / 10) +
                             "." + std::to_string(cc_ % 10) + ")";
    return d + "; block " + std::to_string(block_);
  }

 private:
  void select() {
    cuda_check(cudaSetDevice(ordinal_), info_.id, "cudaSetDevice");
  }

  std::size_t real_size() const { return float_ ? sizeof(float) : sizeof(double); }

  std::string label() const { return info_.id + " (" + info_.name + ")"; }

  // Compiles (or finds) the image and loads it; a cached image that does not
  // load is forgotten and compiled afresh once.
  void load() {
    ensemble_ = nullptr;
    fold_ = nullptr;
    library_.reset();
    CachedImage img = cuda_ensemble_image(defines_, target_, label());
    cudaError_t e = try_load(*img.image);
    if (e != cudaSuccess && img.origin != "compiled") {
      cuda_forget_image(defines_, target_);
      img = cuda_ensemble_image(defines_, target_, label());
      e = try_load(*img.image);
    }
    if (e != cudaSuccess) {
      std::string why = "loading the " + target_.name() + " kernel image (" +
                        std::to_string(img.image->data.size()) + " bytes, NVRTC " + nvrtc_version() + ")";
      if (!jit_log_.empty()) why += "; driver log: " + jit_log_;
      throw_cuda(info_.id, "cudaLibraryLoadData", e, why);
    }
    options_ = img.image->options;

    cudaKernel_t k = nullptr;
    cuda_check(cudaLibraryGetKernel(&k, library_.get(), "aw_ensemble"), info_.id, "cudaLibraryGetKernel",
               "aw_ensemble");
    ensemble_ = k;
    cuda_check(cudaLibraryGetKernel(&k, library_.get(), "aw_fold"), info_.id, "cudaLibraryGetKernel",
               "aw_fold");
    fold_ = k;

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
                                                      2 * block_ * real_size()) != cudaSuccess) {
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

  void allocate(const Plan& plan) {
    const std::size_t rs = real_size();
    const std::size_t max_groups = (max_chunk_ + block_ - 1) / block_ + 1;
    const std::size_t npix = std::max<std::uint64_t>(hist_size_, 1);
    const std::size_t state_r = (features_ & AW_F_INITIAL_STATES) ? max_chunk_ * AW_STATE_REALS * rs : 0;
    const std::size_t final_r = (features_ & AW_F_FINAL_STATES) ? max_chunk_ * AW_STATE_REALS * rs : 0;
    const std::size_t final_i = (features_ & AW_F_FINAL_STATES) ? max_chunk_ * AW_STATE_INTS * 8 : 0;

    // Release the previous plan's buffers before asking for new ones.
    rp_.reset(); ip_.reset(); map32_.reset(); map64_.reset(); counters_.reset(); stats_.reset();
    initial_.reset(); final_r_.reset(); final_i_.reset();

    const double need = static_cast<double>(plan.rp.size() * rs + plan.ip.size() * 8 + npix * 12 +
                                            AW_C_COUNT * 4 + 2 * max_groups * rs + state_r + final_r + final_i);
    std::size_t free_b = 0, total_b = 0;
    if (cudaMemGetInfo(&free_b, &total_b) == cudaSuccess && need > static_cast<double>(free_b))
      throw DeviceError(info_.id, "", 0,
                        "out of device memory: the run needs " + mib(need) + " on " + label() +
                            ", " + mib(static_cast<double>(free_b)) + " of " +
                            mib(static_cast<double>(total_b)) +
                            " are free; set ensemble.chunk smaller (state records) or "
                            "observe.velocity_map.nside smaller (map)");
    cudaGetLastError();

    rp_ = DeviceBuffer(plan.rp.size() * rs, info_.id, "the real parameters");
    if (float_) {
      std::vector<float> f(plan.rp.begin(), plan.rp.end());
      upload(rp_, f.data(), f.size() * sizeof(float));
    } else {
      upload(rp_, plan.rp.data(), plan.rp.size() * sizeof(double));
    }
    ip_ = DeviceBuffer(plan.ip.size() * 8, info_.id, "the integer parameters");
    upload(ip_, plan.ip.data(), plan.ip.size() * 8);
    map32_ = DeviceBuffer(npix * 4, info_.id, "the velocity map (32-bit chunk counts)");
    map64_ = DeviceBuffer(npix * 8, info_.id, "the velocity map (64-bit totals)");
    cuda_check(cudaMemset(map32_.get(), 0, npix * 4), info_.id, "cudaMemset");
    cuda_check(cudaMemset(map64_.get(), 0, npix * 8), info_.id, "cudaMemset");
    counters_ = DeviceBuffer(AW_C_COUNT * 4, info_.id, "the counters");
    stats_ = DeviceBuffer(2 * max_groups * rs, info_.id, "the energy statistics");
    if (state_r) initial_ = DeviceBuffer(state_r, info_.id, "initial states (ensemble.chunk per launch)");
    if (final_r) final_r_ = DeviceBuffer(final_r, info_.id, "final states (ensemble.chunk per launch)");
    if (final_i) final_i_ = DeviceBuffer(final_i, info_.id, "final states (ensemble.chunk per launch)");
    cuda_check(cudaDeviceSynchronize(), info_.id, "cudaDeviceSynchronize", "preparing buffers");
  }

  void upload(const DeviceBuffer& b, const void* src, std::size_t bytes) {
    if (bytes) cuda_check(cudaMemcpy(b.get(), src, bytes, cudaMemcpyHostToDevice), info_.id, "cudaMemcpy");
  }

  void download(const DeviceBuffer& b, void* dst, std::size_t bytes) {
    if (bytes) cuda_check(cudaMemcpy(dst, b.get(), bytes, cudaMemcpyDeviceToHost), info_.id, "cudaMemcpy");
  }

  void read_reals(const DeviceBuffer& b, std::size_t n, std::vector<double>& out) {
    out.assign(n, 0.0);
    if (!float_) {
      download(b, out.data(), n * sizeof(double));
      return;
    }
    std::vector<float> f(n);
    download(b, f.data(), n * sizeof(float));
    std::copy(f.begin(), f.end(), out.begin());
  }

  int ordinal_;
  int cc_ = 0;
  DeviceInfo info_;
  Stream stream_;
  KernelLibrary library_;
  cudaKernel_t ensemble_ = nullptr, fold_ = nullptr;
  DeviceBuffer rp_, ip_, map32_, map64_, counters_, stats_, initial_, final_r_, final_i_;
  CudaTarget target_;
  std::string defines_, options_, jit_log_;
  bool float_ = false;
  std::uint32_t features_ = 0;
  std::uint64_t hist_size_ = 0, max_chunk_ = 0;
  unsigned block_ = kBlock;
  int blocks_per_sm_ = 4;
};

}  // namespace

std::unique_ptr<Backend> make_cuda_backend(int index) { return std::make_unique<CudaBackend>(index); }

}  // namespace arnoldweb::detail
