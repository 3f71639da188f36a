/* arnoldweb portable device core: the parameter blocks the host fills and
 * every kernel reads (through a pointer to constant memory).
 *
 * Each block is a struct whose members are all of one type (aw_rparams:
 * real, aw_iparams: aw_i64), so its layout is an array of that type in every
 * dialect: the host fills the double block and converts it to float element
 * by element for float kernels. The host includes this header twice, with
 * `real` = double and float (lib/src/params/kernel_params.hpp, whose
 * static_asserts check the layouts). An effect's members are its header's
 * (AW_FX_<NAME>_RPARAMS, _IPARAMS), gathered by AW_EFFECTS_RPARAMS and
 * AW_EFFECTS_IPARAMS (effects/aw_effect_declarations.h).
 *
 * Needs `real`, `aw_i64` and `aw_u32` (aw_dialect.h, or the host's own).
 */
#ifndef AW_PARAM_BLOCKS_H
#define AW_PARAM_BLOCKS_H

#include "aw_params.h"

/* ---------------------------------------------------------- configuration
 * What a kernel is compiled for. OpenCL and CUDA build it from their -D
 * options (compile-time constants everywhere); the C++ backend passes the
 * plan's values at run time. */
typedef struct {
  aw_u32 features;  /* AW_F_* */
  int stages;       /* force evaluations per step */
  int kick_first;   /* 1: kick-drift-kick with merged kicks; 0: drift first */
  int initial;      /* AW_INITIAL_* */
  int gradient;     /* 1: the method's kicks carry force-gradient terms (aw_stepper.h) */
} aw_config;

/* ------------------------------------------------------ real parameters */
/* A square region in gnomonic projection about a direction (zoom,
 * confinement): c the centre, e1 east, e2 north (an orthonormal frame) and the
 * half-width w = tan(half-angle). d is inside when d.c > 0, |d.e1| <= w d.c
 * and |d.e2| <= w d.c. */
typedef struct {
  real c[3], e1[3], e2[3];
  real half_width;
} aw_region;

/* The non-uniform initial distributions (ensemble.initial). */
typedef struct {
  real c[3], e1[3], e2[3]; /* frame of the cap's centre */
  real cos_radius;
} aw_cap;
typedef struct {
  real lon0, lon_width;      /* turns */
  real sin_lat0, sin_lat_width;
} aw_box;
typedef struct {
  real mean_x, mean_y, sigma_x, sigma_y;
} aw_gaussian;

typedef struct {
  real energy;        /* E of every trajectory */
  real kick_merged;   /* (b_last + b_0) h, for back-to-back steps */
  real drift[AW_MAX_STAGES + 1]; /* a_i h / 2pi (turns per unit momentum) */
  real kick[AW_MAX_STAGES + 1];  /* b_i h */
  real gradient[AW_MAX_STAGES + 1]; /* g_i h^3: force-gradient methods only (aw_stepper.h) */
  real gradient_merged;             /* (g_last + g_0) h^3 */
  aw_cap cap;
  aw_box box;
  aw_gaussian gaussian;
  real model[AW_MAX_MODEL_PARAMS]; /* the model's own (models/aw_models.h) */
  /* grids of initial conditions (docs/indicators.md) */
  real grid_position[3]; /* the fixed position of grid initial conditions, turns */
  real grid_lo[2], grid_width[2]; /* plane: momentum ranges; lonlat: lon, lat ranges in turns */
  real grid_fixed;      /* plane: the third momentum */
  AW_EFFECTS_RPARAMS    /* each effect's (its header's AW_FX_<NAME>_RPARAMS) */
} aw_rparams;

/* --------------------------------------------------- integer parameters */
typedef struct {
  aw_i64 seed;              /* Philox key */
  aw_i64 steps_per_segment; /* steps between two samples */
  aw_i64 segments;          /* samples per averaging window */
  aw_i64 windows;           /* averaging windows per trajectory */
  aw_i64 max_attempts;      /* rejection-sampling bound for initial states */
  /* grids of initial conditions (AW_INITIAL_GRID, aw_grid.h) */
  aw_i64 grid_kind;         /* AW_GRID_* */
  aw_i64 grid_n[2];         /* healpix: nside, 0; lonlat: n_lon, n_lat; plane: n1, n2 */
  aw_i64 grid_axes[3];      /* plane: the two gridded momenta, then the fixed one */
  AW_EFFECTS_IPARAMS        /* each effect's (its header's AW_FX_<NAME>_IPARAMS) */
  /* per-trajectory work memory in the series buffer (AW_BUFFERS): series_reals
   * reals per trajectory, in blocks of AW_SERIES_BLOCK trajectories */
  aw_i64 series_reals;
  /* the records (aw_params.h): columns per trajectory, and where each slot's columns start */
  aw_i64 rec_reals, rec_ints;
  aw_i64 rec_col_r[AW_OUT_SLOTS], rec_col_i[AW_OUT_SLOTS];
  aw_i64 rec_width_r[AW_OUT_SLOTS], rec_width_i[AW_OUT_SLOTS];
} aw_iparams;

#endif /* AW_PARAM_BLOCKS_H */
