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
/* open runs (docs/scenes.md, "Open runs"): a launch may start trajectories
 * from states given in their records (ensemble.initial = "file") and stop
 * them at a time slice, leaving in their records all it needs to go on */
#define AW_F_CARRY 0x4000u
/* frequency analysis (NAFF) over two windows, and action samples for
 * diffusion (docs/frequencies.md) */
#define AW_F_FREQUENCIES 0x8000u
#define AW_F_DIFFUSION 0x10000u
/* the sampled states of chosen trajectories (observe.trajectories) */
#define AW_F_TRAJECTORIES 0x20000u
#define AW_F_ALL 0x3ffffu
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

/* ------------------------------------------------------- records
 * What a trajectory writes for the host: each per-trajectory output of the
 * host's output table (lib/src/plan/output_table.cpp) owns a slot and its
 * columns in the trajectory's record of reals and record of integers; the
 * host lays the columns out (aw_iparams.rec_col_r, rec_col_i) for the
 * outputs a plan asks for, and a kernel writes only those. */
#define AW_OUT_INITIAL_STATE 0 /* AW_STATE_REALS reals */
#define AW_OUT_FINAL_STATE 1   /* AW_STATE_REALS reals, AW_STATE_INTS integers */
#define AW_OUT_INDICATORS 2    /* AW_IND_REALS reals */
#define AW_OUT_CARRY 3         /* AW_CARRY_REALS reals, AW_CARRY_INTS integers: in and out */
#define AW_OUT_FREQUENCIES 4   /* AW_FREQ_REALS reals (effects/aw_fx_frequencies.h) */
#define AW_OUT_ACTIONS 5       /* 3 (K + 1) reals, 1 integer (effects/aw_fx_diffusion.h) */
#define AW_OUT_TRAJECTORIES 6  /* picked: AW_PICK_REALS reals, AW_PICK_INTS integers per sample (effects/aw_fx_trajectories.h) */
#define AW_FREQ_REALS 7
/* A frequency pass over a window's samples is shared by a team of
 * AW_NAFF_TEAM members (aw_naff.h): member t takes samples t, t + T, ...;
 * a window holds its samples padded with zeros to a multiple of the team. */
#define AW_NAFF_TEAM 32
#define AW_NAFF_PADDED(n) ((((n) + AW_NAFF_TEAM - 1) / AW_NAFF_TEAM) * AW_NAFF_TEAM)
/* ... and stored in groups of AW_NAFF_GROUP consecutive samples (64 bytes in
 * double: what a GPU's memory delivers at once; aw_naff.h, "teams"). */
#define AW_NAFF_GROUP 4
/* The frequencies' work memory per trajectory (series buffer) for windows of
 * n samples: both windows' samples (padded), the mean rates, a flag, and one
 * real unused so that every trajectory's series starts 32 bytes apart
 * (effects/aw_fx_frequencies.h). */
#define AW_FREQ_SERIES_REALS(n) (12 * AW_NAFF_PADDED(n) + 8)
/* The series buffer is allocated in blocks of this many trajectories (the
 * kernels store every lane of a group; every lane width divides it). */
#define AW_SERIES_BLOCK 32
#define AW_OUT_SLOTS 8

/* Picked records (observe.trajectories): a record per sample of each picked
 * trajectory (at most AW_MAX_PICKS, ip->pick_ids), not per trajectory: they
 * lie in the histogram buffer after the maps and the zoom, from word
 * ip->pick_base on, each value in two 32-bit words (a real's bits in the
 * kernel's precision, low word first; an integer's 64 bits), written once by
 * the trajectory's work-item and folded, summed and checkpointed with the
 * counts (only the trajectory's own launch writes a nonzero word: the sums
 * are its bits). Record (k, q) of pick k, sample q: u_x u_y u_z (turns,
 * wrapped) p_x p_y p_z E(t) - E(0) | winding x y z. */
#define AW_MAX_PICKS 1024
#define AW_PICK_REALS 7
#define AW_PICK_INTS 3

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

/* The chaos indicators of a trajectory (NaN for a flagged one): FLI, mean
 * MEGNO <Y>, the Lyapunov exponent from MEGNO's slope (1/T), the finite-time
 * Lyapunov exponent (1/T). */
#define AW_IND_REALS 4
#define AW_IND_FLI 0
#define AW_IND_MEGNO 1
#define AW_IND_MEGNO_LYAPUNOV 2
#define AW_IND_LYAPUNOV 3

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

#endif /* AW_PARAMS_H */
