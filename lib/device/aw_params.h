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
#define AW_F_ZOOM 0x40u           /* gnomonic high-resolution histogram of a region */
#define AW_F_CONFINE 0x80u        /* only trajectories that stay in a region count */
#define AW_F_FRAMES 0x100u        /* one velocity map per span of windows (time series) */
#define AW_F_REVERSE 0x200u       /* test of time reversibility: after the run, flip P,
                                     integrate as long again, flip P back (final states) */
#define AW_F_ALL 0x3ffu

/* ------------------------------------------------ initial distributions
 * X is uniform on the accessible part of the torus in every case. */
#define AW_INITIAL_SHELL 0    /* direction of P uniform on the sphere */
#define AW_INITIAL_CAP 1      /* direction uniform in a spherical cap */
#define AW_INITIAL_BOX 2      /* direction uniform in a longitude/latitude box */
#define AW_INITIAL_GAUSSIAN 3 /* p_x, p_y Gaussian, p_z from the energy, random sign */

/* -------------------------------------------------- real parameters (rp) */
#define AW_MAX_STAGES 16
#define AW_P_ENERGY 0            /* E */
#define AW_P_ENERGY_LIMIT 1      /* flag when |dE| exceeds this */
#define AW_P_INJECT_VALUE 2      /* test hook: value added to p_x (NaN, Inf) */
#define AW_P_KICK_MERGED 3       /* (b_last + b_0) h, for back-to-back steps */
#define AW_P_DRIFT 4             /* a_i h / 2pi (turns per unit momentum), i = 0..16 */
#define AW_P_KICK (AW_P_DRIFT + AW_MAX_STAGES + 1) /* b_i h, i = 0..16 */
/* Initial distribution (AW_P_INIT + ...):
 *   cap:      c (3), e1 (3), e2 (3): orthonormal frame with c the centre; 9: cos(radius)
 *   box:      0: first longitude (turns), 1: longitude width (turns),
 *             2: sin(first latitude), 3: sin(last latitude) - sin(first latitude)
 *   gaussian: 0, 1: mean p_x, p_y; 2, 3: sigma of p_x, p_y */
#define AW_P_INIT (AW_P_KICK + AW_MAX_STAGES + 1)
/* A square region in gnomonic projection about a direction (zoom, confinement):
 * c (3), e1 (3), e2 (3) orthonormal frame; 9: half-width w = tan(half-angle).
 * d is inside when d.c > 0 and |d.e1| <= w d.c and |d.e2| <= w d.c. */
#define AW_REGION_SIZE 10
#define AW_P_ZOOM (AW_P_INIT + AW_REGION_SIZE)
#define AW_P_CONFINE (AW_P_ZOOM + AW_REGION_SIZE)
#define AW_P_COUNT (AW_P_CONFINE + AW_REGION_SIZE)

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
#define AW_I_INITIAL 9           /* AW_INITIAL_* (the C++ backend reads it here) */
#define AW_I_ZOOM_RESOLUTION 10  /* zoom histogram: R x R bins */
#define AW_I_FRAMES 11           /* number of frames F (1 without AW_F_FRAMES) */
#define AW_MAX_FRAMES 64
#define AW_I_FRAME_BOUNDS 12     /* F + 1 window indices: frame k = windows [b_k, b_k+1) */
#define AW_I_COUNT (AW_I_FRAME_BOUNDS + AW_MAX_FRAMES + 1)

/* ------------------------------------------------------- histograms
 * One buffer of counts: F velocity maps of 12 nside^2 pixels (RING), frame
 * after frame, then the R x R zoom histogram (row y, column x). */

/* ----------------------------------------------------- counters (per chunk)
 * 32-bit atomic counters the kernels increment; the host folds them into
 * 64-bit totals after every chunk. */
#define AW_C_BINNED 0          /* trajectories binned in every window */
#define AW_C_FLAG_NONFINITE 1  /* a coordinate became NaN or Inf */
#define AW_C_FLAG_ENERGY 2     /* |dE| above observe.max_energy_error */
#define AW_C_FLAG_INITIAL 3    /* no accessible initial state found */
#define AW_C_FLAG_COUNT 3      /* number of flag reasons */
#define AW_C_LEFT_REGION 4     /* left the confinement region (not an error) */
#define AW_C_EHIST 5           /* log2 histogram of max |dE| per trajectory */
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
#define AW_STATUS_LEFT_REGION 4

/* Energy statistics: every work-group writes (max, sum) of max|dE| over its
 * binned trajectories; the host reduces the groups in index order. */
#define AW_GROUP_STATS 2

#endif /* AW_PARAMS_H */
