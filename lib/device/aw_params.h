/* arnoldweb portable device core: what the host and every kernel agree on:
 * the feature bits, the initial kinds, the sizes of the parameter blocks
 * (aw_param_blocks.h), the counter slots and the state records. Plain macros:
 * the host includes this header as it is.
 *
 * A new effect declares its bits, its record slot, its sizes and its
 * parameters in its own header (effects/aw_fx_<name>.h, its declarations
 * block), gathered here by the generated effects/aw_effect_declarations.h.
 */
#ifndef AW_PARAMS_H
#define AW_PARAMS_H

/* ---------------------------------------------------------------- features
 * One bit per optional effect. The OpenCL and CUDA kernels are compiled with
 * -DAW_FEATURES=<mask>, so an effect that is not asked for is not in the code.
 * Each effect's bits are in its header's declarations block
 * (effects/aw_fx_<name>.h); the generated effects/aw_effect_declarations.h,
 * included at the end, gathers them and defines AW_F_ALL. */
/* the effects that read E(0) of a trajectory (aw_fx_core.e0) */
#define AW_F_WITH_E0 (AW_F_ENERGY | AW_F_TRAJECTORIES)

/* ------------------------------------------------ initial distributions
 * X is uniform on the accessible part of the torus in every case. */
#define AW_INITIAL_SHELL 0    /* direction of P uniform on the sphere */
#define AW_INITIAL_CAP 1      /* direction uniform in a spherical cap */
#define AW_INITIAL_BOX 2      /* direction uniform in a longitude/latitude box */
#define AW_INITIAL_GAUSSIAN 3 /* p_x, p_y Gaussian, p_z from the energy, random sign */
#define AW_INITIAL_GRID 4     /* trajectory i = point i of a grid (aw_grid.h), X fixed */
#define AW_INITIAL_FILE 5     /* trajectory i = the state in its carry record (AW_OUT_CARRY) */
#define AW_GRID_HEALPIX 0     /* momentum directions: HEALPix pixel centres, RING order */
#define AW_GRID_LONLAT 1      /* momentum directions: n_lon x n_lat cell centres of a lon/lat box */
#define AW_GRID_PLANE 2       /* two momenta on an n1 x n2 grid, the third fixed */

/* ------------------------------------------------------ parameter blocks
 * The structs the host fills and every kernel reads: aw_param_blocks.h. */
#define AW_MAX_STAGES 16
#define AW_MAX_MODEL_PARAMS 192 /* fourier: 7 + 5 x 32 harmonics (models/aw_fourier.h) */

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

/* ------------------------------------------------------- records
 * What a trajectory writes for the host: each per-trajectory output of the
 * host's output table (lib/src/plan/output_table.cpp) owns a slot and its
 * columns in the trajectory's record of reals and record of integers; the
 * host lays the columns out (aw_iparams.rec_col_r, rec_col_i) for the
 * outputs a plan asks for, and a kernel writes only those. Each output's
 * slot AW_OUT_<NAME> (below AW_OUT_SLOTS) and its sizes are in its effect
 * header's declarations block (effects/aw_fx_<name>.h). */
#define AW_OUT_SLOTS 8
/* The series buffer is allocated in blocks of this many trajectories (the
 * kernels store every lane of a group; every lane width divides it). */
#define AW_SERIES_BLOCK 32

/* A state: 6 reals (u_x, u_y, u_z in turns, wrapped; p_x, p_y, p_z) and 4
 * integers (winding x, y, z; status). */
#define AW_STATE_REALS 6
#define AW_STATE_INTS 4
#define AW_STATUS_OK 0
#define AW_STATUS_NONFINITE 1
#define AW_STATUS_ENERGY 2
#define AW_STATUS_INITIAL 3
#define AW_STATUS_LEFT_REGION 4

/* The carry of a trajectory (AW_F_CARRY): its state and every effect's state
 * between two launches, read where a launch does not start the trajectory
 * (a later time slice, or ensemble.initial = "file": the state only) and
 * written where it does not finish it.
 *   reals: u_x u_y u_z (turns) p_x p_y p_z | E(0) max|dE| over-limit inside
 *          | the window's start u_x u_y u_z | the tangent vector
 *          q_x q_y q_z p_x p_y p_z and its observers log2w max_n2 s1 ysum mean_y cov prev_n2
 *   ints:  winding x y z, status | the window's start windings x y z | tangent steps */
#define AW_CARRY_REALS 26
#define AW_CARRY_INTS 8
#define AW_CARRY_ENERGY 6   /* E(0), then the energy effect's max|dE| and over-limit */
#define AW_CARRY_CONFINE 9  /* the confine effect's inside */
#define AW_CARRY_WINDOW 10
#define AW_CARRY_TANGENT 13

/* ------------------------------------------------------- kernel buffers
 * The ensemble kernel's buffers in argument order, written once: the OpenCL
 * and CUDA entry points declare their parameters from this list, the host's
 * EnsembleBuffers is an array indexed by AW_BUF_<NAME>, and every backend
 * passes them in this order. Whatever outputs a scene asks for, they go into
 * these arenas (the output table says what lies where):
 *   rp, ip       the parameter blocks (aw_param_blocks.h)
 *   hist         32-bit counts of the chunk: F velocity maps, then the zoom
 *   counters     AW_C_COUNT 32-bit counters of the chunk
 *   rec_r, rec_i per trajectory of the chunk, ip->rec_reals reals and
 *                ip->rec_ints integers (the records)
 *   group_stats  per work-group, AW_GROUP_STATS reals
 *   series       per trajectory of the chunk, ip->series_reals reals of work
 *                memory (the frequency samples), in blocks of
 *                AW_SERIES_BLOCK trajectories (effects/aw_fx_frequencies.h)
 * X(NAME, address space, element type, parameter name) */
#define AW_BUFFERS(X)                      \
  X(RPARAMS, AW_CONSTANT, aw_rparams, rp)  \
  X(IPARAMS, AW_CONSTANT, aw_iparams, ip)  \
  X(HIST, AW_GLOBAL, aw_u32, hist)         \
  X(COUNTERS, AW_GLOBAL, aw_u32, counters) \
  X(RECORDS_R, AW_GLOBAL, real, rec_r)     \
  X(RECORDS_I, AW_GLOBAL, aw_i64, rec_i)   \
  X(GROUP_STATS, AW_GLOBAL, real, group_stats) \
  X(SERIES, AW_GLOBAL, real, series)
#define AW_BUF_ENUM(NAME, space, type, name) AW_BUF_##NAME,
enum { AW_BUFFERS(AW_BUF_ENUM) AW_BUF_COUNT };
#undef AW_BUF_ENUM

/* Energy statistics: every work-group writes (max, sum) of max|dE| over its
 * binned trajectories; the host reduces the groups in index order. */
#define AW_GROUP_STATS 2

/* ------------------------------------------------------- the effects
 * Their bits, slots, sizes and parameters, from their headers (generated by
 * cmake/ArnoldwebEffects.cmake). */
#include "effects/aw_effect_declarations.h"

#endif /* AW_PARAMS_H */
