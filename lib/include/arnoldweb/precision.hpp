// arnoldweb: the arithmetic a run computes in (integrator.precision,
// integrator.math; docs/scenes.md).
#pragma once

namespace arnoldweb {

enum class Precision { Double, Float };
enum class MathMode { Portable, Native };

const char* to_string(Precision p);
const char* to_string(MathMode m);

}  // namespace arnoldweb
