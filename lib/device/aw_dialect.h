/* arnoldweb portable device core: the dialect prelude.
 *
 * Every file in lib/device/ is valid C++17, OpenCL C 1.2 and CUDA C++ at once.
 * This header is the only place that knows which of the three it is compiled as.
 * It defines qualifiers, the scalar type `real`, the lane type `lreal`
 * (a vector of AW_LANES reals in OpenCL, a scalar elsewhere) and the handful of
 * operations the core may use: + - * / sqrt, explicit fma, and select.
 *
 * Build-time switches (set with -D by the host or by the C++ backend):
 *   AW_FLOAT        compute in float instead of double
 *   AW_NATIVE_MATH  use the vendor's sin/cos instead of the portable polynomials
 *   AW_LANES        trajectories per work-item (OpenCL only: 1, 2, 4, 8, 16)
 */
#ifndef AW_DIALECT_H
#define AW_DIALECT_H

#if defined(__OPENCL_VERSION__)
/* ------------------------------------------------------------ OpenCL C 1.2 */
#define AW_OPENCL 1
#pragma OPENCL FP_CONTRACT OFF
#ifndef AW_FLOAT
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif
#if defined(AW_OPENCL_ALWAYS_INLINE)
/* CPU devices (PoCL): every device function inlined, as the cpu backend's compiler does */
#define AW_FN static inline __attribute__((always_inline))
#else
#define AW_FN static inline
#endif
#define AW_GLOBAL __global
#define AW_CONSTANT __constant
typedef uint aw_u32;
typedef ulong aw_u64;
typedef long aw_i64;

#elif defined(__CUDACC__)
/* ------------------------------------------------------------- CUDA C++ */
#define AW_CUDA 1
#if defined(__CUDACC_RTC__)
/* NVRTC has no C library headers; Random123 needs these names. */
typedef unsigned char uint8_t;
typedef unsigned int uint32_t;
typedef unsigned long long uint64_t;
#define UINT64_C(x) x##ULL
#define R123_USE_SSE 0
#define R123_FORCE_INLINE(decl) decl
#define R123_USE_PHILOX_64BIT 0
#else
#include <stdint.h>
#endif
#define AW_FN static __device__ __forceinline__
#define AW_GLOBAL
#define AW_CONSTANT const
typedef unsigned int aw_u32;
typedef unsigned long long aw_u64;
typedef long long aw_i64;

#else
/* ------------------------------------------------------------ host C++17 */
#define AW_CPP 1
#include <cmath>
#include <cstdint>
#include <cstring>
#if defined(__FMA__) || defined(__AVX512F__)
#include <immintrin.h>
#endif
#if defined(__GNUC__)
#define AW_FN static inline __attribute__((always_inline))
#else
#define AW_FN static inline
#endif
#define AW_GLOBAL
#define AW_CONSTANT const
typedef std::uint32_t aw_u32;
typedef std::uint64_t aw_u64;
typedef std::int64_t aw_i64;
#endif

/* AW_UNROLL_STAGES: the stage loops of the stepper (aw_stepper.h) unrolled in
 * full on CUDA (the default since 2026-11-28; -DAW_CUDA_UNROLL_STAGES=0, an
 * NVRTC option, keeps the loop): the same operations in the same order, so the
 * same bits; what it saves is the per-stage re-materialisation of the sincos
 * constants and loads of the coefficients (bench/gpu/sass_count.py: Figure 3
 * (a) 953 -> 758 instructions a step; H200 2.37e10 -> 2.70e10 trajectory-steps/s,
 * docs/performance.md). Nothing elsewhere. */
#if defined(AW_CUDA) && (!defined(AW_CUDA_UNROLL_STAGES) || AW_CUDA_UNROLL_STAGES)
#define AW_UNROLL_STAGES _Pragma("unroll")
#else
#define AW_UNROLL_STAGES
#endif

/* ------------------------------------------------------------ precision */
#ifdef AW_FLOAT
typedef float real;
#define AW_R(x) x##f
#else
typedef double real;
#define AW_R(x) x
#endif

/* ------------------------------------------------------------ lanes */
#ifndef AW_LANES
#define AW_LANES 1
#endif
#if AW_LANES != 1 && !defined(AW_OPENCL) && !(defined(AW_CPP) && defined(__GNUC__))
#error "AW_LANES > 1 needs explicit vector types: OpenCL C, or GCC/Clang vector extensions in C++"
#endif

