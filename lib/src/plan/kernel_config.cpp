// arnoldweb: what a kernel is compiled for, as compiler options (plan.hpp).
#include <sstream>

#include "arnoldweb/plan.hpp"

namespace arnoldweb {

std::string KernelConfig::defines() const {
  std::ostringstream o;
  o << "-DAW_FEATURES=" << features << "u -DAW_STAGES=" << stages << " -DAW_KICK_FIRST=" << (kick_first ? 1 : 0)
    << " -DAW_GRADIENT=" << (gradient ? 1 : 0)
    << " -DAW_INITIAL=" << initial << " -DAW_MODEL=" << model;
  if (precision == Precision::Float) o << " -DAW_FLOAT";
  if (math == MathMode::Native) o << " -DAW_NATIVE_MATH";
  return o.str();
}

bool KernelConfig::operator==(const KernelConfig& o) const {
  return precision == o.precision && math == o.math && features == o.features && stages == o.stages &&
         kick_first == o.kick_first && gradient == o.gradient && initial == o.initial && model == o.model &&
         model_source == o.model_source;
}

}  // namespace arnoldweb
