/* arnoldweb expression models: the kinetic part, T = sum_i a_i p_i^2 / 2 + b_i p_i.
 *
 * The emitted header of an expression model (models/aw_expression.h, from
 * lib/src/physics/expression/emitter.cpp) includes this for the kinetic half
 * of the model interface (models/aw_models.h): the general form of
 * kinetic/aw_kinetic_ab.h, a and b in rp->model[0..5] as in the fourier model;
 * the potential's parameters follow from [6].
 */
#ifndef AW_EXPRESSION_KINETIC_H
#define AW_EXPRESSION_KINETIC_H

#include "kinetic/aw_kinetic_ab.h"

#define AW_EXPRESSION_FIRST_PARAMETER 6 /* rp->model index of the potential's first parameter */

#endif /* AW_EXPRESSION_KINETIC_H */