#define AW_CAT_(a, b) a##b
#define AW_CAT(a, b) AW_CAT_(a, b)

#if AW_LANES == 1
typedef real lreal; /* one trajectory per work-item */
typedef aw_i64 lint;
/* select(a, b, c): c ? b : a, as OpenCL's select */
#define AW_SELECT(a, b, c) ((c) ? (b) : (a))
#define AW_LOAD_LANES(arr) ((arr)[0])
#define AW_STORE_LANES(v, arr) ((arr)[0] = (v))
#define AW_LANE_TO_INT(x) ((lint)(x))
#define AW_INT_TO_LANE(x) ((lreal)(x))
#define AW_ALL(c) (c)
#define AW_STORE_ILANES(v, arr) ((arr)[0] = (v))
#define AW_LOAD_ILANES(arr) ((arr)[0])
#elif defined(AW_CPP)
/* C++ with GCC/Clang vector extensions: + - * / and comparisons are
 * element-wise, `c ? b : a` selects per element, scalars broadcast. */
typedef real lreal __attribute__((vector_size(sizeof(real) * AW_LANES)));
typedef aw_i64 lint __attribute__((vector_size(8 * AW_LANES)));
#define AW_SELECT(a, b, c) ((c) ? (b) : (a))
#define AW_LOAD_LANES(arr) aw_load_lanes(arr)
#define AW_STORE_LANES(v, arr) std::memcpy((arr), &(v), sizeof(lreal))
#define AW_STORE_ILANES(v, arr) std::memcpy((arr), &(v), sizeof(lint))
#define AW_LOAD_ILANES(arr) aw_load_ilanes(arr)
#define AW_LANE_TO_INT(x) __builtin_convertvector((x), lint)
#define AW_INT_TO_LANE(x) __builtin_convertvector((x), lreal)
#define AW_ALL(c) aw_all_lanes(c)
#else
#ifdef AW_FLOAT
typedef AW_CAT(float, AW_LANES) lreal;
#else
typedef AW_CAT(double, AW_LANES) lreal;
#endif
typedef AW_CAT(long, AW_LANES) lint;
#define AW_SELECT(a, b, c) select((a), (b), (c))
#define AW_LOAD_LANES(arr) AW_CAT(vload, AW_LANES)(0, (arr))
#define AW_STORE_LANES(v, arr) AW_CAT(vstore, AW_LANES)((v), 0, (arr))
#define AW_LANE_TO_INT(x) AW_CAT(convert_long, AW_LANES)(x)
#ifdef AW_FLOAT
#define AW_INT_TO_LANE(x) AW_CAT(convert_float, AW_LANES)(x)
#else
#define AW_INT_TO_LANE(x) AW_CAT(convert_double, AW_LANES)(x)
#endif
#define AW_ALL(c) all(c)
#define AW_STORE_ILANES(v, arr) AW_CAT(vstore, AW_LANES)((v), 0, (arr))
#define AW_LOAD_ILANES(arr) AW_CAT(vload, AW_LANES)(0, (arr))
#endif
/* a scalar broadcast to every lane (OpenCL's builtins do not mix the two) */
#if defined(AW_CPP) && AW_LANES > 1
#define AW_LSPLAT(x) ((lreal){} + (x))
#define AW_ISPLAT(x) ((lint){} + (x))
#else
#define AW_LSPLAT(x) ((lreal)(x))
#define AW_ISPLAT(x) ((lint)(x))
#endif

/* ------------------------------------------------------------ arithmetic
 * Only explicit fma: FP contraction is off in every dialect, so a*b+c is two
 * roundings everywhere and fma(a,b,c) is one rounding everywhere. */
#if defined(AW_CPP) && AW_LANES > 1
/* Scalar and lane overloads. The lane versions apply the correctly rounded
 * scalar operation to each element; the compiler vectorises the loops. */
AW_FN real aw_fma(real a, real b, real c) { return std::fma(a, b, c); }
AW_FN real aw_sqrt(real x) { return std::sqrt(x); }
AW_FN real aw_fabs(real x) { return std::fabs(x); }
AW_FN bool aw_isfinite(real x) { return std::isfinite(x); }
/* Element-wise fma with one rounding. Compilers do not reliably vectorise a
 * loop of scalar fma calls over vector elements, so use the vector FMA
 * instructions where the target has them (same IEEE result per element). */
