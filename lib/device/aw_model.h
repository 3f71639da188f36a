/* arnoldweb portable device core: the model and the quantities every effect
 * uses (the force into the state, the energy). The model itself is one header
 * of models/ (models/aw_models.h). */
#ifndef AW_MODEL_H
#define AW_MODEL_H

#include "models/aw_models.h"

AW_FN void aw_force(aw_lstate* s, AW_CONSTANT aw_rparams* rp) { aw_model_force(s, rp); }

AW_FN lreal aw_energy(const aw_lstate* s, AW_CONSTANT aw_rparams* rp) {
  return aw_model_kinetic(s->px, s->py, s->pz, rp) + aw_model_potential(s->ux, s->uy, s->uz, rp);
}

#endif /* AW_MODEL_H */
