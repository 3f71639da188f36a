// The device core compiled as C++ in double precision, inside namespace
// core_d (one per test translation unit; see core_float.hpp for float).
#pragma once
#include "aw_cpp_std.h"

namespace core_d {
#include "aw_ensemble.h"
}  // namespace core_d
