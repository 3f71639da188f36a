/* arnoldweb portable device core: the general kinetic form of the models
 *
 *   T(P) = sum_i a_i p_i^2 / 2 + sum_i b_i p_i,   a_i >= 0,
 *   dT/dp_i = a_i p_i + b_i (the drift: u_i += d (a_i p_i + b_i), d in turns
 *   per unit of dT/dP),
 *
 * and the speed s > 0 with T(s n) = ke along a unit direction n (initial
 * states): with A = sum a_i n_i^2 and B = sum b_i n_i, A s^2 / 2 + B s = ke.
 * The roots, written without cancellation (t = B + sign(B) sqrt(B^2 + 2 A ke)):
 *   2 ke / t   and   -t / A.
 * The state is put on the first crossing of the energy surface along the ray:
 * the smaller positive root. ok = 0 where there is none (B^2 + 2 A ke < 0, or
 * both roots <= 0, or A = 0 and the second root would be needed).
 * Used by every model whose kinetic form is not |P|^2/2 (that one keeps its
 * own, faster speed in models/aw_seibert2011.h).
 */
#ifndef AW_KINETIC_H
#define AW_KINETIC_H

AW_FN lreal aw_kinetic_speed(lreal ke, lreal A, lreal B, lreal* ok) {
  const lreal zero = AW_LSPLAT(AW_R(0.0)), one = AW_LSPLAT(AW_R(1.0));
  lreal disc = AW_FMA(B, B, AW_R(2.0) * (A * ke));
  lreal reach = AW_SELECT(zero, one, disc >= AW_R(0.0));
  lreal sq = AW_SQRT(AW_SELECT(zero, disc, disc >= AW_R(0.0)));
  lreal t = AW_SELECT(B - sq, B + sq, B >= AW_R(0.0)); /* |t| = |B| + sq */
  lreal t_safe = AW_SELECT(t, one, t == AW_R(0.0));
  lreal a_safe = AW_SELECT(A, one, A == AW_R(0.0));
  lreal near = (AW_R(2.0) * ke) / t_safe; /* the root nearer to 0 */
  lreal far = -t / a_safe;
  lreal near_ok = AW_SELECT(zero, one, (near > AW_R(0.0)) & (t != AW_R(0.0)));
  lreal far_ok = AW_SELECT(zero, one, (far > AW_R(0.0)) & (A > AW_R(0.0)));
  lreal s = AW_SELECT(far, near, near_ok != AW_R(0.0));
  *ok = AW_SELECT(zero, reach, (near_ok != AW_R(0.0)) | (far_ok != AW_R(0.0)));
  return AW_SELECT(zero, s, *ok != AW_R(0.0));
}

#endif /* AW_KINETIC_H */
