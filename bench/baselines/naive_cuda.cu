// arnoldweb bench: the NVIDIA baseline (see naive.hpp): one trajectory per
// CUDA thread, CUDA's sincos, nvcc's default options (FMA contraction on, no
// fast-math). Built as a shared library that the bench loads with dlopen, so
// the bench builds and runs without CUDA and times both in one process.
#include <cuda_runtime.h>

#include <cstdio>
#include <cstring>
#include <vector>

#include "naive.hpp"

#define NAIVE_FN __device__ __forceinline__
#define NAIVE_SINCOS(x, s, c) sincos((x), (s), (c))
#define NAIVE_COS(x) cos(x)
#include "naive_kernel.inc"

namespace {

__constant__ double c_drift_d[17], c_kick_d[18];
__constant__ float c_drift_f[17], c_kick_f[18];

template <class T> __device__ const T* drift_table();
template <class T> __device__ const T* kick_table();
template <> __device__ const double* drift_table<double>() { return c_drift_d; }
template <> __device__ const double* kick_table<double>() { return c_kick_d; }
template <> __device__ const float* drift_table<float>() { return c_drift_f; }
template <> __device__ const float* kick_table<float>() { return c_kick_f; }

template <class T>
__global__ void aw_naive_yoshida(const double* __restrict__ init, unsigned long long n, long long steps,
                                 long long every, int stages, T* __restrict__ emax,
                                 unsigned int* __restrict__ hist, int bins_theta, int bins_phi) {
  const unsigned long long i = (unsigned long long)blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  T vx, vy, vz;
  emax[i] = naive_trajectory<T>(init + 6 * i, steps, every, stages, drift_table<T>(), kick_table<T>(),
                                &vx, &vy, &vz);
  const int b = naive_bin<T>(vx, vy, vz, bins_theta, bins_phi);
  if (b >= 0) atomicAdd(&hist[b], 1u);
}

struct Fail {
  const char* call;
  cudaError_t e;
};

void check(cudaError_t e, const char* call) {
  if (e != cudaSuccess) throw Fail{call, e};
}

template <class T>
void run(const AwNaiveArgs& a, AwNaiveOut& out) {
  check(cudaSetDevice(a.device), "cudaSetDevice");
  cudaDeviceProp prop{};
  check(cudaGetDeviceProperties(&prop, a.device), "cudaGetDeviceProperties");
  std::snprintf(out.device_name, sizeof out.device_name, "%s", prop.name);
  T drift[17], kick[18];
  for (int i = 0; i < 17; ++i) drift[i] = T(a.drift[i]);
  for (int i = 0; i < 18; ++i) kick[i] = T(a.kick[i]);
  if (sizeof(T) == 8) {
    check(cudaMemcpyToSymbol(c_drift_d, drift, sizeof drift), "cudaMemcpyToSymbol");
    check(cudaMemcpyToSymbol(c_kick_d, kick, sizeof kick), "cudaMemcpyToSymbol");
  } else {
    check(cudaMemcpyToSymbol(c_drift_f, drift, sizeof drift), "cudaMemcpyToSymbol");
    check(cudaMemcpyToSymbol(c_kick_f, kick, sizeof kick), "cudaMemcpyToSymbol");
  }
  const std::size_t nbins = static_cast<std::size_t>(a.bins_theta) * a.bins_phi;
  double* d_init = nullptr;
  T* d_emax = nullptr;
  unsigned int* d_hist = nullptr;
  cudaEvent_t e0 = nullptr, e1 = nullptr;
  try {
    check(cudaMalloc(&d_init, a.n * 6 * sizeof(double)), "cudaMalloc");
    check(cudaMalloc(&d_emax, a.n * sizeof(T)), "cudaMalloc");
    check(cudaMalloc(&d_hist, nbins * sizeof(unsigned int)), "cudaMalloc");
    check(cudaMemcpy(d_init, a.init, a.n * 6 * sizeof(double), cudaMemcpyHostToDevice), "cudaMemcpy");
    check(cudaMemset(d_hist, 0, nbins * sizeof(unsigned int)), "cudaMemset");
    check(cudaEventCreate(&e0), "cudaEventCreate");
    check(cudaEventCreate(&e1), "cudaEventCreate");
    const unsigned block = a.block > 0 ? static_cast<unsigned>(a.block) : 256u;
    // warm-up: module load and first launch stay out of the timing
    const unsigned long long nw = a.n < 4096 ? a.n : 4096;
    aw_naive_yoshida<T><<<static_cast<unsigned>((nw + block - 1) / block), block>>>(
        d_init, nw, a.steps < 10 ? a.steps : 10, a.energy_every, a.stages, d_emax, d_hist, a.bins_theta,
        a.bins_phi);
    check(cudaGetLastError(), "warm-up launch");
    check(cudaDeviceSynchronize(), "cudaDeviceSynchronize");
    check(cudaMemset(d_hist, 0, nbins * sizeof(unsigned int)), "cudaMemset");
    check(cudaEventRecord(e0), "cudaEventRecord");
    aw_naive_yoshida<T><<<static_cast<unsigned>((a.n + block - 1) / block), block>>>(
        d_init, a.n, a.steps, a.energy_every, a.stages, d_emax, d_hist, a.bins_theta, a.bins_phi);
    check(cudaGetLastError(), "cudaLaunchKernel aw_naive_yoshida");
    check(cudaEventRecord(e1), "cudaEventRecord");
    check(cudaEventSynchronize(e1), "cudaEventSynchronize");
    float ms = 0;
    check(cudaEventElapsedTime(&ms, e0, e1), "cudaEventElapsedTime");
    out.seconds = ms * 1e-3;
    std::vector<T> em(a.n);
    std::vector<unsigned int> hist(nbins);
    check(cudaMemcpy(em.data(), d_emax, a.n * sizeof(T), cudaMemcpyDeviceToHost), "cudaMemcpy");
    check(cudaMemcpy(hist.data(), d_hist, nbins * sizeof(unsigned int), cudaMemcpyDeviceToHost), "cudaMemcpy");
    out.emax = 0;
    for (T v : em) out.emax = static_cast<double>(v) > out.emax ? static_cast<double>(v) : out.emax;
    out.binned = 0;
    for (unsigned int c : hist) out.binned += c;
  } catch (...) {
    cudaFree(d_init);
    cudaFree(d_emax);
    cudaFree(d_hist);
    if (e0) cudaEventDestroy(e0);
    if (e1) cudaEventDestroy(e1);
    throw;
  }
  cudaFree(d_init);
  cudaFree(d_emax);
  cudaFree(d_hist);
  cudaEventDestroy(e0);
  cudaEventDestroy(e1);
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int aw_naive_cuda_run(const AwNaiveArgs* a, AwNaiveOut* out) {
  std::memset(out, 0, sizeof *out);
  try {
    if (a->stages < 1 || a->stages > 16) {
      std::snprintf(out->error, sizeof out->error, "stages must be 1..16");
      return 1;
    }
    if (a->use_float)
      run<float>(*a, *out);
    else
      run<double>(*a, *out);
    return 0;
  } catch (const Fail& f) {
    cudaGetLastError();
    std::snprintf(out->error, sizeof out->error, "%s: %s (%d)", f.call, cudaGetErrorString(f.e),
                  static_cast<int>(f.e));
    return 1;
  }
}

extern "C" __attribute__((visibility("default"))) int aw_naive_cuda_mem_info(int device, unsigned long long* free_b,
                                                                           unsigned long long* total_b) {
  if (cudaSetDevice(device) != cudaSuccess) return 1;
  std::size_t f = 0, t = 0;
  if (cudaMemGetInfo(&f, &t) != cudaSuccess) {
    cudaGetLastError();
    return 1;
  }
  *free_b = f;
  *total_b = t;
  return 0;
}
