// arnoldweb bench: the plain baselines every throughput figure is divided by.
// The same Yoshida-6 loop written the obvious way: one trajectory at a time,
// positions in radians (never wrapped), the force from the vendor's sin/cos,
// the force at the end of a step reused at the start of the next (7 force
// evaluations per step, like the library), energy sampled every
// `energy_every` steps, the averaged velocity binned on a latitude-longitude
// grid with atomic increments.
//   naive_openmp.cpp: scalar C++, libm sin/cos, OpenMP over trajectories.
//   naive_cuda.cu:    one trajectory per CUDA thread, CUDA's sincos (built
//                     with nvcc when CMake finds CUDA; loaded at run time).
#pragma once

#include <cstdint>

extern "C" {

// Plain C so that the CUDA baseline can live in a shared library built by
// nvcc and be loaded with dlopen (same process, no link-time CUDA dependency).
struct AwNaiveArgs {
  int device;                 // CUDA ordinal (ignored by the OpenMP baseline)
  int use_float;              // 1: float everywhere, 0: double
  unsigned long long n;       // trajectories
  long long steps;            // steps per trajectory
  long long energy_every;     // steps between energy samples (0: no energy tracking)
  const double* init;         // 6 per trajectory: u_x, u_y, u_z (turns), p_x, p_y, p_z
  int stages;                 // force evaluations per step (kick-first method)
  double drift[17];           // a_i h (radians per unit momentum), i < stages
  double kick[18];            // b_i h, i <= stages
  double step_time;           // h (time units), for the averaged velocity
  int bins_theta, bins_phi;   // velocity histogram
  int block;                  // CUDA threads per block (0: 256)
};

struct AwNaiveOut {
  double seconds;             // the timed run (after a warm-up launch), device time
  double emax;                // max over trajectories of max |dE|
  unsigned long long binned;  // histogram total (== n unless non-finite)
  char device_name[128];
  char error[512];            // empty on success
};

// Returns 0 on success; on failure fills out->error and returns non-zero.
int aw_naive_openmp_run(const AwNaiveArgs* args, AwNaiveOut* out);

// Exported by libarnoldweb_naive_cuda.so (bench/baselines/naive_cuda.cu).
typedef int (*AwNaiveCudaRun)(const AwNaiveArgs*, AwNaiveOut*);
typedef int (*AwNaiveCudaMemInfo)(int device, unsigned long long* free_bytes,
                                  unsigned long long* total_bytes);
}
