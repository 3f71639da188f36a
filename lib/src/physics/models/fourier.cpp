// arnoldweb model "fourier": harmonics given in the scene (lib/device/models/aw_fourier.h).
#include <cmath>

#include "physics/model_table.hpp"

namespace arnoldweb::detail {

AW_MODEL_ID(2);  // for good (model_descriptor.hpp)
namespace {

constexpr int kMaxHarmonics = 32;  // AW_FOURIER_MAX (lib/device/models/aw_fourier.h)
constexpr int kFirstHarmonic = 7;  // AW_FOURIER_FIRST: rp.model[6] holds their number
constexpr int kMaxWaveNumber = 64;
constexpr double kTwoPi = 6.283185307179586476925;

// k integers from -64 to 64, not all 0.
std::string check_harmonics(const std::vector<double>& v) {
  for (std::size_t j = 0; j + 5 <= v.size(); j += 5) {
    const std::string where = " (harmonic " + std::to_string(j / 5 + 1) + ")";
    for (std::size_t i = 0; i < 3; ++i)
      if (v[j + i] != std::floor(v[j + i]) || std::fabs(v[j + i]) > kMaxWaveNumber)
        return where + ": k must be integers from -" + std::to_string(kMaxWaveNumber) + " to " +
               std::to_string(kMaxWaveNumber);
    if (v[j] == 0 && v[j + 1] == 0 && v[j + 2] == 0) return where + ": k = 0 is a constant";
  }
  return "";
}

// rp.model[6] = n, then per harmonic k_x, k_y, k_z, c, phi in turns.
void place_harmonics(const std::vector<double>& v, double* model) {
  model[6] = static_cast<double>(v.size() / 5);
  for (std::size_t j = 0; j + 5 <= v.size(); j += 5) {
    double* m = model + kFirstHarmonic + j;
    m[0] = v[j], m[1] = v[j + 1], m[2] = v[j + 2], m[3] = v[j + 3];
    m[4] = v[j + 4] / kTwoPi;
  }
}

}  // namespace

ModelDescriptor describe_fourier() {
  ModelDescriptor m;
  m.title = "A truncated Fourier potential with harmonics given in the scene";
  m.formula = "H = sum_i a_i p_i^2/2 + sum_i b_i p_i + sum_k c_k cos(k.X + phi_k)";
  m.notes = "model.harmonics = [[kx, ky, kz, c, phi], ...] (1 to " + std::to_string(kMaxHarmonics) +
            ", k integers, phi in radians); model.kinetic_a = [a_x, a_y, a_z] (>= 0), "
            "model.kinetic_b = [b_x, b_y, b_z]";
  ModelParameter h;
  h.key = "model.harmonics";
  h.type = "array of [kx, ky, kz, c, phi]";
  h.allowed = "1 to " + std::to_string(kMaxHarmonics) + " harmonics, k integers in [-" +
              std::to_string(kMaxWaveNumber) + ", " + std::to_string(kMaxWaveNumber) + "], not all 0";
  h.must = "an array of 1 to " + std::to_string(kMaxHarmonics) + " harmonics [kx, ky, kz, c, phi] (k integers from -" +
           std::to_string(kMaxWaveNumber) + " to " + std::to_string(kMaxWaveNumber) + ", not all 0; c, phi finite)";
  h.help = "V = sum c cos(kx x + ky y + kz z + phi), phi in radians. The default is the paper's potential "
           "cos x cos y (1 + cos 2z) in six harmonics.";
  h.width = 5;
  h.max_rows = kMaxHarmonics;
  h.integer_columns = 3;
  h.default_value = {1, 1, 0, 0.5, 0, 1, -1, 0, 0.5, 0, 1, 1, 2, 0.25, 0,
                     1, 1, -2, 0.25, 0, 1, -1, 2, 0.25, 0, 1, -1, -2, 0.25, 0};
  h.check = check_harmonics;
  h.place = place_harmonics;
  m.parameters = {h, kinetic_a_parameter(), kinetic_b_parameter()};
  m.kinetic = kinetic_in_slots;
  m.v_range = [](const RealParams& rp) {
    double sum = 0;
    for (int j = 0; j < static_cast<int>(rp.model[6]); ++j) sum += std::fabs(rp.model[kFirstHarmonic + 5 * j + 3]);
    return std::array<double, 2>{-sum, sum};
  };
  m.hessian_bound = [](const RealParams& rp) {  // sum |c_k| |k|^2
    double sum = 0;
    for (int j = 0; j < static_cast<int>(rp.model[6]); ++j) {
      const double* k = &rp.model[kFirstHarmonic + 5 * j];
      sum += std::fabs(k[3]) * (k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
    }
    return sum;
  };
  m.wave_vectors = [](const RealParams& rp) {
    std::vector<std::array<int, 3>> k;
    for (int j = 0; j < static_cast<int>(rp.model[6]); ++j) {
      const double* w = &rp.model[kFirstHarmonic + 5 * j];
      k.push_back({static_cast<int>(w[0]), static_cast<int>(w[1]), static_cast<int>(w[2])});
    }
    return k;
  };
  return m;
}

}  // namespace arnoldweb::detail
