// arnoldweb: owners of CUDA runtime objects (device memory, a loaded kernel
// library, a stream). Move-only; destructors free quietly and never throw.
#pragma once

#include <cuda_runtime_api.h>

#include <cstddef>
#include <utility>

#include "backends/cuda/cuda_error.hpp"

namespace arnoldweb::detail {

class DeviceBuffer {
 public:
  DeviceBuffer() = default;
  // Allocates `bytes` (at least 1) on the current device; `what` names the
  // buffer in the error.
  DeviceBuffer(std::size_t bytes, const std::string& device, const char* what) : bytes_(bytes) {
    cudaError_t e = cudaMalloc(&ptr_, bytes ? bytes : 1);
    if (e != cudaSuccess) {
      ptr_ = nullptr;
      cudaGetLastError();
      throw_cuda(device, "cudaMalloc", e,
                 std::string("allocating ") + std::to_string(bytes) + " bytes for " + what);
    }
  }
  DeviceBuffer(DeviceBuffer&& o) noexcept
      : ptr_(std::exchange(o.ptr_, nullptr)), bytes_(std::exchange(o.bytes_, 0)) {}
  DeviceBuffer& operator=(DeviceBuffer&& o) noexcept {
    if (this != &o) {
      reset();
      ptr_ = std::exchange(o.ptr_, nullptr);
      bytes_ = std::exchange(o.bytes_, 0);
    }
    return *this;
  }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  ~DeviceBuffer() { reset(); }

  void reset() noexcept {
    if (ptr_) cudaFree(ptr_);
    ptr_ = nullptr;
    bytes_ = 0;
  }
  void* get() const noexcept { return ptr_; }
  std::size_t bytes() const noexcept { return bytes_; }

 private:
  void* ptr_ = nullptr;
  std::size_t bytes_ = 0;
};

class KernelLibrary {
 public:
  KernelLibrary() = default;
  explicit KernelLibrary(cudaLibrary_t lib) : lib_(lib) {}
  KernelLibrary(KernelLibrary&& o) noexcept : lib_(std::exchange(o.lib_, nullptr)) {}
  KernelLibrary& operator=(KernelLibrary&& o) noexcept {
    if (this != &o) {
      reset();
      lib_ = std::exchange(o.lib_, nullptr);
    }
    return *this;
  }
  KernelLibrary(const KernelLibrary&) = delete;
  KernelLibrary& operator=(const KernelLibrary&) = delete;
  ~KernelLibrary() { reset(); }

  void reset() noexcept {
    if (lib_) cudaLibraryUnload(lib_);
    lib_ = nullptr;
  }
  cudaLibrary_t get() const noexcept { return lib_; }

 private:
  cudaLibrary_t lib_ = nullptr;
};

class Stream {
 public:
  Stream() = default;
  explicit Stream(const std::string& device) {
    cuda_check(cudaStreamCreateWithFlags(&s_, cudaStreamNonBlocking), device,
               "cudaStreamCreateWithFlags");
  }
  Stream(Stream&& o) noexcept : s_(std::exchange(o.s_, nullptr)) {}
  Stream& operator=(Stream&& o) noexcept {
    if (this != &o) {
      reset();
      s_ = std::exchange(o.s_, nullptr);
    }
    return *this;
  }
  Stream(const Stream&) = delete;
  Stream& operator=(const Stream&) = delete;
  ~Stream() { reset(); }

  void reset() noexcept {
    if (s_) cudaStreamDestroy(s_);
    s_ = nullptr;
  }
  cudaStream_t get() const noexcept { return s_; }

 private:
  cudaStream_t s_ = nullptr;
};

}  // namespace arnoldweb::detail
