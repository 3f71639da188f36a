// The frequency analysis (lib/device/aw_naff.h) in float, against double: the
// same signals give frequencies that agree to float's accuracy.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "aw_cpp_std.h"
#include "naff_cases.hpp"

#define AW_FLOAT 1
namespace naff_f {
#include "aw_naff.h"
#include "naff_driver.h"
}  // namespace naff_f

namespace naff_test {

std::vector<float> analyse_float(const Chunk& c, int p, int terms, int log2m) {
  std::vector<float> re(c.re.begin(), c.re.end()), im(c.im.begin(), c.im.end());
  std::vector<float> wre((std::size_t{1} << log2m) * c.count), wim(wre.size());
  std::vector<float> out(static_cast<std::size_t>(c.count) * terms * 5);
  for (int j = 0; j < c.count; ++j)
    naff_f::naff_test_analyse(re.data(), im.data(), wre.data(), wim.data(), out.data(), j, c.count, c.n, p, terms,
                              log2m);
  return out;
}

}  // namespace naff_test

TEST_SUITE("frequencies") {
  TEST_CASE("float and double agree to float's accuracy") {
    using naff_test::Term;
    for (int n : {256, 1024, 4096}) {
      CAPTURE(n);
      const std::vector<Term> terms = {{0.3183098861837907, {1.0, 0.0}},
                                       {0.1234567890123457, std::polar(0.4, 0.3)},
                                       {-0.2718281828459045, std::polar(0.2, 1.1)}};
      const naff_test::Chunk c = naff_test::make_chunk({terms}, n, 0.25);
      const int log2m = naff_test::fft_log2(n);
      const std::vector<double> d = naff_test::analyse_double(c, 1, 3, log2m);
      const std::vector<float> f = naff_test::analyse_float(c, 1, 3, log2m);
      for (int t = 0; t < 3; ++t) {
        CAPTURE(t);
        const double df = std::fabs(f[t * 5] - d[t * 5]);
        const double da = std::abs(std::complex<double>(f[t * 5 + 1], f[t * 5 + 2]) -
                                   std::complex<double>(d[t * 5 + 1], d[t * 5 + 2]));
        MESSAGE("n " << n << " term " << t << ": |float - double| frequency " << df << " cycles/sample ("
                     << df * n << " bins), amplitude " << da);
        CHECK(f[t * 5 + 4] == 1);
        // float's round-off: eps_f sqrt(n) / n cycles per sample, with a margin
        CHECK(df < 4 * 1.2e-7 / std::sqrt(n));
        CHECK(da < 4 * 1.2e-7 * std::sqrt(n));
      }
    }
  }
}
