/* arnoldweb CUDA entry points: thin kernels over lib/device.
 * Compiled at run time by NVRTC with the same defines as the OpenCL kernels:
 * -DAW_FEATURES=<mask> -DAW_STAGES=<n> -DAW_KICK_FIRST=<0|1> -DAW_GRADIENT=<0|1> -DAW_INITIAL=<k>
 * -DAW_MODEL=<id> [-DAW_FLOAT] [-DAW_NATIVE_MATH]. */
#define AW_LOCAL
#define AW_BARRIER() __syncthreads()
/* the frequency analysis: a warp per trajectory (aw_naff.h, "teams") */
#define AW_NAFF_TEAM_PARALLEL 1
#ifndef AW_NAFF_BATCH
#define AW_NAFF_BATCH 4 /* samples loaded ahead by a member (aw_naff.h): 4 fit aw_frequencies' registers */
#endif
#include "aw_dialect.h" /* real */
#include "aw_params.h" /* AW_F_* */
#if AW_FEATURES & AW_F_FREQUENCIES
/* The window's weights chi_p(m) of windows up to this many samples, made by
 * each block once (aw_freq_window_fill) for its samplers: one function
 * computes them, at the same m, as the sampler would (aw_freq_sample), so the
 * bits are the same; a sample reads its weight instead of a division, a sine
 * and a cosine. */
#define AW_FREQ_WINDOW_TABLE 1024
__shared__ real aw_freq_window_table[AW_FREQ_WINDOW_TABLE];
#endif
#include "aw_ensemble.h"
#include "aw_reduce.h"

/* Occupancy. The kernel is bound by FP64 latency at the 4 resident blocks of
 * 128 threads that ~100 registers allow per SM (ncu on an H200: FP64 pipe 74%
 * busy, 16 warps/SM). Asking for AW_CUDA_MIN_BLOCKS blocks makes ptxas fit
 * the registers (64 for 8: 32 warps/SM); what spills is live only across energy samples
 * and windows, never inside the step loop (bench/NOTES.md). Blocks larger
 * than AW_CUDA_MAX_BLOCK are refused by the launch; the backend clamps. */
#ifndef AW_CUDA_MAX_BLOCK
#define AW_CUDA_MAX_BLOCK 128
#endif
#ifndef AW_CUDA_MIN_BLOCKS
#ifdef AW_FLOAT
#define AW_CUDA_MIN_BLOCKS 8 /* H200 sweep 4/6/8: 4.07/3.99/4.17e10 and 3.99/3.95/4.12e10 */
#else
#define AW_CUDA_MIN_BLOCKS 4 /* H200 sweep 4/6/8: 1.915/1.889/1.911e10 and 1.944/1.896/1.901e10 */
#endif
#endif
/* The buffers' parameters come from their list (AW_BUFFERS, aw_params.h). */
#define AW_KERNEL_PARAM(NAME, space, type, name) , space type* name
extern "C" __global__ void __launch_bounds__(AW_CUDA_MAX_BLOCK, AW_CUDA_MIN_BLOCKS)
    aw_ensemble(aw_u64 chunk_first, aw_u64 chunk_end, aw_i64 seg_first, aw_i64 seg_end AW_BUFFERS(AW_KERNEL_PARAM)) {
  extern __shared__ unsigned char aw_shared[];
  real* scratch = (real*)aw_shared;
  const aw_config cfg = {AW_FEATURES, AW_STAGES, AW_KICK_FIRST, AW_INITIAL, AW_GRADIENT};
  aw_lanes l = {chunk_first + ((aw_u64)blockIdx.x * blockDim.x + threadIdx.x), chunk_end, chunk_first};
  real emax = 0, esum = 0;
#if AW_FEATURES & AW_F_FREQUENCIES
  aw_freq_window_fill(ip, (int)threadIdx.x, (int)blockDim.x);
  __syncthreads();
#endif
  if (l.first < chunk_end) {
    aw_outputs out = {hist, counters, rec_r, rec_i, series};
    aw_ensemble_item(cfg, l, seg_first, seg_end, rp, ip, out, &emax, &esum);
  }
  aw_group_reduce(scratch, (int)threadIdx.x, (int)blockDim.x, blockIdx.x, emax, esum, group_stats);
}

/* The frequency analysis of a launch's trajectories, after aw_ensemble over
 * all their segments (effects/aw_fx_frequencies.h). Compiled only where the
 * plan asks for frequencies. A warp analyses one trajectory, its passes
 * shared by its threads (aw_naff.h, "teams"; AW_NAFF_TEAM_PARALLEL = 1), in
 * blocks of 128 threads (kFreqBlock, cuda_compute_device.cpp). */
#if AW_FEATURES & AW_F_FREQUENCIES
/* Its passes wait on loads more than on arithmetic: six blocks of 128 per SM
 * (80 registers, samples loaded 4 ahead rather than 8: no spills) ran the
 * default scene's frequencies in 0.258 s against 0.263 s at five (96
 * registers); eight (64 registers) spilled and took 0.275 s (H200,
 * 2026-11-26). The same bits either way. */
#ifndef AW_FREQ_MIN_BLOCKS
#define AW_FREQ_MIN_BLOCKS 6
#endif
extern "C" __global__ void __launch_bounds__(128, AW_FREQ_MIN_BLOCKS)
    aw_frequencies(aw_u64 chunk_first, aw_u64 chunk_end AW_BUFFERS(AW_KERNEL_PARAM)) {
  const aw_naff_team team = {(int)(threadIdx.x % AW_NAFF_TEAM), 0};
  const aw_u64 rec = ((aw_u64)blockIdx.x * blockDim.x + threadIdx.x) / AW_NAFF_TEAM;
  if (chunk_first + rec < chunk_end) { /* whole warps */
    aw_outputs out = {hist, counters, rec_r, rec_i, series};
    aw_freq_analyse_record(rec, team, rp, ip, out);
  }
}
#endif

/* total[i] += part[i]; part[i] = 0: 32-bit chunk counts into 64-bit totals. */
extern "C" __global__ void aw_fold(aw_u64* total, aw_u32* part, aw_u64 n) {
  aw_u64 i = (aw_u64)blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) {
    total[i] += part[i];
    part[i] = 0;
  }
}
