/* arnoldweb portable device core: counter-based random numbers.
 *
 * Random123's Philox4x32-10, keyed by the scene's seed and countered by
 * (trajectory index, attempt, draw): every trajectory has its own stream, the
 * same whatever chunk, device or work-item computes it.
 * Uniforms use exact fixed-point conversions (no rounding anywhere):
 * double: 53 random bits * 2^-53, float: 24 random bits * 2^-24, in [0, 1).
 */
#ifndef AW_RNG_H
#define AW_RNG_H

#include "aw_dialect.h"

#ifndef R123_STATIC_INLINE
#if defined(AW_CUDA)
#define R123_STATIC_INLINE static __inline__
#else
#define R123_STATIC_INLINE static inline
#endif
#endif
#include <Random123/philox.h>

/* Two uniforms in [0, 1) from one Philox block. */
AW_FN void aw_uniform2(aw_u64 seed, aw_u64 index, aw_u32 attempt, aw_u32 draw,
                       real* a, real* b) {
  philox4x32_ctr_t c = {{(aw_u32)index, (aw_u32)(index >> 32), attempt, draw}};
  philox4x32_key_t k = {{(aw_u32)seed, (aw_u32)(seed >> 32)}};
  philox4x32_ctr_t r = philox4x32(c, k);
#ifdef AW_FLOAT
  *a = (real)(r.v[0] >> 8) * AW_R(5.9604644775390625e-08); /* 2^-24 */
  *b = (real)(r.v[2] >> 8) * AW_R(5.9604644775390625e-08);
#else
  *a = (real)((((aw_u64)r.v[0]) << 21) | (aw_u64)(r.v[1] >> 11)) * 1.1102230246251565e-16; /* 2^-53 */
  *b = (real)((((aw_u64)r.v[2]) << 21) | (aw_u64)(r.v[3] >> 11)) * 1.1102230246251565e-16;
#endif
}

#endif /* AW_RNG_H */
