// The device core compiled as C++ in single precision, inside namespace core_f.
#pragma once
#include "aw_cpp_std.h"

#define AW_FLOAT 1
namespace core_f {
#include "aw_ensemble.h"
}  // namespace core_f
