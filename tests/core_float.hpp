// The device core compiled as C++ in single precision, inside namespace core_f.
#pragma once
#include <Random123/philox.h>

#include <cmath>
#include <cstdint>

#define AW_FLOAT 1
namespace core_f {
#include "aw_ensemble.h"
}  // namespace core_f