AW_FN lreal aw_fma(lreal a, lreal b, lreal c) {
  lreal r = c; /* every element is overwritten below */
#if defined(__AVX512F__) && !defined(AW_FLOAT) && AW_LANES == 8
  r = (lreal)_mm512_fmadd_pd((__m512d)a, (__m512d)b, (__m512d)c);
#elif defined(__AVX512F__) && defined(AW_FLOAT) && AW_LANES == 16
  r = (lreal)_mm512_fmadd_ps((__m512)a, (__m512)b, (__m512)c);
#elif defined(__FMA__) && ((!defined(AW_FLOAT) && AW_LANES % 4 == 0) || (defined(AW_FLOAT) && AW_LANES % 8 == 0))
  for (int i = 0; i < (int)(sizeof(lreal) / 32); ++i) {
#ifdef AW_FLOAT
    __m256 x, y, z;
    std::memcpy(&x, (const char*)&a + 32 * i, 32);
    std::memcpy(&y, (const char*)&b + 32 * i, 32);
    std::memcpy(&z, (const char*)&c + 32 * i, 32);
    __m256 o = _mm256_fmadd_ps(x, y, z);
#else
    __m256d x, y, z;
    std::memcpy(&x, (const char*)&a + 32 * i, 32);
    std::memcpy(&y, (const char*)&b + 32 * i, 32);
    std::memcpy(&z, (const char*)&c + 32 * i, 32);
    __m256d o = _mm256_fmadd_pd(x, y, z);
#endif
    std::memcpy((char*)&r + 32 * i, &o, 32);
  }
#else
  for (int i = 0; i < AW_LANES; ++i) r[i] = std::fma(a[i], b[i], c[i]);
#endif
  return r;
}
AW_FN lreal aw_sqrt(lreal x) {
  lreal r = x; /* every element is overwritten below */
  for (int i = 0; i < AW_LANES; ++i) r[i] = std::sqrt(x[i]);
  return r;
}
AW_FN lreal aw_fabs(lreal x) { return (x < 0) ? -x : x; }
/* x - x is 0 for finite x and NaN for NaN and +-Inf (no fast-math here) */
AW_FN auto aw_isfinite(lreal x) { return (x - x) == 0; }
template <class M>
AW_FN bool aw_all_lanes(M m) {
  for (int i = 0; i < AW_LANES; ++i)
    if (!m[i]) return false;
  return true;
}
AW_FN lreal aw_load_lanes(const real* a) {
  lreal v;
  std::memcpy(&v, a, sizeof v);
  return v;
}
AW_FN lint aw_load_ilanes(const aw_i64* a) {
  lint v;
  std::memcpy(&v, a, sizeof v);
  return v;
}
#define AW_FMA(a, b, c) aw_fma((a), (b), (c))
#define AW_SQRT(x) aw_sqrt(x)
#define AW_FABS(x) aw_fabs(x)
#define AW_ISFINITE(x) aw_isfinite(x)
#define AW_FREXP(x, e) std::frexp((x), (e))
#elif defined(AW_CPP)
#define AW_FMA(a, b, c) std::fma((a), (b), (c))
#define AW_SQRT(x) std::sqrt(x)
#define AW_FABS(x) std::fabs(x)
#define AW_ISFINITE(x) std::isfinite(x)
#define AW_FREXP(x, e) std::frexp((x), (e))
#elif defined(AW_CUDA) && defined(AW_FLOAT)
#define AW_FMA(a, b, c) fmaf((a), (b), (c))
#define AW_SQRT(x) sqrtf(x)
#define AW_FABS(x) fabsf(x)
#define AW_ISFINITE(x) isfinite(x)
#define AW_FREXP(x, e) frexpf((x), (e))
#else
#define AW_FMA(a, b, c) fma((a), (b), (c))
#define AW_SQRT(x) sqrt(x)
#define AW_FABS(x) fabs(x)
#define AW_ISFINITE(x) isfinite(x)
#define AW_FREXP(x, e) frexp((x), (e))
#endif

