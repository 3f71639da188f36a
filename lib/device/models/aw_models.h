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
 *   aw_model_kinetic_diag(rp, a)   the diagonal a_i of d^2T/dP^2
 * The kinetic form is T = sum a_i p_i^2/2 + b_i p_i (a_i >= 0; models/aw_kinetic.h
 * has the speed for it).
 * Its parameters are rp->model[...] (filled by its entry in the host's model
 * table, lib/src/physics/models.cpp). The kernels are compiled with
 * -DAW_MODEL=<id>; the line below that includes the model's header is the
 * device side of its table entry.
 */
#ifndef AW_MODELS_H
#define AW_MODELS_H

#define AW_MODEL_SEIBERT2011 0
#define AW_MODEL_FGL 1
#define AW_MODEL_FOURIER 2

#ifndef AW_MODEL
#define AW_MODEL AW_MODEL_SEIBERT2011
#endif

#if AW_MODEL == AW_MODEL_SEIBERT2011
#include "models/aw_seibert2011.h"
#elif AW_MODEL == AW_MODEL_FGL
#include "models/aw_fgl.h"
#elif AW_MODEL == AW_MODEL_FOURIER
#include "models/aw_fourier.h"
#elif AW_MODEL == 1000
/* an expression model (model.kind = "expression"): the header emitted from the
 * scene's potential (lib/src/physics/expression/), given to the OpenCL and
 * CUDA compilers and to the host C++ compiler (the cpu backend's run-time
 * variant, cpu_runtime_kernel.cpp) under this name. Not an AW_MODEL_ line: the
 * cpu backend's ahead-of-time variants are generated from those lines only. */
#include "models/aw_expression.h"
#else
#error "unknown AW_MODEL"
#endif

#endif /* AW_MODELS_H */
