// arnoldweb compare DIR_A DIR_B: exit 0 for maps that are statistically the
// same, 1 for different ones, 2 with a message naming the file for what
// cannot be compared.
#include <doctest/doctest.h>

#include <fstream>

#include "support.hpp"

namespace {

// A tiny run (3000 trajectories, 1 T, nside 4) written to dir/name; `sets` change it.
std::string saved_run(const std::string& dir, const std::string& name, const std::string& sets) {
  const std::string scene = dir + "/scene.toml";
  std::ofstream(scene) << "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 3000\n[integrator]\nstep = 0.02\n"
                          "[run]\naverage = 1.0\nduration = 1.0\n[observe]\nvelocity_map = { nside = 4 }\n"
                          "energy_error = false\n[output]\nimages = false\n";
  const std::string out = dir + "/" + name;
  std::string text;
  const int rc = awtest::run_cli("run " + scene + " --quiet --device cpu --out " + out + " " + sets, &text);
  CAPTURE(text);
  REQUIRE(rc == 0);
  return out;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_SUITE("compare") {
  TEST_CASE("arnoldweb compare: 0 consistent, 1 different, 2 for what cannot be compared") {
    const std::string dir = awtest::temp_dir("compare");
    const std::string a = saved_run(dir, "a", "--set ensemble.seed=1");
    const std::string b = saved_run(dir, "b", "--set ensemble.seed=2");
    const std::string cap = saved_run(dir, "cap",
                                      "--set ensemble.seed=3 --set ensemble.initial=\"cap\" "
                                      "--set ensemble.cap.center=[45,30] --set ensemble.cap.radius=30");
    const std::string fine = saved_run(dir, "fine", "--set observe.velocity_map.nside=8");
    std::string out;
    // two seeds of one scene
    int rc = awtest::run_cli("compare " + a + " " + b, &out);
    CAPTURE(out);
    CHECK(rc == 0);
    CHECK(contains(out, "3000 counts"));
    CHECK(contains(out, "chi2/dof"));
    CHECK(contains(out, "statistically consistent at alpha = 0.001"));
    CHECK_FALSE(contains(out, "note"));
    // one seed twice: said to be no independent samples (here: the same map, chi2 = 0)
    rc = awtest::run_cli("compare " + a + " " + a, &out);
    CHECK(rc == 0);
    CHECK(contains(out, "both runs have ensemble.seed = 1"));
    // initial directions in a cap against the whole shell
    rc = awtest::run_cli("compare " + a + " " + cap + " --alpha 0.01", &out);
    CHECK(rc == 1);
    CHECK(contains(out, "different at alpha = 0.01"));
    // what cannot be compared: exit 2, the file named
    rc = awtest::run_cli("compare " + a + " " + dir + "/nothing-here", &out);
    CHECK(rc == 2);
    CHECK(contains(out, dir + "/nothing-here: no such directory"));
    rc = awtest::run_cli("compare " + a + " " + fine, &out);
    CHECK(rc == 2);
    CHECK(contains(out, fine + "/map.h5: map nside 8, but " + a + "/map.h5 has map nside 4"));
    rc = awtest::run_cli("compare " + a + " " + b + " --what zoom", &out);
    CHECK(rc == 2);
    CHECK(contains(out, a + "/map.h5: holds no zoom"));
    rc = awtest::run_cli("compare " + a + " " + b + " --what frames", &out);
    CHECK(rc == 2);
    CHECK(contains(out, "--what"));
  }
}
