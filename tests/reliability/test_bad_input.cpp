// Reliability: scenes and arguments that are too large, too deep or not files
// at all are refused before the TOML parser sees them, with the file, line
// and column (issue 12, item 7), and the smaller defects of item 10.
#include <doctest/doctest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "support.hpp"

namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string write(const std::string& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir + "/" + name) << text;
  return dir + "/" + name;
}

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

}  // namespace

TEST_SUITE("reliability") {
  TEST_CASE("7. scenes beyond the parser's limits are refused before parsing, quickly") {
    const std::string dir = awtest::temp_dir("limits");
    struct Case {
      std::string name, text, says;
    };
    const std::vector<Case> cases = {
        {"deep header", "[" + repeat("a.", 35000) + "a]\nx = 1\n", "more than 16 dotted parts"},
        {"deep dotted key", "[model]\n" + repeat("a.", 5000) + "a = 1\n", "more than 16 dotted parts"},
        {"nested arrays", "[model]\nenergy = " + repeat("[", 100000) + repeat("]", 100000) + "\n",
         "nested more than 32 deep"},
        {"nested inline tables", "[model]\nenergy = " + repeat("{a=", 5000) + "1" + repeat("}", 5000) + "\n",
         "nested more than 32 deep"},
        {"long key", "[model]\n" + std::string(900000, 'k') + " = 1\n", "longer than 256"},
        {"large file", "# " + std::string(2 << 20, 'x') + "\n", "at most 1048576 bytes"},
    };
    for (const Case& c : cases) {
      CAPTURE(c.name);
      const std::string path = write(dir, "scene.toml", c.text);
      std::string out;
      CHECK(awtest::run_cli({"check", path}, &out) == 2);
      CHECK(contains(out, c.says));
      CHECK(contains(out, "scene.toml"));
    }
    // a key that is long but allowed, in a quoted string, is fine
    std::string out;
    const std::string ok = write(dir, "ok.toml", "[output]\ndir = \"" + std::string(5000, 'd') + "\"\n");
    CHECK(awtest::run_cli({"check", ok}, &out) != 2);
    // --set goes through the same limits
    CHECK(awtest::run_cli({"check", ok, "--set", repeat("a.", 100) + "b=1"}, &out) == 2);
    CHECK(contains(out, "dotted parts"));
    CHECK(awtest::run_cli({"check", ok, "--set", "model.energy=" + repeat("[", 1000)}, &out) == 2);
    CHECK(contains(out, "nested"));
  }

  TEST_CASE("7. a FIFO, a device or a directory given as the scene is refused, not read") {
    const std::string dir = awtest::temp_dir("notfile");
    const std::string fifo = dir + "/scene.fifo";
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    std::string out;
    CHECK(awtest::run_cli({"check", fifo}, &out) == 2);  // would block for ever if opened for reading
    CHECK(contains(out, "pipe (FIFO)"));
    CHECK(awtest::run_cli(std::vector<std::string>{"check", "/dev/zero"}, &out) == 2);  // bad_alloc before
    CHECK(contains(out, "a device"));
    CHECK(awtest::run_cli({"check", dir}, &out) == 2);
    CHECK(contains(out, "a directory"));
  }

  TEST_CASE("10. smaller defects: unknown commands named, arrays shown, --target checked, hopeless tolerances refused") {
    const std::string dir = awtest::temp_dir("small");
    const std::string scene = write(dir, "scene.toml", "[run]\naverage = 1.0\nduration = 1.0\n");
    std::string out;
    CHECK(awtest::run_cli({"frobnicate"}, &out) == 2);
    CHECK(contains(out, "unknown command 'frobnicate'"));
    CHECK(awtest::run_cli({"check", scene, "--set", "ensemble.cap.center=[1,2,3]"}, &out) == 2);
    CHECK(contains(out, "got [1, 2, 3]"));
    for (const char* bad : {"nan", "inf", "-1", "0", "2", "x"}) {
      CAPTURE(bad);
      CHECK(awtest::run_cli({"accuracy", scene, "--target", bad}, &out) == 2);
      CHECK(contains(out, "--target"));
    }
    // a tolerance below double's round-off is refused at once, not after minutes of pilots
    CHECK(awtest::run_cli({"check", scene, "--device", "cpu", "--set", "integrator.step=auto", "--set",
                           "integrator.tolerance=1e-16"},
                          &out) == 2);
    CHECK(contains(out, "below what double precision can reach"));
  }
}
