/* arnoldweb portable device core: the state of a lane of trajectories.
 *
 * Positions are carried in turns (u = x / 2pi), wrapped to [-1/2, 1/2] after
 * each step, with integer winding counts; the momentum; and the force at the
 * current position, cached so that back-to-back steps share one evaluation.
 */
#ifndef AW_STATE_H
#define AW_STATE_H

#include "aw_dialect.h"
#include "aw_param_blocks.h"

typedef struct {
  lreal ux, uy, uz;
  lint wx, wy, wz;
  lreal px, py, pz;
  lreal fx, fy, fz;
} aw_lstate;

#endif /* AW_STATE_H */
