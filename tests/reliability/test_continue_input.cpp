// Reliability: `arnoldweb continue DIR` (issue 37, item 7). DIR and the values
// continuing adds are passed as values, never spliced into TOML (`continue
// '"q" #'` ran from a file named q while it checked the digest of another);
// --set run.duration together with --for is refused, and so is every --set of
// a key that changes the trajectories (one list: continue_keys()). Each case
// failed before (ARNOLDWEB_TEST_CLI=<old build>).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <nlohmann/json.hpp>

#include "arnoldweb/output.hpp"
#include "output_table/output_table.hpp"
#include "run_outputs.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const std::string kScene =
    "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 500\nseed = 3\n[integrator]\nstep = 0.02\n"
    "[run]\naverage = 1.0\nduration = 2.0\ndevice = \"cpu\"\n[observe]\nvelocity_map = { nside = 8 }\n"
    "energy_error = false\nfinal_states = true\n[output]\nimages = false\n";

}  // namespace

TEST_SUITE("reliability") {
  TEST_CASE("issue 37, 7. continue takes DIR as a value, and --set only for keys that keep the trajectories") {
    const std::string dir = awtest::temp_dir("continue-input");
    std::ofstream(dir + "/scene.toml") << kScene;
    awtest::CliOptions here;
    here.cwd = dir;
    std::string out;
    REQUIRE(awtest::run_cli({"run", "scene.toml", "--quiet", "--out", "both", "--set", "run.duration=4"}, &out, here) == 0);
    // a run in a directory whose name reads as TOML (moved there: `run --out` has its own reading of
    // --out), and a file of other states named by that TOML
    const std::string odd = "\"q\" #";
    REQUIRE(awtest::run_cli({"run", "scene.toml", "--quiet", "--out", "first"}, &out, here) == 0);
    fs::rename(dir + "/first", dir + "/" + odd);
    REQUIRE(awtest::run_cli({"run", "scene.toml", "--quiet", "--out", "other", "--set", "ensemble.seed=9"}, &out, here) == 0);
    fs::copy_file(dir + "/other/states.h5", dir + "/q");
    const int rc = awtest::run_cli({"continue", odd, "--for", "2", "--quiet", "--set", "output.images=false"}, &out, here);
    CAPTURE(out);
    REQUIRE(rc == 0);
    const nlohmann::json both = awtest::summary_of(dir + "/both"), cont = awtest::summary_of(dir + "/" + odd + "-to-4");
    CHECK(cont["digests"]["final_states"] == both["digests"]["final_states"]);  // from the run, not from q
    CHECK(cont["scene"]["ensemble"]["file"] == odd + "/states.h5");
    CHECK(cont["time"]["end"] == 4.0);

    // run.duration is what --for gives: both at once are refused, not one silently taken
    CHECK(awtest::run_cli({"continue", "both", "--for", "2", "--quiet", "--set", "run.duration=10"}, &out, here) == 2);
    CHECK(contains(out, "--set run.duration=10: run.duration: a continuation runs for the duration it is given"));
    // keys that change the trajectories, as the docs say (docs/cluster.md)
    for (const std::string set : {"integrator.step=0.01", "model.energy=16", "ensemble.seed=4", "observe.confine={ "
                                  "center = [0, 0], width = 10 }", "integrator.method=\"yoshida6\""}) {
      CAPTURE(set);
      CHECK(awtest::run_cli({"continue", "both", "--for", "2", "--quiet", "--set", set}, &out, here) == 2);
      CHECK(contains(out, "a continuation keeps the run's trajectories, so it may set only keys that leave them "
                          "unchanged (run.device"));
      CHECK(contains(out, "ensemble.file = \"<the run's directory>/states.h5\""));
    }
    CHECK_FALSE(fs::exists(dir + "/both-to-6"));
  }

  TEST_CASE("issue 37, 7. the keys continue allows are those docs/cluster.md names, the output table's in docs/outputs.md") {
    const auto read = [](const std::string& page) {
      std::ifstream in(std::string(ARNOLDWEB_SOURCE_DIR) + "/docs/" + page);
      return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    const std::string doc = read("cluster.md"), outputs = read("outputs.md");
    std::string section = doc.substr(doc.find("**Continuing a finished run.**"));
    section = section.substr(0, section.find("\n\n"));
    REQUIRE(contains(section, "every key of the output table"));
    std::set<std::string> table_keys;  // the output table's keys: an output's, named where the outputs are
    for (const arnoldweb::detail::OutputSwitch* w : arnoldweb::detail::output_switches()) table_keys.insert(w->key);
    for (const arnoldweb::detail::KeyTable* t : arnoldweb::detail::key_tables()) table_keys.insert(t->key);
    for (const arnoldweb::detail::DirectionKey* d : arnoldweb::detail::direction_keys()) table_keys.insert(d->key);
    for (const std::string& key : arnoldweb::continue_keys()) {
      CAPTURE(key);
      CHECK(contains(table_keys.count(key) ? outputs : section, "`" + key));
    }
  }
}
