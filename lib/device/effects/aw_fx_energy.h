/* arnoldweb effects "energy_error" and "max_energy_error": |E(t) - E(0)| at
 * every sample; its maximum per trajectory goes into a log2 histogram and the
 * work-group statistics; above observe.max_energy_error a trajectory is
 * flagged at the end of the window. */
#ifndef AW_FX_ENERGY_H
#define AW_FX_ENERGY_H

#include "aw_model.h"
#include "effects/aw_fx_common.h"

/* Bin of the log2 histogram of an energy error e >= 0 (or NaN: last bin). */
AW_FN int aw_energy_bin(real e) {
  if (!(e < AW_R(65536.0))) return AW_EHIST_BINS - 1; /* >= 2^16, Inf, NaN */
  if (e < AW_R(5.421010862427522e-20)) return 0;      /* < 2^-64, zero */
  int ex;
  real m = AW_FREXP(e, &ex); /* e = m 2^ex, m in [1/2, 1) */
  int quarter = (int)((m - AW_R(0.5)) * AW_R(8.0));
  return 1 + (ex - 1 - AW_EHIST_MIN_EXP) * AW_EHIST_BINS_PER_OCTAVE + quarter;
}

/* At a sample: the error, its running maximum, and whether it is over the
 * limit (kept until the end of the window). */
AW_FN void aw_energy_sample(const aw_lstate* s, AW_CONSTANT aw_rparams* rp, lreal e0, lreal* emax, lreal* over,
                            int limit) {
  lreal de = AW_FABS(aw_energy(s, rp) - e0);
  *emax = AW_SELECT(*emax, de, de > *emax);
  if (limit) *over = AW_SELECT(*over, AW_LSPLAT(AW_R(1.0)), de > rp->energy_limit);
}

#endif /* AW_FX_ENERGY_H */
