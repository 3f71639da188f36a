// arnoldweb: digests and statistics of a result.
#include "arnoldweb/result.hpp"

#include <xxhash.h>

#include <cmath>
#include <cstdio>

#include "aw_params.h"

namespace arnoldweb {
namespace {

std::string hex128(XXH128_hash_t h) {
  char buf[33];
  std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                static_cast<unsigned long long>(h.low64));
  return buf;
}

// Hash of several arrays in sequence (their bytes, little-endian as stored).
class Digest {
 public:
  Digest() : state_(XXH3_createState()) { XXH3_128bits_reset(state_); }
  ~Digest() { XXH3_freeState(state_); }
  Digest(const Digest&) = delete;
  Digest& operator=(const Digest&) = delete;
  template <class T>
  void add(const std::vector<T>& v) {
    XXH3_128bits_update(state_, v.data(), v.size() * sizeof(T));
  }
  std::string hex() const { return hex128(XXH3_128bits_digest(state_)); }

 private:
  XXH3_state_t* state_;
};

}  // namespace

double EnergyStats::quantile(double q) const {
  std::uint64_t total = 0;
  for (auto c : log_hist) total += c;
  if (total == 0) return 0;
  const double target = q * static_cast<double>(total);
  std::uint64_t run = 0;
  for (std::size_t b = 0; b < log_hist.size(); ++b) {
    run += log_hist[b];
    if (static_cast<double>(run) >= target && log_hist[b] > 0) {
      if (b == 0) return std::ldexp(1.0, AW_EHIST_MIN_EXP);
      if (b + 1 == log_hist.size()) return INFINITY;
      const int octave = static_cast<int>((b - 1) / AW_EHIST_BINS_PER_OCTAVE);
      const int quarter = static_cast<int>((b - 1) % AW_EHIST_BINS_PER_OCTAVE);
      // bin covers [2^(e-1) (1 + q/4), 2^(e-1) (1 + (q+1)/4)) with e - 1 = MIN_EXP + octave
      return std::ldexp(1.0 + (quarter + 1) / 4.0, AW_EHIST_MIN_EXP + octave);
    }
  }
  return INFINITY;
}

std::string digest_map(const Result& r) {
  Digest d;
  d.add(r.map);
  return d.hex();
}

std::string digest_records(const Result& r, const std::string& name) {
  const Records* rec = r.records_of(name);
  if (!rec || (rec->reals.empty() && rec->ints.empty())) return "";
  Digest d;
  d.add(rec->reals);
  d.add(rec->ints);
  return d.hex();
}

const Records* Result::records_of(const std::string& name) const {
  for (const Records& r : records)
    if (r.name == name) return &r;
  return nullptr;
}

const std::vector<double>& Result::reals(const std::string& name) const {
  static const std::vector<double> none;
  const Records* r = records_of(name);
  return r ? r->reals : none;
}

const std::vector<std::int64_t>& Result::ints(const std::string& name) const {
  static const std::vector<std::int64_t> none;
  const Records* r = records_of(name);
  return r ? r->ints : none;
}

}  // namespace arnoldweb
