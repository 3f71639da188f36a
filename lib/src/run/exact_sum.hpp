// arnoldweb: an exact sum of doubles. Every finite value is added into a
// fixed-point integer wide enough for the whole double range (2^-1074 to
// 2^1024), so the sum does not depend on the order of the additions or on how
// they are split between accumulators that are merged later; value() rounds
// it once, to nearest even. Used for the energy statistics of a run, whose
// chunks may be reduced in any order, by any number of processes.
// Negative and non-finite values are rare in these statistics (they are sums
// of |dE|): they go into a plain double that is added at the end, so a NaN or
// an infinity still shows.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace arnoldweb::detail {

class ExactSum {
 public:
  void add(double x);
  void merge(const ExactSum& other);
  double value() const;  // the exact sum, rounded once

  // A fixed-size little-endian image of the state (for checkpoints and for
  // messages between processes); read() throws std::runtime_error on a bad image.
  std::string image() const;
  static ExactSum read(const std::string& image);
  static constexpr std::size_t kImageBytes = 8 * (70 + 1);

 private:
  static constexpr int kLimbs = 70;  // 32 bits each: 2240 bits > 2098 + headroom
  void normalise() const;
  mutable std::array<std::uint64_t, kLimbs> limb_{};  // limb k holds bits [32k, 32k + 32) (+ pending carries)
  mutable std::uint32_t pending_ = 0;                 // additions since the last carry propagation
  double other_ = 0.0;                                // negative and non-finite values
};

}  // namespace arnoldweb::detail
