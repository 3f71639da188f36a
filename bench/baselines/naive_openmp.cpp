// arnoldweb bench: the CPU baseline (see naive.hpp): scalar C++, one
// trajectory at a time, libm sin/cos, OpenMP over trajectories.
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "naive.hpp"

using std::acos;
using std::atan2;
using std::sqrt;

#define NAIVE_FN static inline
#define NAIVE_SINCOS(x, s, c) (*(s) = std::sin(x), *(c) = std::cos(x))
#define NAIVE_COS(x) std::cos(x)
#include "naive_kernel.inc"

namespace {

template <class T>
int run(const AwNaiveArgs& a, AwNaiveOut& out) {
  T drift[17], kick[18];
  for (int i = 0; i < 17; ++i) drift[i] = T(a.drift[i]);
  for (int i = 0; i < 18; ++i) kick[i] = T(a.kick[i]);
  const long long n = static_cast<long long>(a.n);
  std::vector<unsigned long long> hist(static_cast<std::size_t>(a.bins_theta) * a.bins_phi, 0);
  unsigned long long* h = hist.data();
  double emax = 0;
  const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(dynamic, 16) reduction(max : emax)
  for (long long i = 0; i < n; ++i) {
    T vx, vy, vz;
    const T e = naive_trajectory<T>(a.init + 6 * i, a.steps, a.energy_every, a.stages, drift, kick,
                                    &vx, &vy, &vz);
    emax = static_cast<double>(e) > emax ? static_cast<double>(e) : emax;
    const int b = naive_bin<T>(vx, vy, vz, a.bins_theta, a.bins_phi);
    if (b >= 0) {
#pragma omp atomic
      h[b] += 1;
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.emax = emax;
  out.binned = 0;
  for (auto c : hist) out.binned += c;
  std::snprintf(out.device_name, sizeof out.device_name, "CPU, %d OpenMP threads", omp_get_max_threads());
  return 0;
}

}  // namespace

extern "C" int aw_naive_openmp_run(const AwNaiveArgs* a, AwNaiveOut* out) {
  std::memset(out, 0, sizeof *out);
  if (a->stages < 1 || a->stages > 16) {
    std::snprintf(out->error, sizeof out->error, "stages must be 1..16");
    return 1;
  }
  return a->use_float ? run<float>(*a, *out) : run<double>(*a, *out);
}
