// The frequency analysis and the diffusion sampling inside a run
// (observe.frequencies, observe.diffusion; docs/frequencies.md), on every
// device present (ctest entries frequency-runs.cpu, .opencl, .cuda):
//  - integrable motion: fgl at eps = 0 turns its angles at nu = I exactly, the
//    paper's model with its potential off at nu = P, and nothing changes
//    between the windows;
//  - a rotating pendulum (fourier, one harmonic) against its frequency from
//    quadrature: the error falls with the window's length as Laskar's
//    Hanning window promises; a librating one: the largest term at its
//    libration frequency (not at the mean rate), in both windows;
//  - the records are the same bits with and without time slices of the
//    diffusion sampling, and on every backend (the parity suite's digests);
//  - the diffusion analysis: the sampled actions, their moments and D.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "arnoldweb/diffusion.hpp"
#include "aw_params.h"
#include "support.hpp"

using namespace arnoldweb;

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

// fgl on a plane grid of actions, the frequencies of `samples` samples every 0.16 T.
Scene fgl_scene(const std::vector<std::string>& sets) {
  return awtest::scene_from(R"(
    [model]
    kind = "fgl"
    epsilon = 0.0
    energy = 0.5
    [ensemble]
    initial = "grid"
    grid = { kind = "plane", resolution = [8, 6], range1 = [-0.5, 1.5], range2 = [-0.45, 1.4], axes = [0, 1], fixed = 0.0, position = [0.1, 0.2, 0.3] }
    [integrator]
    method = "saba3"
    step = 0.02
    [run]
    average = 40.96
    duration = 40.96
    [observe]
    velocity_map = false
    energy_error = { every = 0.32 }
    frequencies = { samples = 128, every = 0.16, window = 1 }
  )", sets, "<frequency-runs>");
}

// The rotation frequency of the pendulum H = p^2/2 + c cos x from x = 0 with
// momentum p0, in turns per T (T = 2 pi time units): 2 pi / (the period in time
// units), the period int_0^{2 pi} dx / p(x) by the trapezoid rule (spectrally
// accurate for a smooth periodic integrand).
double pendulum_frequency(double c, double p0) {
  const double e = 0.5 * p0 * p0 + c;
  const int n = 4096;
  double period = 0;
  for (int i = 0; i < n; ++i) period += 1 / std::sqrt(2 * (e - c * std::cos(kTwoPi * i / n)));
  period *= kTwoPi / n;
  return kTwoPi / period;
}

// The pendulum in x (c = 0.5), free motion in y and z; momenta p0 = 1.3 .. 1.9 in x from x = 0
// (its top): rotations; `sets` change that.
Scene pendulum_scene(int samples, std::vector<std::string> sets = {}) {
  const double every = 0.05;
  const double duration = 2 * samples * every;
  sets.insert(sets.begin(), {awtest::set("run.duration", duration), awtest::set("run.average", duration),
                             "observe.frequencies={ samples = " + std::to_string(samples) + ", every = 0.05, window = 1 }"});
  return awtest::scene_from(R"(
    [model]
    kind = "fourier"
    harmonics = [[1, 0, 0, 0.5, 0.0]]
    energy = 1.0
    [ensemble]
    initial = "grid"
    grid = { kind = "plane", resolution = [4, 1], range1 = [1.2, 2.0], range2 = [0.3, 0.5], axes = [0, 1], fixed = 0.7, position = [0.0, 0.0, 0.0] }
    [integrator]
    method = "yoshida6a"
    step = 0.005
    [observe]
    velocity_map = false
    energy_error = { every = 0.05 }
  )", sets, "<pendulum>");
}

// The libration frequency of the same pendulum about x = pi from there with momentum p0 < 2 sqrt c,
// in turns per T: sqrt(c) pi / (2 K(k)), k = p0 / (2 sqrt c) = sin(amplitude / 2), K by the
// arithmetic-geometric mean (K(k) = pi / (2 AGM(1, sqrt(1 - k^2)))).
double libration_frequency(double c, double p0) {
  const double k = p0 / (2 * std::sqrt(c));
  double a = 1, b = std::sqrt(1 - k * k);
  for (int i = 0; i < 40; ++i) {
    const double m = (a + b) / 2;
    b = std::sqrt(a * b);
    a = m;
  }
  return std::sqrt(c) * a;  // sqrt(c) pi / (2 K) = sqrt(c) AGM
}

