/* arnoldweb portable device core: work-group reduction of energy statistics.
 *
 * Each work-item contributes (max, sum) of max|dE| over its binned lanes; the
 * group's pair goes to stats[2 * group]. The tree has a fixed shape for a given
 * group size, so a device always produces the same sums. Used by the OpenCL
 * and CUDA entry points; the C++ backend reduces its blocks itself.
 * The dialect file defines AW_LOCAL (address space of the scratch array) and
 * AW_BARRIER() (a work-group barrier on local memory).
 */
#ifndef AW_REDUCE_H
#define AW_REDUCE_H

#include "aw_dialect.h"
#include "aw_params.h"

AW_FN void aw_group_reduce(AW_LOCAL real* scratch, int lid, int lsz, aw_u64 group, real emax,
                           real esum, AW_GLOBAL real* stats) {
  scratch[2 * lid] = emax;
  scratch[2 * lid + 1] = esum;
  AW_BARRIER();
  for (int off = lsz / 2; off > 0; off /= 2) {
    if (lid < off) {
      real m = scratch[2 * (lid + off)];
      scratch[2 * lid] = (m > scratch[2 * lid]) ? m : scratch[2 * lid];
      scratch[2 * lid + 1] = scratch[2 * lid + 1] + scratch[2 * (lid + off) + 1];
    }
    AW_BARRIER();
  }
  if (lid == 0) {
    stats[AW_GROUP_STATS * group] = scratch[0];
    stats[AW_GROUP_STATS * group + 1] = scratch[1];
  }
}

#endif /* AW_REDUCE_H */