/* rint() without a library call: adding and subtracting 1.5 * 2^52 (2^23 in
 * float) rounds to the nearest integer, ties to even, for |x| < 2^51 (2^22).
 * Only two IEEE additions, so identical everywhere and vectorisable. */
#ifdef AW_FLOAT
#define AW_ROUND_MAGIC AW_R(12582912.0)
#else
#define AW_ROUND_MAGIC 6755399441055744.0
#endif
#define AW_RINT_SMALL(x) (((x) + AW_ROUND_MAGIC) - AW_ROUND_MAGIC)

/* ------------------------------------------------------------ bit patterns
 * `lbits`: an unsigned integer lane of the width of `real`. AW_AS_BITS and
 * AW_FROM_BITS reinterpret (never convert), so integer work on them is exact
 * and leaves the floating-point pipes free (on GPUs the FP64 pipe is the
 * bottleneck). The sum t = x + AW_ROUND_MAGIC of AW_RINT_SMALL holds
 * rint(x) in its low bits, two's complement: AW_MAGIC_TO_INT(t) reads it as
 * an integer lane (lint) without a float-to-integer conversion. */
#ifdef AW_FLOAT
typedef aw_u32 aw_bits_e; /* one element of lbits */
#else
typedef aw_u64 aw_bits_e;
#endif
#if defined(AW_OPENCL)
#define AW_BITS_C(x) ((aw_bits_e)(x##UL))
#else
#define AW_BITS_C(x) ((aw_bits_e)(x##ULL))
#endif
#ifdef AW_FLOAT
#define AW_ROUND_MAGIC_BITS AW_BITS_C(0x4B400000)
#define AW_BIT1_TO_SIGN 30 /* shift that moves bit 1 to the sign bit */
#else
#define AW_ROUND_MAGIC_BITS AW_BITS_C(0x4338000000000000)
#define AW_BIT1_TO_SIGN 62
#endif

#if AW_LANES == 1 && defined(AW_OPENCL)
#ifdef AW_FLOAT
typedef uint lbits;
#define AW_AS_BITS(x) as_uint(x)
#define AW_FROM_BITS(b) as_float(b)
#define AW_MAGIC_TO_INT(t) ((lint)as_int(AW_AS_BITS(t) - AW_ROUND_MAGIC_BITS))
#else
typedef ulong lbits;
#define AW_AS_BITS(x) as_ulong(x)
#define AW_FROM_BITS(b) as_double(b)
#define AW_MAGIC_TO_INT(t) as_long(AW_AS_BITS(t) - AW_ROUND_MAGIC_BITS)
#endif
#elif AW_LANES == 1 && defined(AW_CUDA)
#ifdef AW_FLOAT
typedef unsigned int lbits;
#define AW_AS_BITS(x) ((lbits)__float_as_int(x))
#define AW_FROM_BITS(b) __int_as_float((int)(b))
#define AW_MAGIC_TO_INT(t) ((lint)(int)(AW_AS_BITS(t) - AW_ROUND_MAGIC_BITS))
#else
typedef unsigned long long lbits;
#define AW_AS_BITS(x) ((lbits)__double_as_longlong(x))
#define AW_FROM_BITS(b) __longlong_as_double((long long)(b))
#define AW_MAGIC_TO_INT(t) ((lint)(AW_AS_BITS(t) - AW_ROUND_MAGIC_BITS))
#endif
#elif AW_LANES == 1
#ifdef AW_FLOAT
typedef std::uint32_t lbits;
#define AW_MAGIC_TO_INT(t) ((lint)(std::int32_t)(AW_AS_BITS(t) - AW_ROUND_MAGIC_BITS))
#else
typedef std::uint64_t lbits;
#define AW_MAGIC_TO_INT(t) ((lint)(AW_AS_BITS(t) - AW_ROUND_MAGIC_BITS))
#endif
AW_FN lbits aw_as_bits(real x) {
  lbits b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}
AW_FN real aw_from_bits(lbits b) {
  real x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}
