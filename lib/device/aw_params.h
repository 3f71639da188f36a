/* arnoldweb portable device core: what the host and every kernel agree on:
 * the feature bits, the initial kinds, the sizes of the parameter blocks
 * (aw_param_blocks.h), the counter slots and the state records. Plain macros:
 * the host includes this header as it is.
 *
 * A new effect adds a bit and its counters here, and its fields in
 * aw_param_blocks.h.
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
/* chaos indicators (docs/indicators.md): the tangent vector through the
 * derivative of the same step, and its observers, each only when asked */
#define AW_F_TANGENT 0x400u       /* tangent dynamics (any indicator sets it) */
#define AW_F_FLI 0x800u           /* fast Lyapunov indicator: max_t log |w| */
#define AW_F_MEGNO 0x1000u        /* mean MEGNO <Y> and the Lyapunov exponent from its slope */
#define AW_F_LYAPUNOV 0x2000u     /* finite-time maximal Lyapunov exponent log |w(t)| / t */
#define AW_F_ALL 0x3fffu

/* ------------------------------------------------ initial distributions
 * X is uniform on the accessible part of the torus in every case. */
#define AW_INITIAL_SHELL 0    /* direction of P uniform on the sphere */
#define AW_INITIAL_CAP 1      /* direction uniform in a spherical cap */
#define AW_INITIAL_BOX 2      /* direction uniform in a longitude/latitude box */
#define AW_INITIAL_GAUSSIAN 3 /* p_x, p_y Gaussian, p_z from the energy, random sign */
#define AW_INITIAL_GRID 4     /* trajectory i = point i of a grid (aw_grid.h), X fixed */
#define AW_GRID_HEALPIX 0     /* momentum directions: HEALPix pixel centres, RING order */
#define AW_GRID_LONLAT 1      /* momentum directions: n_lon x n_lat cell centres of a lon/lat box */
#define AW_GRID_PLANE 2       /* two momenta on an n1 x n2 grid, the third fixed */

/* ------------------------------------------------------ parameter blocks
 * The structs the host fills and every kernel reads: aw_param_blocks.h. */
#define AW_MAX_STAGES 16
#define AW_MAX_MODEL_PARAMS 192 /* fourier: 7 + 5 x 32 harmonics (models/aw_fourier.h) */
#define AW_MAX_FRAMES 64

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

/* ------------------------------------------------------- indicator records
 * Per trajectory, when an indicator is asked for (NaN for a flagged one):
 * FLI, mean MEGNO <Y>, the Lyapunov exponent from MEGNO's slope (1/T), the
 * finite-time Lyapunov exponent (1/T). */
#define AW_IND_REALS 4
#define AW_IND_FLI 0
#define AW_IND_MEGNO 1
#define AW_IND_MEGNO_LYAPUNOV 2
#define AW_IND_LYAPUNOV 3

/* Energy statistics: every work-group writes (max, sum) of max|dE| over its
 * binned trajectories; the host reduces the groups in index order. */
#define AW_GROUP_STATS 2

#endif /* AW_PARAMS_H */
