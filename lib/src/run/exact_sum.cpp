// arnoldweb: an exact sum of doubles (exact_sum.hpp).
#include "run/exact_sum.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace arnoldweb::detail {

void ExactSum::add(double x) {
  if (!(x >= 0.0) || !std::isfinite(x)) {
    other_ += x;
    return;
  }
  if (x == 0.0) return;
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, 8);
  const int biased = static_cast<int>(bits >> 52);
  std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
  int position = 0;  // of the mantissa's lowest bit, in units of 2^-1074
  if (biased) {
    mantissa |= std::uint64_t{1} << 52;
    position = biased - 1;
  }
  const int k = position / 32, shift = position % 32;
  const unsigned __int128 v = static_cast<unsigned __int128>(mantissa) << shift;  // < 2^85
  limb_[k] += static_cast<std::uint32_t>(v);
  limb_[k + 1] += static_cast<std::uint32_t>(v >> 32);
  limb_[k + 2] += static_cast<std::uint32_t>(v >> 64);
  if (++pending_ >= (1u << 30)) normalise();
}

void ExactSum::normalise() const {
  std::uint64_t carry = 0;
  for (auto& l : limb_) {
    const std::uint64_t t = l + carry;
    l = t & 0xffffffffu;
    carry = t >> 32;
  }
  pending_ = 0;  // carry is 0: the top limbs stay empty for finite sums below 2^1100
}

void ExactSum::merge(const ExactSum& o) {
  normalise();
  o.normalise();
  for (int k = 0; k < kLimbs; ++k) limb_[k] += o.limb_[k];
  pending_ = 1;
  normalise();
  other_ += o.other_;
}

double ExactSum::value() const {
  normalise();
  int top = kLimbs - 1;
  while (top >= 0 && limb_[top] == 0) --top;
  double exact = 0.0;
  if (top >= 0) {
    const int h = top * 32 + (63 - __builtin_clzll(limb_[top]));  // highest set bit
    auto bit_range = [&](int lo) {  // the 64 bits [lo, lo + 64) (lo may be negative)
      unsigned __int128 acc = 0;
      for (int k = top; k >= 0 && k * 32 + 32 > lo; --k) {
        const int off = k * 32 - lo;
        if (off >= 64) continue;
        acc |= off >= 0 ? static_cast<unsigned __int128>(limb_[k]) << off
                        : static_cast<unsigned __int128>(limb_[k] >> (-off));
      }
      return static_cast<std::uint64_t>(acc);
    };
    if (h < 53) {
      exact = std::ldexp(static_cast<double>(bit_range(0)), -1074);  // exact: a subnormal or small normal
    } else {
      const int lo = h - 63;
      std::uint64_t t = bit_range(lo);  // top bit of t is bit h
      bool sticky = false;
      for (int k = 0; k <= top && !sticky; ++k) {
        if (k * 32 >= lo) break;
        const int below = lo - k * 32;  // bits of limb k under lo
        const std::uint64_t mask = below >= 32 ? 0xffffffffu : ((std::uint64_t{1} << below) - 1);
        sticky = (limb_[k] & mask) != 0;
      }
      std::uint64_t q = t >> 11;
      const std::uint64_t rem = t & 0x7ff;
      if (rem > 0x400 || (rem == 0x400 && (sticky || (q & 1)))) ++q;
      exact = std::ldexp(static_cast<double>(q), lo + 11 - 1074);
    }
  }
  return other_ == 0.0 ? exact : exact + other_;
}

std::string ExactSum::image() const {
  normalise();
  std::string s(kImageBytes, '\0');
  for (int k = 0; k < kLimbs; ++k)
    for (int b = 0; b < 8; ++b) s[8 * k + b] = static_cast<char>(limb_[k] >> (8 * b));
  std::uint64_t o = 0;
  std::memcpy(&o, &other_, 8);
  for (int b = 0; b < 8; ++b) s[8 * kLimbs + b] = static_cast<char>(o >> (8 * b));
  return s;
}

ExactSum ExactSum::read(const std::string& s) {
  if (s.size() != kImageBytes) throw std::runtime_error("an exact sum of the wrong size");
  ExactSum e;
  auto word = [&](int k) {
    std::uint64_t v = 0;
    for (int b = 0; b < 8; ++b) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(s[8 * k + b])) << (8 * b);
    return v;
  };
  for (int k = 0; k < kLimbs; ++k) {
    e.limb_[k] = word(k);
    if (e.limb_[k] > 0xffffffffu) throw std::runtime_error("an exact sum that is not normalised");
  }
  const std::uint64_t o = word(kLimbs);
  std::memcpy(&e.other_, &o, 8);
  return e;
}

}  // namespace arnoldweb::detail
