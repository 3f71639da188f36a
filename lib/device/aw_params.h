/* arnoldweb portable device core: what the host passes to every kernel.
 *
 * This header is included by the device core (all three dialects) and by the
 * host (lib/src), so both agree on the layout of the two parameter buffers,
 * the feature bits and the counter slots. Plain macros only.
 */
#ifndef AW_PARAMS_H
#define AW_PARAMS_H

/* ---------------------------------------------------------------- features
 * One bit per optional effect. The OpenCL and CUDA kernels are compiled with
 * -DAW_FEATURES=<mask>, so an effect that is not asked for is not in the code. */
#define AW_F_VELOCITY_MAP 0x1u    /* bin averaged velocities on the sphere */
#define AW_F_ENERGY 0x2u          /* track |E(t) - E(0)| at every sample */
#define AW_F_ENERGY_LIMIT 0x4u    /* flag trajectories above a threshold */
#define AW_F_INITIAL_STATES 0x8u  /* write initial states */
#define AW_F_FINAL_STATES 0x10u   /* write final states */
#define AW_F_TEST_INJECT 0x20u    /* test hook: poison one trajectory */
#define AW_F_ALL 0x3fu

/* ------------------------------------------------ initial distributions */
#define AW_INITIAL_SHELL 0 /* X uniform on the torus, direction uniform */

/* -------------------------------------------------- real parameters (rp) */
#define AW_MAX_STAGES 16
#define AW_P_ENERGY 0            /* E */
#define AW_P_ENERGY_LIMIT 1      /* flag when |dE| exceeds this */
#define AW_P_INJECT_VALUE 2      /* test hook: value added to p_x (NaN, Inf) */
#define AW_P_KICK_MERGED 3       /* (b_last + b_0) h, for back-to-back steps */
#define AW_P_DRIFT 4             /* a_i h / 2pi (turns per unit momentum), i = 0..16 */
#define AW_P_KICK (AW_P_DRIFT + AW_MAX_STAGES + 1) /* b_i h, i = 0..16 */
#define AW_P_COUNT (AW_P_KICK + AW_MAX_STAGES + 1)

/* ----------------------------------------------- integer parameters (ip) */
#define AW_I_SEED 0              /* Philox key */
#define AW_I_STEPS_PER_SEGMENT 1 /* steps between two samples */
#define AW_I_SEGMENTS 2          /* samples per averaging window */
#define AW_I_WINDOWS 3           /* averaging windows per trajectory */
#define AW_I_NSIDE 4             /* HEALPix resolution of the velocity map */
#define AW_I_MAX_ATTEMPTS 5      /* rejection-sampling bound for initial states */
#define AW_I_STAGES 6            /* force evaluations per step */
#define AW_I_KICK_FIRST 7        /* 1: kick-drift-kick with merged kicks; 0: drift first */
#define AW_I_INJECT_INDEX 8      /* test hook: the trajectory to poison */
#define AW_I_COUNT 9

/* ----------------------------------------------------- counters (per chunk)
 * 32-bit atomic counters the kernels increment; the host folds them into
 * 64-bit totals after every chunk. */
#define AW_C_BINNED 0          /* trajectories binned in every window */
#define AW_C_FLAG_NONFINITE 1  /* a coordinate became NaN or Inf */
#define AW_C_FLAG_ENERGY 2     /* |dE| above observe.max_energy_error */
#define AW_C_FLAG_INITIAL 3    /* no accessible initial state found */
#define AW_C_FLAG_COUNT 3      /* number of flag reasons */
#define AW_C_EHIST 4           /* log2 histogram of max |dE| per trajectory */
#define AW_EHIST_BINS_PER_OCTAVE 4
#define AW_EHIST_MIN_EXP (-64) /* first bin: |dE| < 2^-64 (and exact zero) */
#define AW_EHIST_MAX_EXP 16    /* last bin: |dE| >= 2^16 */
#define AW_EHIST_BINS ((AW_EHIST_MAX_EXP - AW_EHIST_MIN_EXP) * AW_EHIST_BINS_PER_OCTAVE + 2)
#define AW_C_COUNT (AW_C_EHIST + AW_EHIST_BINS)

/* ------------------------------------------------------- state records
 * Per trajectory, when states are asked for: 6 reals (u_x, u_y, u_z in turns,
 * wrapped; p_x, p_y, p_z) and 4 integers (winding x, y, z; status). */
#define AW_STATE_REALS 6
#define AW_STATE_INTS 4
#define AW_STATUS_OK 0
#define AW_STATUS_NONFINITE 1
#define AW_STATUS_ENERGY 2
#define AW_STATUS_INITIAL 3

/* Energy statistics: every work-group writes (max, sum) of max|dE| over its
 * binned trajectories; the host reduces the groups in index order. */
#define AW_GROUP_STATS 2

#endif /* AW_PARAMS_H */
