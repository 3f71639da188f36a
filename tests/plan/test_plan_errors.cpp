// Values wrong together (the planner's checks, plan/checks.hpp fail_at): the
// error is placed at the key's own override when one gave it; when the file
// gave it and the message names a key that an override (--set, Python's
// Scene.set) gave, at that override, saying where the key's value is written.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "arnoldweb/errors.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

// run.average at line 4, column 1
const std::string kScene = "[integrator]\nstep = 0.02\n[run]\naverage = 5.0\nduration = 5.0\n";

SceneError plan_error(const std::string& text, const std::vector<std::string>& sets) {
  try {
    make_plan(awtest::scene_from(text, sets, "scene.toml"));
  } catch (const SceneError& e) {
    return e;
  }
  FAIL("the plan was not refused");
  return SceneError("", 0, 0, "", "");
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_SUITE("plan") {
  TEST_CASE("values wrong together are placed at what the user set") {
    // the step the user set makes the file's run.average wrong: at the override
    SceneError e = plan_error(kScene, {"integrator.step=0.013"});
    CHECK(e.key() == "run.average");
    CHECK(e.file() == "--set integrator.step=0.013");
    CHECK(e.line() == 0);
    CHECK(contains(e.message(), "integrator.step = 0.013"));
    CHECK(contains(e.message(), "(run.average as written at scene.toml:4:1)"));
    CHECK(std::string(e.what()).rfind("--set integrator.step=0.013: run.average: ", 0) == 0);
    // the latest of two overrides the message names
    e = plan_error(kScene, {"integrator.step=0.013", "run.duration=26"});
    CHECK(e.file() == "--set integrator.step=0.013");  // run.average's check names the step only
    // the key's own override: there, as before
    e = plan_error(kScene, {"run.average=5.01"});
    CHECK(e.file() == "--set run.average=5.01");
    CHECK_FALSE(contains(e.message(), "as written at"));
    // nothing the message names was set: the file's place, as before
    const std::string wrong = "[integrator]\nstep = 0.013\n[run]\naverage = 5.0\nduration = 5.0\n";
    e = plan_error(wrong, {"model.energy=16"});
    CHECK(e.file() == "scene.toml");
    CHECK(e.line() == 4);
    CHECK(e.key() == "run.average");
  }
}
