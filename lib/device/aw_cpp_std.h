/* arnoldweb portable device core: what the C++ dialect needs from the standard
 * library and Random123. A C++ file that compiles the core inside a namespace
 * of its own (to hold several precisions in one program) includes this first,
 * outside that namespace. Not used by OpenCL or CUDA. */
#ifndef AW_CPP_STD_H
#define AW_CPP_STD_H
#include <Random123/philox.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#if defined(__FMA__) || defined(__AVX512F__)
#include <immintrin.h>
#endif
#endif /* AW_CPP_STD_H */
