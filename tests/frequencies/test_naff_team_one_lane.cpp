// The team form of the refinement (aw_naff.h, "teams") with one lane, as a
// GPU's work-item computes its member: its frequency is aw_naff_refine's on
// the same prewindowed samples to round-off (the same terms summed in
// another order), and it stops where aw_naff_refine stops.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "aw_cpp_std.h"
#include "naff_team_signals.hpp"

namespace naff_one_lane {
#include "aw_naff.h"
}  // namespace naff_one_lane

namespace naff_team_test {
void refine_one_lane(const double* z, int n, double sigma0, double* freq, int* ok) {
  const naff_one_lane::aw_naff_team team = {0, nullptr};
  double power;
  naff_one_lane::aw_naff_refine_team(z, 2 * AW_NAFF_GROUP, n, sigma0, team, freq, &power, ok);
}
void largest_one_lane(const double* z, int n, int p, double sigma0, double* freq, int* ok) {
  const naff_one_lane::aw_naff_team team = {0, nullptr};
  naff_one_lane::aw_naff_largest_team(z, 2 * AW_NAFF_GROUP, n, p, sigma0, team, freq, ok);
}
}  // namespace naff_team_test

TEST_SUITE("frequencies") {
  TEST_CASE("team: the team's frequency is aw_naff_refine's to round-off, on signals of every length") {
    using namespace naff_one_lane;
    const auto window = [](int k, int nn, int pp) { return aw_naff_window_at(k, nn, pp); };
    std::mt19937_64 rng(7);
    for (int n : {16, 64, 300, 512, 1000, 4096}) {
      for (int p : {1, 2}) {
        CAPTURE(n);
        CAPTURE(p);
        for (int trial = 0; trial < 6; ++trial) {
          const naff_team_test::Signal s =
              naff_team_test::make_signal(rng, n, AW_NAFF_PADDED(n), p, window);
          std::vector<double> re(n), im(n);
          for (int k = 0; k < n; ++k) re[k] = s.z[2 * k], im[k] = s.z[2 * k + 1];
          aw_naff_result r;
          aw_naff_refine(re.data(), im.data(), 1, n, 0, s.start, &r);
          double freq = -7;
          int ok = -7;
          naff_team_test::refine_one_lane(s.z.data(), n, s.start, &freq, &ok);
          CHECK(ok == r.ok);
          CHECK(ok == 1);
          CHECK(std::fabs(freq - r.freq) <= 1e-13);
          CHECK(std::fabs(freq - s.sigma) < 0.5 / n);  // the leading term (moved by its neighbours)
        }
      }
    }
  }
}
