#include "params/kernel_params.hpp"

#include <cstring>

namespace arnoldweb::detail {

std::vector<unsigned char> KernelParams::real_bytes(Precision precision) const {
  const std::size_t n = real_count();
  const double* d = reinterpret_cast<const double*>(&reals);
  std::vector<unsigned char> out;
  if (precision == Precision::Float) {
    std::vector<float> f(d, d + n);  // each element rounded to nearest, as the kernels would
    out.resize(n * sizeof(float));
    std::memcpy(out.data(), f.data(), out.size());
  } else {
    out.resize(n * sizeof(double));
    std::memcpy(out.data(), d, out.size());
  }
  return out;
}

}  // namespace arnoldweb::detail
