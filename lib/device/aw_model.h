/* arnoldweb portable device core: the model, H = T(P) + V(X) on the 3-torus,
 * and the quantities every effect uses (the force into the state, the energy).
 *
 * A model is one header models/aw_<name>.h that defines, with a fixed order
 * of operations (the same bits on every backend):
 *   aw_model_force(s, rp)          F = -grad V at s->u (turns) into s->f
 *   aw_model_force_hessian(s, rp, hess)  the same F, and the Hessian of V
 *                                  (xx, yy, zz, xy, xz, yz) from the same sin/cos
 *   aw_model_potential(ux, uy, uz, rp)   V
 *   aw_model_kinetic(px, py, pz, rp)     T
 *   aw_model_drift(s, d, rp)       u += d dT/dP (d in turns per unit of dT/dP)
 *   aw_model_speed(ke, dx, dy, dz, rp, &ok)  s > 0 with T(s n) = ke for the
 *                                  unit direction n (initial states)
 *   aw_model_kinetic_diag(rp, a)   the diagonal a_i of d^2T/dP^2
 * The kinetic form is T = sum a_i p_i^2/2 + b_i p_i (a_i >= 0): kinetic/ holds
 * whole kinetic halves (|P|^2/2: kinetic/aw_kinetic_standard.h; a and b in
 * rp->model[0..5]: kinetic/aw_kinetic_ab.h) and the speed of the general form
 * (kinetic/aw_kinetic.h).
 * Its parameters are rp->model[...], filled from the scene as its descriptor
 * declares (lib/src/physics/models/<name>.cpp). OpenCL and CUDA kernels are
 * compiled with -DAW_MODEL=<id>; models/aw_models.h, generated from the list of
 * headers (cmake/ArnoldwebModels.cmake), includes the one asked for. What is
 * compiled ahead for one model (the cpu backend's kernel variants, the host's
 * copy of a model) names its header as AW_MODEL_HEADER instead, and so depends
 * on no other model's header nor on the list: adding a model rebuilds none of it.
 */

#ifndef AW_MODEL_H
#define AW_MODEL_H

#ifdef AW_MODEL_HEADER
#include AW_MODEL_HEADER
#else
#include "models/aw_models.h"
#endif

AW_FN void aw_force(aw_lstate* s, AW_CONSTANT aw_rparams* rp) { aw_model_force(s, rp); }

AW_FN lreal aw_energy(const aw_lstate* s, AW_CONSTANT aw_rparams* rp) {
  return aw_model_kinetic(s->px, s->py, s->pz, rp) + aw_model_potential(s->ux, s->uy, s->uz, rp);
}

#endif /* AW_MODEL_H */