// The pendulum librating about x = pi (its bottom; the position in radians): p0 = 1.0, 1.1, 1.2, 1.3
// (amplitudes 1.57 to 2.35 radians), 1024 samples every 0.05 T (26 to 31 librations a window).
Scene libration_scene() {
  return pendulum_scene(1024, {"ensemble.grid.range1=[0.95, 1.35]",
                               "ensemble.grid.position=[3.141592653589793, 0.0, 0.0]"});
}

}  // namespace

TEST_SUITE("frequency-runs") {
  TEST_CASE("integrable fgl: every angle turns at nu = I, the same in both windows") {
    // 100 samples: windows padded to 128, the padding cleared by the analysis
    for (const auto& device : awtest::devices_under_test())
      for (const char* samples : {"128", "100"}) {
      CAPTURE(device.id);
      CAPTURE(samples);
      const Scene s = fgl_scene({std::string("observe.frequencies.samples=") + samples});
      const Result r = awtest::run_on(device.id, make_plan(s));
      const std::vector<double>& f = r.reals("frequencies");
      REQUIRE(f.size() == 48 * AW_FREQ_REALS);
      for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 8; ++i) {
          const double i1 = -0.5 + (i + 0.5) * 2.0 / 8, i2 = -0.45 + (j + 0.5) * 1.85 / 6;
          const double* rec = &f[static_cast<std::size_t>(j * 8 + i) * AW_FREQ_REALS];
          CAPTURE(i1);
          CAPTURE(i2);
          CHECK(std::fabs(rec[0] - i1) < 1e-10);
          CHECK(std::fabs(rec[1] - i2) < 1e-10);
          CHECK(std::fabs(rec[2] - 1.0) < 1e-10);
          for (int d = 0; d < 3; ++d) CHECK(std::fabs(rec[3 + d] - rec[d]) < 1e-10);
          CHECK(rec[6] < 1e-10);
        }
    }
  }

  TEST_CASE("the paper's model with its potential off (fourier, amplitudes 0): nu = P, both windows") {
    for (const auto& device : awtest::devices_under_test()) {
      CAPTURE(device.id);
      const Scene s = awtest::scene_from(R"(
        [model]
        kind = "fourier"
        harmonics = [[1, 1, 0, 0.0, 0.0], [1, -1, 0, 0.0, 0.0], [1, 1, 2, 0.0, 0.0], [1, 1, -2, 0.0, 0.0], [1, -1, 2, 0.0, 0.0], [1, -1, -2, 0.0, 0.0]]
        energy = 1.0
        [ensemble]
        initial = "grid"
        grid = { kind = "plane", resolution = [5, 3], range1 = [-2.5, 2.5], range2 = [-1.5, 1.5], axes = [0, 2], fixed = -0.35, position = [0.1, 0.2, 0.3] }
        [integrator]
        method = "yoshida6a"
        step = 0.01
        [run]
        average = 12.8
        duration = 12.8
        [observe]
        velocity_map = false
        energy_error = { every = 0.05 }
        frequencies = { samples = 128, every = 0.05, window = 1 }
      )", {}, "<free motion>");
      const Result r = awtest::run_on(device.id, make_plan(s));
      const std::vector<double>& f = r.reals("frequencies");
      REQUIRE(f.size() == 15 * AW_FREQ_REALS);
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 5; ++i) {
          const double px = -2.5 + (i + 0.5), pz = -1.5 + (j + 0.5), py = -0.35;
          const double* rec = &f[static_cast<std::size_t>(j * 5 + i) * AW_FREQ_REALS];
          CAPTURE(px);
          CAPTURE(pz);
          CHECK(std::fabs(rec[0] - px) < 1e-10);
          CHECK(std::fabs(rec[1] - py) < 1e-10);
          CHECK(std::fabs(rec[2] - pz) < 1e-10);
          CHECK(rec[6] < 1e-10);
        }
    }
  }

  TEST_CASE("a rotating pendulum: the frequency of quadrature, the error falling as 1/T^4 or faster") {
    const double c = 0.5;
    for (const auto& device : awtest::devices_under_test()) {
      CAPTURE(device.id);
      // windows of 64, 256 and 1024 samples: 3.2, 12.8 and 51.2 T (4 to 70 turns)
      double worst[3] = {0, 0, 0};
      const int samples[3] = {64, 256, 1024};
      for (int w = 0; w < 3; ++w) {
        const Result r = awtest::run_on(device.id, make_plan(pendulum_scene(samples[w])));
        for (int i = 0; i < 4; ++i) {
          const double p0 = 1.2 + (i + 0.5) * 0.8 / 4;
          const double* f = &r.reals("frequencies")[static_cast<std::size_t>(i) * AW_FREQ_REALS];
          CAPTURE(p0);
          CHECK(std::fabs(f[1] - 0.4) < 1e-10);  // free motion in y: nu = p_y
          CHECK(std::fabs(f[2] - 0.7) < 1e-10);  // and in z
          worst[w] = std::max(worst[w], std::fabs(f[0] - pendulum_frequency(c, p0)));
        }
      }
      MESSAGE("pendulum frequency error, windows of 3.2, 12.8, 51.2 T: " << worst[0] << ", " << worst[1] << ", "
                                                                         << worst[2]);
      CHECK(worst[0] < 1e-3);
      CHECK(worst[1] < worst[0] / 200);  // 4x the window: 256x for 1/T^4
      CHECK(worst[2] < worst[1] / 200);
      CHECK(worst[2] < 1e-8);
    }
  }

  // e^{2 pi i u} of the libration has its terms at k f (f the libration frequency), the
  // largest at k = +-1 for these amplitudes (J_1 > J_0 from 1.44 radians on), the one nearest the
  // mean rate (0) at k = 0: NAFF's frequency is |nu| = f, where the search from the mean rate
  // alone found the term at 0. The +f and -f terms are equally large (a symmetric libration):
  // which is the larger changes with the window, and the index compares |nu|.
  TEST_CASE("a librating pendulum: the largest term at the libration frequency of quadrature, |nu| in both "
            "windows, a small index") {
    const double c = 0.5;
    for (const auto& device : awtest::devices_under_test()) {
      CAPTURE(device.id);
      const Result r = awtest::run_on(device.id, make_plan(libration_scene()));
      int flips = 0;
      for (int i = 0; i < 4; ++i) {
        const double p0 = 0.95 + (i + 0.5) * 0.1, f = libration_frequency(c, p0);
        const double* rec = &r.reals("frequencies")[static_cast<std::size_t>(i) * AW_FREQ_REALS];
        CAPTURE(p0);
        CAPTURE(f);
        MESSAGE("p0 " << p0 << ": nu " << rec[0] << ", " << rec[3] << ", |nu| - f " << std::fabs(rec[0]) - f << ", "
                      << std::fabs(rec[3]) - f << "; index " << std::log10(rec[6]));
        // the window's leakage from the other terms (0, +-2f, ...): 1e-7 to 1e-6 turns per T, growing
        // towards the separatrix; the term at 0 that the mean rate's search found is f away
        CHECK(std::fabs(std::fabs(rec[0]) - f) < 3e-6);
        CHECK(std::fabs(std::fabs(rec[3]) - f) < 3e-6);
        CHECK(std::fabs(rec[1] - 0.4) < 1e-10);  // free motion in y and z
        CHECK(std::fabs(rec[2] - 0.7) < 1e-10);
        CHECK(rec[6] < 1e-5);                    // regular: the index compares |nu|
        flips += (rec[0] > 0) != (rec[3] > 0) ? 1 : 0;
      }
      CHECK(flips > 0);  // the sign did change between the windows: nu itself would give an index of log10 2f
    }
  }

  TEST_CASE("float runs find the double run's frequencies to float accuracy") {
    const auto& device = awtest::devices_under_test().front();
    CAPTURE(device.id);
    const Result d = awtest::run_on(device.id, make_plan(fgl_scene({"model.epsilon=0.01"})));
    const Result f = awtest::run_on(device.id, make_plan(fgl_scene({"model.epsilon=0.01", "integrator.precision=\"float\""})));
    const auto& a = d.reals("frequencies");
    const auto& b = f.reals("frequencies");
    REQUIRE(a.size() == b.size());
    for (std::size_t t = 0; t < a.size() / AW_FREQ_REALS; ++t)
      for (int k = 0; k < 6; ++k) CHECK(std::fabs(a[t * AW_FREQ_REALS + k] - b[t * AW_FREQ_REALS + k]) < 1e-4);
  }

  TEST_CASE("frequencies and actions, double and float: every device gives the cpu backend's bits") {
    for (const char* precision : {"\"double\"", "\"float\""})
      for (const char* samples : {"128", "100"}) {  // 100: windows padded to whole teams
      CAPTURE(precision);
      CAPTURE(samples);
      const Plan plan = make_plan(fgl_scene({"model.epsilon=0.03", std::string("integrator.precision=") + precision,
                                             std::string("observe.frequencies.samples=") + samples,
                                             "observe.fli=true",
                                             "observe.diffusion={ every = 5.12, along = [1, 1, 0], across = [1, -1, 0] }"}));
      const Result ref = awtest::run_on("cpu", plan);
      REQUIRE(ref.reals("frequencies").size() == 48 * AW_FREQ_REALS);
      for (const auto& device : awtest::devices_under_test()) {
        CAPTURE(device.id);
        const Result r = awtest::run_on(device.id, plan);
        for (const char* name : {"frequencies", "actions", "indicators"}) {
          CAPTURE(name);
          CHECK(awtest::first_difference(r.reals(name), ref.reals(name)) == -1);
          CHECK(digest_records(r, name) == digest_records(ref, name));
        }
        CHECK(r.analyses == ref.analyses);
      }
    }
  }

  // The paper's model at E = 15: chaotic orbits, whose refinements take from 2 to
  // more than 20 passes (2-23, mean 5, on the default scene's ensemble). A GPU
  // analyses a trajectory with a team of work-items, one member each (a warp in
  // CUDA, a work-group in OpenCL: AW_NAFF_TEAM_PARALLEL), a CPU with one
  // work-item computing the members a vector at a time: the same frequencies,
  // bit for bit. OpenCL devices run every form: eight lanes (a CPU's), one lane
  // (ARNOLDWEB_OPENCL_LANES=1), and the teams of work-items a GPU runs
  // (ARNOLDWEB_OPENCL_TEAMS=1 with one lane).
  TEST_CASE("frequencies of chaotic and librating orbits: every device and lane width gives the cpu backend's bits") {
    const Plan chaotic = make_plan(awtest::scene_from(R"(
      [model]
      energy = 15.0
      [ensemble]
      trajectories = 300
      seed = 7
      [integrator]
      method = "yoshida6a"
      step = 0.02
      [run]
      average = 10.24
      duration = 10.24
      [observe]
      velocity_map = { nside = 4 }
      frequencies = { samples = 128, every = 0.04 }
    )", {}, "<frequency-runs>"));
    const Result ref = awtest::run_on("cpu", chaotic);
    const std::vector<double> f = ref.reals("frequencies");
    REQUIRE(f.size() == 300 * AW_FREQ_REALS);
    int finite = 0;
    for (double v : f) finite += std::isfinite(v) ? 1 : 0;
    CHECK(finite > 250 * AW_FREQ_REALS);  // most orbits give every frequency
    // and librating orbits, whose largest terms the grid over their band finds
    const Plan libration = make_plan(libration_scene());
    const std::vector<double> lf = awtest::run_on("cpu", libration).reals("frequencies");
    struct Form {
      const char *lanes, *teams;
    };
    for (const auto& device : awtest::devices_under_test()) {
      for (const Form form : {Form{"", ""}, Form{"8", "0"}, Form{"1", "0"}, Form{"1", "1"}}) {
        if (*form.lanes && device.backend != "opencl") continue;
        CAPTURE(device.id);
        CAPTURE(form.lanes);
        CAPTURE(form.teams);
        if (*form.lanes) ::setenv("ARNOLDWEB_OPENCL_LANES", form.lanes, 1);
        if (*form.teams) ::setenv("ARNOLDWEB_OPENCL_TEAMS", form.teams, 1);
        const Result r = awtest::run_on(device.id, chaotic), l = awtest::run_on(device.id, libration);
        ::unsetenv("ARNOLDWEB_OPENCL_LANES");
        ::unsetenv("ARNOLDWEB_OPENCL_TEAMS");
        CHECK(awtest::first_difference(r.reals("frequencies"), f) == -1);
        CHECK(awtest::first_difference(l.reals("frequencies"), lf) == -1);
      }
    }
  }

  // The GPU's team form needs one lane: asked for with more, an OpenCL device
  // refuses to compile and names both settings.
  TEST_CASE("ARNOLDWEB_OPENCL_TEAMS=1 with several lanes: a clear error naming ARNOLDWEB_OPENCL_LANES") {
    const Plan plan = make_plan(fgl_scene({}));
    for (const auto& device : awtest::devices_under_test()) {
      if (device.backend != "opencl") continue;
      CAPTURE(device.id);
      ::setenv("ARNOLDWEB_OPENCL_LANES", "8", 1);
      ::setenv("ARNOLDWEB_OPENCL_TEAMS", "1", 1);
      CHECK_THROWS_WITH_AS(awtest::run_on(device.id, plan), doctest::Contains("ARNOLDWEB_OPENCL_LANES=1"),
                           DeviceError);
      ::unsetenv("ARNOLDWEB_OPENCL_LANES");
      ::unsetenv("ARNOLDWEB_OPENCL_TEAMS");
    }
  }

  TEST_CASE("frequencies: the plan's checks name the key and the bound") {
    CHECK_THROWS_WITH_AS(make_plan(fgl_scene({"run.duration=20", "run.average=20"})),
                         doctest::Contains("observe.frequencies"), SceneError);
    CHECK_THROWS_WITH_AS(make_plan(fgl_scene({"observe.frequencies.every=0.17"})),
                         doctest::Contains("integrator.step"), SceneError);
    CHECK_THROWS_WITH_AS(make_plan(fgl_scene({"run.slice=20.48"})), doctest::Contains("run.slice"), SceneError);
  }

  TEST_CASE("diffusion: the actions at every sample time, in slices or not, and the analysis of summary.json") {
    const std::vector<std::string> sets = {"model.epsilon=0.02", "observe.frequencies=false",
                                           "observe.diffusion={ every = 2.56, along = [1, 1, 0], across = [1, -1, 0], fit_from = 10.24 }",
                                           "ensemble.grid.range1=[0.29, 0.31]", "ensemble.grid.range2=[0.29, 0.31]"};
    for (const auto& device : awtest::devices_under_test()) {
      CAPTURE(device.id);
      const Plan plan = make_plan(fgl_scene(sets));
      const Result r = awtest::run_on(device.id, plan);
      const Records* rec = r.records_of("actions");
      REQUIRE(rec != nullptr);
      REQUIRE(rec->reals_per == 3 * 17);  // t = 0, 2.56, ..., 40.96
      REQUIRE(rec->count() == 48);
      // the first sample is the initial action: I1 of the first cell's centre
      CHECK(rec->reals[0] == doctest::Approx(0.29 + 0.5 * 0.02 / 8).epsilon(1e-12));
      // the sampled actions are the final states' at the end
      auto slices = sets;
      slices.push_back("run.slice=10.24");
      slices.push_back("observe.final_states=true");
      const Result sliced = awtest::run_on(device.id, make_plan(fgl_scene(slices)));
      CHECK(awtest::first_difference(sliced.reals("actions"), r.reals("actions")) == -1);
      const auto& fin = sliced.reals("final_states");
      for (std::size_t t = 0; t < 48; ++t)
        for (int c = 0; c < 3; ++c) CHECK(fin[t * AW_STATE_REALS + 3 + c] == rec->reals[t * rec->reals_per + 48 + c]);
      // the analysis: the moments at 17 times and D along and across
      REQUIRE(r.analyses.count("diffusion") == 1);
      const nlohmann::json j = nlohmann::json::parse(r.analyses.at("diffusion"));
      CHECK(j["trajectories"] == 48);
      CHECK(j["moments"]["t"].size() == 17);
      CHECK(j["moments"]["along_variance"][0] == 0.0);
      CHECK(std::isfinite(j["along_fit"]["D"].get<double>()));
      // the same D as the library's estimator on the records
      ActionSamples s;
      s.trajectories = 48;
      s.times = 17;
      for (int k = 0; k < 17; ++k) s.t.push_back(2.56 * k);
      s.actions = rec->reals;
      DiffusionOptions o;
      o.t_min = 10.24;
      CHECK(j["along_fit"]["D"].get<double>() == fit_diffusion(s, {1, 1, 0}, o).D);
    }
  }

  TEST_CASE("diffusion with averaging: each sample is the mean of the actions at its points, in slices or not") {
    // the points of sample q: q D - j a, j = 0 .. m - 1, here D = 2.56 T, a = 0.32 T, m = 4
    const std::vector<std::string> base = {"model.epsilon=0.02", "observe.frequencies=false",
                                           "ensemble.grid.range1=[0.29, 0.31]", "ensemble.grid.range2=[0.29, 0.31]"};
    auto with = [&](std::vector<std::string> extra) {
      std::vector<std::string> sets = base;
      sets.insert(sets.end(), extra.begin(), extra.end());
      return make_plan(fgl_scene(sets));
    };
    const Plan fine = with({"observe.diffusion={ every = 0.32, along = [1, 1, 0], across = [1, -1, 0] }"});
    const Plan averaged = with({"observe.diffusion={ every = 2.56, along = [1, 1, 0], across = [1, -1, 0], "
                                "fit_from = 10.24, average = 1.28, average_every = 0.32 }"});
    for (const auto& device : awtest::devices_under_test()) {
      CAPTURE(device.id);
      const Result f = awtest::run_on(device.id, fine);
      const Result a = awtest::run_on(device.id, averaged);
      const Records* rf = f.records_of("actions");
      const Records* ra = a.records_of("actions");
      REQUIRE(rf != nullptr);
      REQUIRE(ra != nullptr);
      REQUIRE(rf->reals_per == 3 * 129);  // every 0.32 T to 40.96 T
      REQUIRE(ra->reals_per == 3 * 17);
      for (std::size_t t = 0; t < 48; ++t)
        for (int c = 0; c < 3; ++c) {
          const double* fr = rf->reals.data() + t * rf->reals_per;
          const double* ar = ra->reals.data() + t * ra->reals_per;
          CHECK(ar[c] == fr[c]);  // t = 0: the initial action itself
          for (int q = 1; q <= 16; ++q) {
            double sum = 0;  // in the device's order: the earliest point first
            for (int j = 3; j >= 0; --j) sum += fr[3 * (8 * q - j) + c];
            CHECK(ar[3 * q + c] == sum * 0.25);
          }
        }
      // the same bits in time slices that end at sample times
      const Plan sliced = with({"observe.diffusion={ every = 2.56, along = [1, 1, 0], across = [1, -1, 0], "
                                "fit_from = 10.24, average = 1.28, average_every = 0.32 }",
                                "run.slice=10.24"});
      CHECK(awtest::first_difference(awtest::run_on(device.id, sliced).reals("actions"), a.reals("actions")) == -1);
      // the analysis starts at the first mean (t = 2.56), not at the instantaneous t = 0
      const nlohmann::json j = nlohmann::json::parse(a.analyses.at("diffusion"));
      CHECK(j["moments"]["t"].size() == 16);
      CHECK(j["moments"]["t"][0] == 2.56);
      CHECK(j["moments"]["along_variance"][0] == 0.0);
      CHECK(j["average"] == 1.28);
      ActionSamples s;
      s.trajectories = 48;
      s.times = 16;
      for (int k = 1; k <= 16; ++k) s.t.push_back(2.56 * k);
      for (std::size_t t = 0; t < 48; ++t)
        s.actions.insert(s.actions.end(), ra->reals.begin() + static_cast<std::ptrdiff_t>(t * ra->reals_per + 3),
                         ra->reals.begin() + static_cast<std::ptrdiff_t>((t + 1) * ra->reals_per));
      DiffusionOptions o;
      o.t_min = 10.24;
      CHECK(j["along_fit"]["D"].get<double>() == fit_diffusion(s, {1, 1, 0}, o).D);
    }
  }

  TEST_CASE("diffusion: the plan's checks name the key and the bound") {
    const std::string on = "observe.diffusion={ every = 2.56, along = [1, 1, 0], across = [1, -1, 0] }";
    CHECK_THROWS_WITH_AS(make_plan(fgl_scene({on, "observe.diffusion.every=3"})), doctest::Contains("observe.diffusion.every"),
                         SceneError);
    CHECK_THROWS_WITH_AS(make_plan(fgl_scene({on, "observe.diffusion.across=[2, 2, 0]"})),
                         doctest::Contains("observe.diffusion.across"), SceneError);
    CHECK_THROWS_WITH_AS(make_plan(fgl_scene({on, "observe.diffusion.fit_from=50"})),
                         doctest::Contains("observe.diffusion.fit_from"), SceneError);
    // averaging: a span that holds whole intervals, no longer than the sample interval, slices at sample times
    CHECK_THROWS_WITH_AS(make_plan(fgl_scene({on, "observe.diffusion.average=1.28", "observe.diffusion.average_every=0.5"})),
                         doctest::Contains("observe.diffusion.average_every"), SceneError);
    CHECK_THROWS_WITH_AS(make_plan(fgl_scene({on, "observe.diffusion.average=5.12", "observe.diffusion.average_every=0.32"})),
                         doctest::Contains("observe.diffusion.average"), SceneError);
    CHECK_THROWS_WITH_AS(make_plan(fgl_scene({on, "observe.frequencies=false", "observe.diffusion.average=1.28",
                                              "observe.diffusion.average_every=0.32", "run.slice=1.28"})),
                         doctest::Contains("run.slice"), SceneError);
    CHECK_NOTHROW(make_plan(fgl_scene({on, "observe.frequencies=false", "observe.diffusion.average=1.28",
                                       "observe.diffusion.average_every=0.32", "run.slice=5.12"})));
  }
}
