/* arnoldweb portable device core: the model, H = T(P) + V(X) on the 3-torus.
 *
 * A model is one header in this folder that defines, with a fixed order of
 * operations (the same bits on every backend):
 *   aw_model_force(s, rp)          F = -grad V at s->u (turns) into s->f
 *   aw_model_force_hessian(s, rp, hess)  the same F, and the Hessian of V
 *                                  (xx, yy, zz, xy, xz, yz) from the same sin/cos
 *   aw_model_potential(ux, uy, uz, rp)   V
 *   aw_model_kinetic(px, py, pz, rp)     T
 *   aw_model_drift(s, d, rp)       u += d dT/dP (d in turns per unit of dT/dP)
 *   aw_model_speed(ke, dx, dy, dz, rp, &ok)  s > 0 with T(s n) = ke for the
 *                                  unit direction n (initial states)
 * Its parameters are rp->model[...] (filled by its entry in the host's model
 * table, lib/src/physics/models.cpp). The kernels are compiled with
 * -DAW_MODEL=<id>; the line below that includes the model's header is the
 * device side of its table entry.
 */
#ifndef AW_MODELS_H
#define AW_MODELS_H

#define AW_MODEL_SEIBERT2011 0

#ifndef AW_MODEL
#define AW_MODEL AW_MODEL_SEIBERT2011
#endif

#if AW_MODEL == AW_MODEL_SEIBERT2011
#include "models/aw_seibert2011.h"
#else
#error "unknown AW_MODEL"
#endif

#endif /* AW_MODELS_H */