#define AW_AS_BITS(x) aw_as_bits(x)
#define AW_FROM_BITS(b) aw_from_bits(b)
#elif defined(AW_CPP)
#ifdef AW_FLOAT
typedef std::uint32_t lbits __attribute__((vector_size(4 * AW_LANES)));
typedef std::int32_t aw_lsbits __attribute__((vector_size(4 * AW_LANES)));
#define AW_MAGIC_TO_INT(t) __builtin_convertvector((aw_lsbits)(AW_AS_BITS(t) - AW_ROUND_MAGIC_BITS), lint)
#else
typedef std::uint64_t lbits __attribute__((vector_size(8 * AW_LANES)));
#define AW_MAGIC_TO_INT(t) ((lint)(AW_AS_BITS(t) - AW_ROUND_MAGIC_BITS))
#endif
#define AW_AS_BITS(x) ((lbits)(x))
#define AW_FROM_BITS(b) ((lreal)(b))
#else /* OpenCL vectors */
#ifdef AW_FLOAT
typedef AW_CAT(uint, AW_LANES) lbits;
#define AW_AS_BITS(x) AW_CAT(as_uint, AW_LANES)(x)
#define AW_FROM_BITS(b) AW_CAT(as_float, AW_LANES)(b)
#define AW_MAGIC_TO_INT(t) \
  AW_CAT(convert_long, AW_LANES)(AW_CAT(as_int, AW_LANES)(AW_AS_BITS(t) - AW_ROUND_MAGIC_BITS))
#else
typedef AW_CAT(ulong, AW_LANES) lbits;
#define AW_AS_BITS(x) AW_CAT(as_ulong, AW_LANES)(x)
#define AW_FROM_BITS(b) AW_CAT(as_double, AW_LANES)(b)
#define AW_MAGIC_TO_INT(t) AW_CAT(as_long, AW_LANES)(AW_AS_BITS(t) - AW_ROUND_MAGIC_BITS)
#endif
#endif

/* q = a / b with the remainder *r = a - q b. Written out, not as a % b beside
 * a / b: LLVM's DivRemPairs pass turns that pair into `freeze` instructions,
 * which Oclgrind 21.10's --uninitialized plugin stops at (tests/oclgrind). */
AW_FN aw_i64 aw_divrem(aw_i64 a, aw_i64 b, aw_i64* r) {
  const aw_i64 q = a / b;
  *r = a - q * b;
  return q;
}

/* Two consecutive reals p[0], p[1] of global memory, p at an even index of
 * an aligned buffer (a sample's re and im): one 16-byte access on a GPU (8 in
 * float), two elsewhere. */
#if defined(AW_CUDA) || defined(__OPENCL_VERSION__)
#ifdef AW_FLOAT
typedef float2 aw_real_pair;
#else
typedef double2 aw_real_pair;
#endif
#define AW_LOAD_PAIR(p, a, b)                                             \
  do {                                                                    \
    const aw_real_pair pair_ = *(AW_GLOBAL const aw_real_pair*)(p);       \
    (a) = pair_.x;                                                        \
    (b) = pair_.y;                                                        \
  } while (0)
#define AW_STORE_PAIR(p, a, b)                 \
  do {                                         \
    aw_real_pair pair_;                        \
    pair_.x = (a);                             \
    pair_.y = (b);                             \
    *(AW_GLOBAL aw_real_pair*)(p) = pair_;     \
  } while (0)
#else
#define AW_LOAD_PAIR(p, a, b) \
  do {                        \
    (a) = (p)[0];             \
    (b) = (p)[1];             \
  } while (0)
#define AW_STORE_PAIR(p, a, b) \
  do {                         \
    (p)[0] = (a);              \
    (p)[1] = (b);              \
  } while (0)
#endif

/* (q, r) = (k / d, k % d) for a k that goes up one at a time (the segments of
 * a run), kept without a division per step: a 64-bit division is a software
 * routine of tens of instructions on a GPU, and the segment loop comes round
 * every few steps when frequencies are sampled. */
typedef struct {
  aw_i64 q, r;
} aw_count;

AW_FN aw_count aw_count_at(aw_i64 k, aw_i64 d) {
  aw_count c;
  c.q = aw_divrem(k, d, &c.r);
  return c;
}

/* k -> k + 1 */
AW_FN void aw_count_next(aw_count* c, aw_i64 d) {
  c->r = c->r + 1;
  if (c->r == d) {
    c->r = 0;
    c->q = c->q + 1;
  }
}

#endif /* AW_DIALECT_H */
