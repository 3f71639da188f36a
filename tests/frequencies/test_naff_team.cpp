// The team form of the refinement (aw_naff.h, "teams") with eight lanes of
// GCC vectors, as the cpu backend compiles the core (eight members at a time),
// gives the bits of the one-lane form (a GPU's work-item per member): lengths
// that fill whole teams and lengths padded to them, a signal with a NaN; the
// padding, whatever the buffer held there, cleared by aw_naff_clear_padding.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "aw_cpp_std.h"
#include "naff_team_signals.hpp"

#define AW_LANES 8
namespace naff_team8 {
#include "aw_naff.h"
}  // namespace naff_team8

TEST_SUITE("frequencies") {
  TEST_CASE("team: eight members at a time in a vector give the bits of one member at a time") {
    using namespace naff_team8;
    const auto window = [](int k, int nn, int pp) { return aw_naff_window_at(k, nn, pp); };
    std::mt19937_64 rng(2026);
    for (int n : {16, 64, 300, 512, 1000}) {
      for (int p : {1, 2}) {
        CAPTURE(n);
        CAPTURE(p);
        for (int trial = 0; trial < 8; ++trial) {
          CAPTURE(trial);
          naff_team_test::Signal s =
              naff_team_test::make_signal(rng, n, AW_NAFF_PADDED(n), p, window);
          if (trial == 3) s.z[2 * static_cast<std::size_t>(n / 2)] = NAN;
          const aw_naff_team team = {0, nullptr};
          double f8 = -7, f1 = -8;
          int ok8 = -7, ok1 = -8;
          double power;
          aw_naff_refine_team(s.z.data(), 2 * AW_NAFF_GROUP, n, s.start, team, &f8, &power, &ok8);
          naff_team_test::refine_one_lane(s.z.data(), n, s.start, &f1, &ok1);
          CHECK(ok8 == ok1);
          CHECK(std::memcmp(&f8, &f1, sizeof(double)) == 0);
          if (trial == 3) {
            CHECK(ok8 == 0);  // not finite: no maximum, the start returned
            CHECK(f8 == s.start);
          } else {
            CHECK(ok8 == 1);
            CHECK(std::fabs(f8 - s.sigma) < 0.5 / n);
          }
        }
      }
    }
  }

  TEST_CASE("team: the padding past n is cleared before the passes, whatever the buffer held there") {
    using namespace naff_team8;
    const auto window = [](int k, int nn, int pp) { return aw_naff_window_at(k, nn, pp); };
    std::mt19937_64 rng(7);
    for (int n : {16, 100, 300, 512, 1000}) {
      CAPTURE(n);
      const int padded = AW_NAFF_PADDED(n);
      const naff_team_test::Signal s = naff_team_test::make_signal(rng, n, padded, 1, window);
      std::vector<double> dirty = s.z;
      for (std::size_t i = 2 * static_cast<std::size_t>(n); i < dirty.size(); ++i) dirty[i] = NAN;
      const aw_naff_team team = {0, nullptr};
      aw_naff_clear_padding(dirty.data(), 2 * AW_NAFF_GROUP, n, team);
      CHECK(std::memcmp(dirty.data(), s.z.data(), dirty.size() * sizeof(double)) == 0);  // the samples kept, the padding 0
      double f_dirty = -7, f_clean = -8;
      int ok_dirty = -7, ok_clean = -8;
      double power;
      aw_naff_refine_team(dirty.data(), 2 * AW_NAFF_GROUP, n, s.start, team, &f_dirty, &power, &ok_dirty);
      aw_naff_refine_team(s.z.data(), 2 * AW_NAFF_GROUP, n, s.start, team, &f_clean, &power, &ok_clean);
      CHECK(ok_dirty == 1);
      CHECK(ok_clean == 1);
      CHECK(std::memcmp(&f_dirty, &f_clean, sizeof(double)) == 0);
    }
  }
}

TEST_SUITE("frequencies") {
  TEST_CASE("team: the search for the largest term, eight members at a time, gives the bits of one at a time") {
    using namespace naff_team8;
    const auto window = [](int k, int nn, int pp) { return aw_naff_window_at(k, nn, pp); };
    std::mt19937_64 rng(37);
    std::uniform_real_distribution<double> uni(0, 1);
    int scanned = 0;
    for (int n : {64, 300, 512}) {
      for (int p : {0, 1, 2}) {
        for (int trial = 0; trial < 6; ++trial) {
          CAPTURE(n);
          CAPTURE(p);
          CAPTURE(trial);
          // librations of 2 pi a from 0.5 to 5 radians, 3 to 10 of their periods in the window
          const naff_team_test::Libration l = {0.02 * (uni(rng) - 0.5), (0.5 + 4.5 * uni(rng)) / 6.283185307179586,
                                               (3 + 7 * uni(rng)) / n, 6.283 * uni(rng), 0.05 * uni(rng),
                                               6.283 * uni(rng)};
          std::vector<double> raw;
          naff_team_test::Signal s = naff_team_test::make_libration(l, n, AW_NAFF_PADDED(n), p, window, &raw);
          if (trial == 5) s.z[2 * static_cast<std::size_t>(n / 3) + 1] = NAN;
          const aw_naff_team team = {0, nullptr};
          double f8 = -7, f1 = -8, f_mean = -9, power;
          int ok8 = -7, ok1 = -8, ok_mean = -9;
          aw_naff_largest_team(s.z.data(), 2 * AW_NAFF_GROUP, n, p, s.start, team, &f8, &ok8);
          naff_team_test::largest_one_lane(s.z.data(), n, p, s.start, &f1, &ok1);
          CHECK(ok8 == ok1);
          CHECK(ok8 == (trial == 5 ? 0 : 1));
          CHECK(std::memcmp(&f8, &f1, sizeof(double)) == 0);
          aw_naff_refine_team(s.z.data(), 2 * AW_NAFF_GROUP, n, s.start, team, &f_mean, &power, &ok_mean);
          scanned += (ok8 && f8 != f_mean) ? 1 : 0;
        }
      }
    }
    MESSAGE(scanned << " of 45 finite signals have their largest term away from the maximum nearest the mean rate");
    CHECK(scanned >= 10);  // the grid and the candidates were taken, not only the first search
  }
}
