/* arnoldweb effects "velocity_map", "frames" and "zoom": at the end of every
 * averaging window, the direction of the averaged velocity (the displacement
 * over the window) is counted in the HEALPix map of the window's frame, and
 * in the R x R gnomonic zoom histogram when it falls inside its square. */
/* What the host reads too (plain macros, gathered by the generated
 * effects/aw_effect_declarations.h that aw_params.h includes). */
#ifndef AW_FX_BINNING_DECLARATIONS
#define AW_FX_BINNING_DECLARATIONS
#define AW_F_VELOCITY_MAP 0x1u /* bin averaged velocities on the sphere */
#define AW_F_ZOOM 0x40u        /* gnomonic high-resolution histogram of a region */
#define AW_F_FRAMES 0x100u     /* one velocity map per span of windows (time series) */
#define AW_MAX_FRAMES 64
#define AW_FX_BINNING_RPARAMS aw_region zoom;
#define AW_FX_BINNING_IPARAMS                                                                   \
  aw_i64 nside;           /* HEALPix resolution of the velocity map */                            \
  aw_i64 zoom_resolution; /* zoom histogram: R x R bins */                                        \
  aw_i64 frames;          /* number of frames F (1 without AW_F_FRAMES) */                        \
  aw_i64 frame_bounds[AW_MAX_FRAMES + 1]; /* frame k = windows [b_k, b_k+1) */
#endif

#if !defined(AW_EFFECT_DECLARATIONS_ONLY) && !defined(AW_FX_BINNING_H)
#define AW_FX_BINNING_H

#include "aw_healpix.h"
#include "effects/aw_fx_common.h"

AW_EFFECT_ORDER(90)

/* Bin of direction (x, y, z) in the R x R zoom histogram of region r, or -1. */
AW_FN aw_i64 aw_zoom_bin(AW_CONSTANT aw_region* r, aw_i64 res, real x, real y, real z) {
  real dc = AW_FMA(z, r->c[2], AW_FMA(y, r->c[1], x * r->c[0]));
  if (!(dc > AW_R(0.0))) return -1;
  real gx = AW_FMA(z, r->e1[2], AW_FMA(y, r->e1[1], x * r->e1[0])) / dc; /* tangent-plane coordinates */
  real gy = AW_FMA(z, r->e2[2], AW_FMA(y, r->e2[1], x * r->e2[0])) / dc;
  real w = r->half_width;
  if (!(AW_FABS(gx) < w) || !(AW_FABS(gy) < w)) return -1;
  real n = (real)res;
  aw_i64 ix = (aw_i64)((gx / w + AW_R(1.0)) * AW_R(0.5) * n);
  aw_i64 iy = (aw_i64)((gy / w + AW_R(1.0)) * AW_R(0.5) * n);
  if (ix >= res) ix = res - 1;
  if (iy >= res) iy = res - 1;
  return iy * res + ix;
}

/* Frame of window w: the k with b_k <= w < b_k+1, or -1. */
AW_FN int aw_frame_of(AW_CONSTANT aw_iparams* ip, aw_i64 w) {
  const int frames = (int)ip->frames;
  for (int k = 0; k < frames; ++k)
    if (w >= ip->frame_bounds[k] && w < ip->frame_bounds[k + 1]) return k;
  return -1;
}

/* Counts the displacement (dx, dy, dz) of one trajectory over a window of
 * frame `frame` (-1: none). A trajectory that did not move counts in pixel 0
 * of the map and nowhere in the zoom. */
AW_FN void aw_bin_window(aw_config cfg, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out,
                         int frame, real dx, real dy, real dz) {
  const aw_i64 nside = ip->nside;
  const aw_i64 npix = 12 * nside * nside;
  const int moved = !(dx == AW_R(0.0) && dy == AW_R(0.0) && dz == AW_R(0.0));
  if (AW_HAS(AW_F_VELOCITY_MAP) && frame >= 0) {
    aw_i64 pix = moved ? aw_vec2pix_ring(nside, dx, dy, dz) : 0;
    AW_ATOMIC_INC(&out.hist[(aw_u64)(frame * npix + pix)]);
  }
  if (AW_HAS(AW_F_ZOOM) && moved) {
    AW_GLOBAL aw_u32* zoom = out.hist + (aw_u64)(ip->frames * npix);
    aw_i64 bin = aw_zoom_bin(&rp->zoom, ip->zoom_resolution, dx, dy, dz);
    if (bin >= 0) AW_ATOMIC_INC(&zoom[bin]);
  }
}

/* At the end of window w: the displacements (dx, dy, dz) of the lanes that
 * are still fine after the window's flags, binned. */
AW_FN void aw_fx_binning_window_end(aw_config cfg, aw_fx_core* fx, aw_i64 w, const real* dx, const real* dy,
                                    const real* dz, aw_lanes l, AW_CONSTANT aw_rparams* rp,
                                    AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  const int frame = AW_HAS(AW_F_FRAMES) ? aw_frame_of(ip, w) : 0;
  for (int j = 0; j < AW_LANES; ++j)
    if (fx->status[j] == AW_STATUS_OK && AW_LANE_ACTIVE(l, j)) aw_bin_window(cfg, rp, ip, out, frame, dx[j], dy[j], dz[j]);
}

#endif /* AW_FX_BINNING_H */
