/* arnoldweb OpenCL entry points: thin kernels over lib/device.
 * Compiled at run time with the plan's options (KernelConfig::defines()):
 * -DAW_FEATURES=<mask> -DAW_STAGES=<n> -DAW_KICK_FIRST=<0|1> -DAW_GRADIENT=<0|1> -DAW_INITIAL=<k>
 * -DAW_MODEL=<id> -DAW_LANES=<n> [-DAW_FLOAT] [-DAW_NATIVE_MATH]. */
#define AW_LOCAL __local
#define AW_BARRIER() barrier(CLK_LOCAL_MEM_FENCE)
#include "aw_ensemble.h"
#include "aw_reduce.h"

/* The buffers' parameters come from their list (AW_BUFFERS, aw_params.h). */
#define AW_KERNEL_PARAM(NAME, space, type, name) , space type* name
__kernel void aw_ensemble(ulong chunk_first, ulong chunk_end, long seg_first, long seg_end AW_BUFFERS(AW_KERNEL_PARAM),
                          __local real* scratch) {
  const aw_config cfg = {AW_FEATURES, AW_STAGES, AW_KICK_FIRST, AW_INITIAL, AW_GRADIENT};
  aw_lanes l = {chunk_first + (ulong)get_global_id(0) * AW_LANES, chunk_end, chunk_first};
  real emax = 0, esum = 0;
  if (l.first < chunk_end) {
    aw_outputs out = {hist, counters, rec_r, rec_i, series};
    aw_ensemble_item(cfg, l, seg_first, seg_end, rp, ip, out, &emax, &esum);
  }
  aw_group_reduce(scratch, (int)get_local_id(0), (int)get_local_size(0), get_group_id(0), emax,
                  esum, group_stats);
}

/* The frequency analysis of a launch's trajectories, after aw_ensemble over
 * all their segments (effects/aw_fx_frequencies.h). Compiled only where the
 * plan asks for frequencies. On a GPU (-DAW_NAFF_TEAM_PARALLEL=1, one lane)
 * a work-group of AW_NAFF_TEAM work-items analyses one trajectory, its passes
 * shared (aw_naff.h, "teams"); elsewhere a work-item analyses its lanes. */
#if AW_FEATURES & AW_F_FREQUENCIES
#if AW_NAFF_TEAM_PARALLEL
__kernel __attribute__((reqd_work_group_size(AW_NAFF_TEAM, 1, 1))) void aw_frequencies(
    ulong chunk_first, ulong chunk_end AW_BUFFERS(AW_KERNEL_PARAM), __local real* scratch /* 6 AW_NAFF_TEAM reals */) {
  /* the scratch an argument: a __local array declared in the kernel was one
   * array for the work-groups PoCL's pthread device ran at once (NaN
   * frequencies that changed from run to run) */
  const aw_naff_team team = {(int)get_local_id(0), scratch};
  const ulong rec = get_group_id(0);
  if (chunk_first + rec < chunk_end) {
    aw_outputs out = {hist, counters, rec_r, rec_i, series};
    aw_freq_analyse_record(rec, team, rp, ip, out);
  }
}
#else
__kernel void aw_frequencies(ulong chunk_first, ulong chunk_end AW_BUFFERS(AW_KERNEL_PARAM)) {
  aw_lanes l = {chunk_first + (ulong)get_global_id(0) * AW_LANES, chunk_end, chunk_first};
  if (l.first < chunk_end) {
    aw_outputs out = {hist, counters, rec_r, rec_i, series};
    aw_freq_analyse(l, rp, ip, out);
  }
}
#endif
#endif

/* total[i] += part[i]; part[i] = 0: 32-bit chunk counts into 64-bit totals. */
__kernel void aw_fold(__global ulong* total, __global uint* part, ulong n) {
  size_t i = get_global_id(0);
  if (i < n) {
    total[i] += part[i];
    part[i] = 0;
  }
}
