// The kernels' lane form of the refinement (aw_naff_refine_lanes, 8 lanes of
// GCC vectors as the cpu backend compiles the core) gives every lane the
// frequency aw_naff_refine gives its signal alone, bit for bit, on samples
// prewindowed by aw_naff_window_at: lanes that stop early, a lane with a NaN,
// lanes not active.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "aw_cpp_std.h"

#define AW_LANES 8
namespace naff_lanes {
#include "aw_naff.h"
}  // namespace naff_lanes

TEST_SUITE("frequencies") {
  TEST_CASE("lanes: aw_naff_refine_lanes = aw_naff_refine on prewindowed samples, lane by lane, bit for bit") {
    using namespace naff_lanes;
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> uni(-0.45, 0.45), amp(0.05, 0.4), phase(0, 6.283185307179586);
    for (int n : {64, 300, 512}) {
      for (int p : {1, 2}) {
        CAPTURE(n);
        CAPTURE(p);
        const int groups = 4, count = groups * AW_LANES;
        std::vector<double> re(static_cast<std::size_t>(n) * count), im(re.size());
        std::vector<double> sigma(count), start(count);
        for (int j = 0; j < count; ++j) {
          // a leading term and two smaller ones; the start a fraction of a bin off
          sigma[j] = uni(rng);
          const double s2 = uni(rng), s3 = uni(rng), a2 = amp(rng), a3 = amp(rng), f2 = phase(rng), f3 = phase(rng);
          start[j] = sigma[j] + (uni(rng) / 0.45) * 0.4 / n;
          for (int k = 0; k < n; ++k) {
            const double w = aw_naff_window_at(k, n, p);
            const double t = k, a = 6.283185307179586 * sigma[j] * t;
            const double b = 6.283185307179586 * s2 * t + f2, c = 6.283185307179586 * s3 * t + f3;
            re[static_cast<std::size_t>(k) * count + j] = w * (std::cos(a) + a2 * std::cos(b) + a3 * std::cos(c));
            im[static_cast<std::size_t>(k) * count + j] = w * (std::sin(a) + a2 * std::sin(b) + a3 * std::sin(c));
          }
        }
        re[static_cast<std::size_t>(n / 2) * count + 9] = NAN;  // lane 1 of the second group
        int refined = 0;
        for (int g = 0; g < groups; ++g) {
          int active[AW_LANES];
          for (int j = 0; j < AW_LANES; ++j) active[j] = !(g == 3 && j >= 5);  // the last group: 5 lanes
          double freq[AW_LANES], lane_start[AW_LANES];
          int ok[AW_LANES];
          for (int j = 0; j < AW_LANES; ++j) freq[j] = -7, ok[j] = -7, lane_start[j] = start[g * AW_LANES + j];
          aw_naff_refine_lanes(re.data() + g * AW_LANES, im.data() + g * AW_LANES, count, n,
                               AW_LOAD_LANES(lane_start), active, freq, ok);
          for (int j = 0; j < AW_LANES; ++j) {
            const int t = g * AW_LANES + j;
            CAPTURE(t);
            if (!active[j]) {
              CHECK(freq[j] == -7);
              CHECK(ok[j] == -7);
              continue;
            }
            aw_naff_result r;
            aw_naff_refine(re.data() + t, im.data() + t, count, n, 0, start[t], &r);
            CHECK(ok[j] == r.ok);
            CHECK(std::memcmp(&freq[j], &r.freq, sizeof(double)) == 0);
            if (t == 9) CHECK(ok[j] == 0);
            if (t != 9) {
              CHECK(ok[j] == 1);
              CHECK(std::fabs(freq[j] - sigma[t]) < 0.5 / n);  // the leading term (moved by its neighbours), not one of them
              refined += ok[j];
            }
          }
        }
        CHECK(refined == count - 3 - 1);
      }
    }
  }
}
