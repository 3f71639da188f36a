// The pictures are a plugin opened at run time (output/picture_plugin.hpp):
// where it cannot be opened -- a build without cairo, or a machine without
// cairo's X11 libraries that installed the wheel -- a run still computes and
// writes its numbers, says why it drew no pictures, and `render` fails
// cleanly with the reason.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "arnoldweb/version.hpp"
#include "output/picture_plugin.hpp"
#include "output_table/output_table.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const std::string kScene =
    "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 300\n[integrator]\nstep = 0.02\n"
    "[run]\naverage = 1.0\nduration = 1.0\n[observe]\nvelocity_map = { nside = 8 }\n";

}  // namespace

TEST_SUITE("output") {
  TEST_CASE("the pictures' plugin: a missing or foreign file is refused with the loader's reason") {
    std::string why;
    CHECK(arnoldweb::detail::open_picture_plugin("/nonexistent/libarnoldweb_pictures.so", &why) == nullptr);
    CHECK(contains(why, "/nonexistent/libarnoldweb_pictures.so"));
    CHECK(contains(why, "could not be opened"));
    const std::string dir = awtest::temp_dir("plugin");
    std::ofstream(dir + "/fake.so") << "not a shared object\n";
    why.clear();
    CHECK(arnoldweb::detail::open_picture_plugin(dir + "/fake.so", &why) == nullptr);
    CHECK(contains(why, "fake.so"));
#ifdef ARNOLDWEB_HAVE_CAIRO
    // this build's own plugin is found beside the library and matches it
    why.clear();
    const arnoldweb::detail::PictureFunctions* f = arnoldweb::detail::picture_functions(&why);
    REQUIRE_MESSAGE(f != nullptr, why);
    CHECK(std::string(f->version) == ARNOLDWEB_VERSION);
    CHECK(static_cast<bool>(f->sphere));
    CHECK(static_cast<bool>(f->outputs));
    // every picture an output's row names is a row of the plugin's picture table
    for (const arnoldweb::detail::RecordOutput& row : arnoldweb::detail::record_outputs())
      for (const std::string& picture : row.pictures) CHECK_MESSAGE(f->draws(picture), (row.name + ": " + picture));
    CHECK_FALSE(f->draws("no-such-picture"));
#endif
  }

  TEST_CASE("without the pictures' plugin a run writes its numbers and says why it drew no pictures") {
    const std::string dir = awtest::temp_dir("nopictures");
    std::ofstream(dir + "/scene.toml") << kScene;
    awtest::CliOptions no_plugin;
    no_plugin.env = {"ARNOLDWEB_PICTURES=" + dir + "/missing/libarnoldweb_pictures.so"};
    std::string out;
    CHECK(awtest::run_cli({"run", dir + "/scene.toml", "--device", "cpu", "--out", dir + "/out"}, &out, no_plugin) ==
          0);
    CAPTURE(out);
    CHECK(contains(out, "no pictures will be drawn"));
    CHECK(contains(out, "missing/libarnoldweb_pictures.so"));
    CHECK(fs::exists(dir + "/out/map.h5"));
    CHECK_FALSE(fs::exists(dir + "/out/map.png"));
    const auto summary = nlohmann::json::parse(std::ifstream(dir + "/out/summary.json"));
    bool warned = false;
    for (const auto& w : summary["warnings"]) warned |= contains(w.get<std::string>(), "no pictures will be drawn");
    CHECK(warned);
    for (const auto& f : summary["files"]) CHECK_FALSE(contains(f.get<std::string>(), ".png"));

    // drawing them afterwards needs the plugin: a clean failure naming why, the directory untouched
    const auto before = fs::last_write_time(dir + "/out/summary.json");
    std::string render_out;
    CHECK(awtest::run_cli({"render", dir + "/out"}, &render_out, no_plugin) != 0);
    CAPTURE(render_out);
    CHECK(contains(render_out, "no pictures"));
    CHECK(contains(render_out, "missing/libarnoldweb_pictures.so"));
    CHECK(fs::last_write_time(dir + "/out/summary.json") == before);
#ifdef ARNOLDWEB_HAVE_CAIRO
    // with the plugin, the same directory gets its pictures
    CHECK(awtest::run_cli({"render", dir + "/out"}, &render_out) == 0);
    CHECK(fs::exists(dir + "/out/map.png"));
#endif
  }
}
