// Reliability: what arnoldweb reads back (issue 27, items 1-5 and 11; issue
// 37, item 1: HDF5 files that lead out of themselves). Every
// file of an output directory has its size and XXH3-128 digest in
// summary.json; render and compare read summary.json and map.h5 as plain files
// without blocking, check the JSON's form, every file's digest and the shapes
// summary.json declares, and refuse anything else with exit 2 naming the file.
// Each case failed before the fix it guards (ARNOLDWEB_TEST_CLI=<old build>).
#include <doctest/doctest.h>
#include <sys/stat.h>
#include <xxhash.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "h5_test_file.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

json summary_of(const std::string& dir) { return json::parse(slurp(dir + "/summary.json")); }
void write_summary(const std::string& dir, const json& j) { std::ofstream(dir + "/summary.json") << j.dump(2); }

// A small run (nside 8, as in the issue) into dir/name.
std::string saved_run(const std::string& dir, const std::string& name, int seed, const std::string& extra = "") {
  const std::string scene = dir + "/scene.toml";
  std::ofstream(scene) << "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 2000\n[integrator]\nstep = 0.02\n"
                          "[run]\naverage = 1.0\nduration = 1.0\n[observe]\nvelocity_map = { nside = 8 }\n"
                          "energy_error = false\n[output]\nimages = false\n"
                       << extra;
  const std::string out = dir + "/" + name;
  std::string text;
  const int rc = awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", out, "--set",
                                  "ensemble.seed=" + std::to_string(seed)},
                                 &text);
  CAPTURE(text);
  REQUIRE(rc == 0);
  return out;
}

// A copy of a saved run to damage.
std::string copy_of(const std::string& dir, const std::string& name) {
  const std::string to = fs::path(dir).parent_path().string() + "/" + name;
  fs::remove_all(to);
  fs::copy(dir, to, fs::copy_options::recursive);
  return to;
}

// The CLI with a deadline (a read that blocks is a failure, not a hang of
// the test): its exit code, -2 if it was still running after `seconds`.
int run_within(const std::vector<std::string>& args, double seconds, std::string* out) {
  awtest::StartedCli cli = awtest::start_cli(args);
  const int rc = cli.finish_within(seconds);
  *out = cli.output;
  return rc;
}

// render and compare of a damaged directory: both exit 2 in a few seconds,
// naming `names` (the file) in the message.
void both_refuse(const std::string& damaged, const std::string& other, const std::string& names) {
  std::string out;
#ifdef ARNOLDWEB_HAVE_CAIRO
  CHECK(run_within({"render", damaged}, 20, &out) == 2);
  CAPTURE(out);
  CHECK(contains(out, names));
  CHECK_FALSE(contains(out, "unexpected error"));
#endif
  CHECK(run_within({"compare", damaged, other}, 20, &out) == 2);
  CAPTURE(out);
  CHECK(contains(out, names));
  CHECK_FALSE(contains(out, "unexpected error"));
}

std::string hex128(const std::string& bytes) {
  const XXH128_hash_t h = XXH3_128bits(bytes.data(), bytes.size());
  char buf[33];
  std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                static_cast<unsigned long long>(h.low64));
  return buf;
}

// A copy of the saved run `a` ("bad") whose map.h5 `write` makes, with its digest recorded in
// summary.json (as a copied directory would have it), or, `older`, without file_digests.
std::string with_map(const std::string& a, bool older, const std::function<void(const std::string&)>& write) {
  const std::string bad = copy_of(a, "bad");
  fs::remove(bad + "/map.h5");
  write(bad + "/map.h5");
  json j = summary_of(bad);
  if (older) {
    j.erase("file_digests");
  } else {
    const std::string bytes = slurp(bad + "/map.h5");
    j["file_digests"]["map.h5"] = {{"bytes", bytes.size()}, {"xxh3_128", hex128(bytes)}};
  }
  write_summary(bad, j);
  return bad;
}

// Every file under `dir` but summary.json is in its file_digests with its
// size and the XXH3-128 of its bytes, and nothing else is.
void digests_match(const std::string& dir) {
  const json j = summary_of(dir);
  REQUIRE(j.contains("file_digests"));
  const json& d = j["file_digests"];
  std::size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string rel = fs::relative(e.path(), dir).string();
    if (rel == "summary.json") continue;
    CAPTURE(rel);
    ++files;
    REQUIRE(d.contains(rel));
    const std::string bytes = slurp(e.path().string());
    CHECK(d[rel]["bytes"].get<std::uint64_t>() == bytes.size());
    CHECK(d[rel]["xxh3_128"].get<std::string>() == hex128(bytes));
  }
  CHECK(d.size() == files);
}

}  // namespace

TEST_SUITE("reliability") {
  TEST_CASE("1. a summary.json that declares another nside than map.h5 holds is refused, never read past the map") {
    const std::string dir = awtest::temp_dir("nside");
    const std::string a = saved_run(dir, "a", 1), b = saved_run(dir, "b", 2);
    for (const int nside : {1024, 16, 4}) {
      CAPTURE(nside);
      // the scene as run (what render plans the pictures with)
      const std::string scene_edit = copy_of(a, "scene-edit");
      json j = summary_of(scene_edit);
      std::string toml = j["scene_toml"];
      toml.replace(toml.find("nside = 8"), 9, "nside = " + std::to_string(nside));
      j["scene_toml"] = toml;
      write_summary(scene_edit, j);
#ifdef ARNOLDWEB_HAVE_CAIRO
      std::string out;
      CHECK(run_within({"render", scene_edit}, 20, &out) == 2);  // SIGSEGV (nside 1024), exit 0 (16) before
      CAPTURE(out);
      CHECK(contains(out, scene_edit + "/summary.json"));
      CHECK(contains(out, "observe.velocity_map.nside = " + std::to_string(nside)));
#endif
      // the maps record
      const std::string maps_edit = copy_of(a, "maps-edit");
      j = summary_of(maps_edit);
      j["maps"]["nside"] = nside;
      write_summary(maps_edit, j);
      both_refuse(maps_edit, b, "nside");
    }
  }

  TEST_CASE("2. a summary.json of the wrong form is exit 2 naming it, from render and compare alike") {
    const std::string dir = awtest::temp_dir("form");
    const std::string a = saved_run(dir, "a", 1), b = saved_run(dir, "b", 2);
    const json good = summary_of(a);
    std::vector<std::pair<std::string, json>> cases = {{"[]", json::array()}, {"null", nullptr}, {"5", 5}};
    json j = good;
    j["trajectories"] = "many";
    cases.push_back({"trajectories a string", j});
    j = good;
    j["maps"] = json::array({8});
    cases.push_back({"maps a list", j});
    j = good;
    j["file_digests"]["map.h5"]["bytes"] = -1;
    cases.push_back({"a negative size", j});
    j = good;
    j["scene_toml"] = 15;
    cases.push_back({"scene_toml a number", j});
    for (const auto& c : cases) {
      const std::string& what = c.first;  // (clang 14 cannot capture a structured binding in CAPTURE)
      CAPTURE(what);
      const std::string bad = copy_of(a, "bad");
      write_summary(bad, c.second);
      both_refuse(bad, b, bad + "/summary.json");  // render: "unexpected error" (exit 1) before
    }
    const std::string not_json = copy_of(a, "not-json");
    std::ofstream(not_json + "/summary.json") << "{ \"arnoldweb\": ";
    both_refuse(not_json, b, "not valid JSON");
  }

  TEST_CASE("3. FIFOs, devices and kernel files in place of what is read are refused without blocking") {
    const std::string dir = awtest::temp_dir("fifo");
    const std::string a = saved_run(dir, "a", 1), b = saved_run(dir, "b", 2);
    for (const std::string name : {"map.h5", "summary.json"}) {
      CAPTURE(name);
      const std::string bad = copy_of(a, "fifo");
      fs::remove(bad + "/" + name);
      REQUIRE(mkfifo((bad + "/" + name).c_str(), 0600) == 0);
      both_refuse(bad, b, bad + "/" + name + ": cannot read it: it is a pipe (FIFO)");  // blocked for ever before
      const std::string dev = copy_of(a, "device");
      fs::remove(dev + "/" + name);
      fs::create_symlink("/dev/zero", dev + "/" + name);
      both_refuse(dev, b, "it is a device");
    }
    // a scene: /proc/kmsg blocked for ever (as root; others may not open it at all)
    std::string out;
    CHECK(run_within({"check", "/proc/kmsg"}, 20, &out) == 2);
    CAPTURE(out);
    CHECK(contains(out, "/proc/kmsg: cannot read the scene file"));
    CHECK(run_within({"check", "/proc/self/status"}, 20, &out) == 2);
    CHECK(contains(out, "a file of the kernel"));
  }

  TEST_CASE("4. flipped bytes, a map.h5 of another run, a grown file: refused by their digest, naming the file") {
    const std::string dir = awtest::temp_dir("digest");
    const std::string a = saved_run(dir, "a", 1), b = saved_run(dir, "b", 2);
    const std::string flipped = copy_of(a, "flipped");
    {
      std::fstream f(flipped + "/map.h5", std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(static_cast<std::streamoff>(fs::file_size(flipped + "/map.h5") / 2));
      f.put('\x5a');
    }
    both_refuse(flipped, b, flipped + "/map.h5: its XXH3-128 digest is");  // rendered and compared before
    const std::string swapped = copy_of(a, "swapped");
    fs::copy_file(b + "/map.h5", swapped + "/map.h5", fs::copy_options::overwrite_existing);
    both_refuse(swapped, b, swapped + "/map.h5");
    const std::string grown = copy_of(a, "grown");
    std::ofstream(grown + "/map.h5", std::ios::app | std::ios::binary) << "more";
    both_refuse(grown, b, "bytes, but summary.json records");
    // an intact pair still compares (exit 0 or 1: a statistical answer)
    std::string out;
    const int rc = run_within({"compare", a, b}, 60, &out);
    CAPTURE(out);
    CHECK((rc == 0 || rc == 1));
  }

  TEST_CASE("5. every file of an output directory has its size and digest in summary.json, render keeps them") {
    const std::string dir = awtest::temp_dir("every");
    // a map, frames, a zoom, final states, indicators, pictures and a panel
    const std::string a = saved_run(dir, "a", 1,
                                    "[ensemble.grid]\nkind = \"healpix\"\nnside = 4\n"
                                    "[[panel]]\nname = \"p\"\nset = [\"model.energy=16\"]\n");
    std::string out;
    const std::string scene = dir + "/scene.toml";
    const std::string full = dir + "/full";
    const int rc = awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", full, "--set",
                                    "ensemble.initial=\"grid\"", "--set", "ensemble.trajectories=192", "--set",
                                    "run.duration=2.0", "--set",
                                    "observe.frames.times=[0,1,2]", "--set", "observe.zoom.resolution=16", "--set",
                                    "observe.final_states=true", "--set", "observe.fli=true", "--set",
                                    "output.images=true"},
                                   &out);
    CAPTURE(out);
    REQUIRE(rc == 0);
    const json j = summary_of(full);
    CHECK(j["file_digests"].contains("indicators.h5"));  // none before (only the data digests)
    CHECK(j["file_digests"].contains("states.h5"));
    CHECK(j["file_digests"].contains("panel-p/summary.json"));
    CHECK(j["files"].size() == j["file_digests"].size());  // the list older code reads is still there
    digests_match(full);
    digests_match(full + "/panel-p");
    digests_match(a);
#ifdef ARNOLDWEB_HAVE_CAIRO
    // render redraws the pictures (new bytes) and records their digests: it reads back checked again
    CHECK(run_within({"render", full}, 120, &out) == 0);
    digests_match(full);
    digests_match(full + "/panel-p");
    CHECK(run_within({"render", full}, 120, &out) == 0);
    CHECK_FALSE(contains(out, "note"));
#endif
  }

  TEST_CASE("11. one exit code for a missing or damaged input: render and compare both exit 2") {
    const std::string dir = awtest::temp_dir("exit");
    const std::string a = saved_run(dir, "a", 1), b = saved_run(dir, "b", 2);
    for (const std::string name : {"summary.json", "map.h5"}) {
      CAPTURE(name);
      const std::string missing = copy_of(a, "missing");
      fs::remove(missing + "/" + name);
      both_refuse(missing, b, missing + "/" + name);  // render: exit 3 before
      const std::string empty = copy_of(a, "empty");
      std::ofstream(empty + "/" + name, std::ios::trunc);
      both_refuse(empty, b, empty + "/" + name);
    }
    both_refuse(dir + "/nothing-here", b, dir + "/nothing-here: no such directory");
  }

  TEST_CASE("4. a directory written before the digests is read, with a note that its files were not checked") {
    const std::string dir = awtest::temp_dir("older");
    const std::string a = saved_run(dir, "a", 1), b = saved_run(dir, "b", 2);
    json j = summary_of(a);
    j.erase("file_digests");
    write_summary(a, j);
    std::string out;
    const int rc = run_within({"compare", a, b}, 60, &out);
    CAPTURE(out);
    CHECK((rc == 0 || rc == 1));
    CHECK(contains(out, "note: " + a + "/summary.json records no file digests"));
#ifdef ARNOLDWEB_HAVE_CAIRO
    CHECK(run_within({"render", a}, 60, &out) == 0);
    CHECK(contains(out, "records no file digests"));
    CHECK_FALSE(summary_of(a).contains("file_digests"));  // render does not pretend it was checked
#endif
  }

  TEST_CASE("12. a map.h5 whose data leads out of the file (to a FIFO) is refused before any read, in bounded time") {
    const std::string dir = awtest::temp_dir("map-out");
    const std::string a = saved_run(dir, "a", 1), b = saved_run(dir, "b", 2);
    const std::string fifo = dir + "/fifo.h5";
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const hsize_t npix = 12 * 8 * 8;
    struct Case {
      std::string name, says;
      std::function<void(awtest::H5TestFile&)> write;
    };
    const std::vector<Case> cases = {
        {"external-link", "/map is an external link to " + fifo + ":/map",
         [&](awtest::H5TestFile& f) { f.external_link("map", fifo, "/map"); }},
        {"external-storage", "/map stores its data in the external file " + fifo,
         [&](awtest::H5TestFile& f) {
           const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
           REQUIRE(H5Pset_external(dcpl, fifo.c_str(), 0, npix * 8) >= 0);
           f.dataset<std::uint64_t>("map", {}, {npix}, H5T_STD_U64LE, dcpl);
           H5Pclose(dcpl);
         }},
        {"virtual", "/map is a virtual dataset",
         [&](awtest::H5TestFile& f) { f.virtual_dataset("map", 4, fifo, true); }},
        {"unwritten", "/map declares 768 values (6144 bytes) and stores 0 bytes",
         [&](awtest::H5TestFile& f) { f.dataset<std::uint64_t>("map", {}, {npix}, H5T_STD_U64LE); }},
    };
    for (const Case& c : cases) {
      CAPTURE(c.name);
      // with a summary.json that records the crafted file's digest, and an older one without digests
      for (const bool older : {false, true}) {
        CAPTURE(older);
        const std::string bad = with_map(a, older, [&](const std::string& map) {
          awtest::H5TestFile f(map);
          c.write(f);
        });
        both_refuse(bad, b, bad + "/map.h5: " + c.says);  // blocked for ever on the FIFO before (or read fill values)
      }
    }
  }

  TEST_CASE("14. a map.h5 on which HDF5 itself crashes is refused naming it; the reader's process goes on" *
            doctest::skip(awtest::kSanitized)) {
    // tests/fuzz/hdf5-defects/local-heap-null-read: HDF5 1.10.8 reads through a null pointer at the
    // first lookup of a name (SIGSEGV: render and compare ended with exit 139 before HDF5 was read
    // in a child process, os/isolated.hpp)
    const std::string dir = awtest::temp_dir("map-crash");
    const std::string a = saved_run(dir, "a", 1), b = saved_run(dir, "b", 2);
    const std::string defect = std::string(ARNOLDWEB_SOURCE_DIR) + "/tests/fuzz/hdf5-defects/local-heap-null-read";
    for (const bool older : {false, true}) {
      CAPTURE(older);
      const std::string bad = with_map(a, older, [&](const std::string& map) { fs::copy_file(defect, map); });
      both_refuse(bad, b, bad + "/map.h5: HDF5 could not read it: its reader (a child process) killed by signal");
      // in this process (Python's reader): an error to catch, not the end of the session
      CHECK_THROWS_WITH_AS(arnoldweb::read_saved_maps(bad), doctest::Contains("HDF5 could not read it"),
                           arnoldweb::SavedRunError);
    }
    // the file handed to h5py (arnoldweb.load): walked whole in a child too
    const std::string bad = copy_of(a, "bad-load");
    fs::copy_file(defect, bad + "/extra.h5");
    const std::string bytes = slurp(bad + "/extra.h5");
    json j = summary_of(bad);
    j["file_digests"]["extra.h5"] = {{"bytes", bytes.size()}, {"xxh3_128", hex128(bytes)}};
    write_summary(bad, j);
    CHECK_THROWS_WITH_AS(arnoldweb::read_saved_hdf5_file(bad, "extra.h5"), doctest::Contains("extra.h5: HDF5 could not read it"),
                         arnoldweb::SavedRunError);
    CHECK(arnoldweb::read_saved_maps(a).map.size() == 12 * 8 * 8);  // and the good one still reads
  }

  TEST_CASE("13. the HDF5 files that arnoldweb.load hands to h5py are checked by the same policy") {
    const std::string dir = awtest::temp_dir("load-out");
    const std::string scene = dir + "/scene.toml";
    const std::string a = saved_run(dir, "a", 1);
    std::string out;
    REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", dir + "/s", "--set",
                             "observe.final_states=true"},
                            &out) == 0);
    const std::string good = arnoldweb::read_saved_hdf5_file(dir + "/s", "states.h5");
    CHECK(good == slurp(dir + "/s/states.h5"));
    // a states.h5 with an external link, its digest recorded (as a copied directory would have it)
    const std::string fifo = dir + "/fifo.h5";
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    fs::remove(dir + "/s/states.h5");
    {
      awtest::H5TestFile f(dir + "/s/states.h5");
      f.group("/final");
      f.external_link("/final/momentum", fifo);
    }
    const std::string bytes = slurp(dir + "/s/states.h5");
    json j = summary_of(dir + "/s");
    j["file_digests"]["states.h5"] = {{"bytes", bytes.size()}, {"xxh3_128", hex128(bytes)}};
    write_summary(dir + "/s", j);
    CHECK(arnoldweb::read_saved_file(dir + "/s", "states.h5") == bytes);  // the bytes, checked by digest only
    const std::string link = "states.h5: /final/momentum is an external link to " + fifo;
    CHECK_THROWS_WITH_AS(arnoldweb::read_saved_hdf5_file(dir + "/s", "states.h5"), doctest::Contains(link.c_str()),
                         arnoldweb::SavedRunError);
    // and continue, which reads the same file as states
    CHECK(run_within({"continue", dir + "/s", "--for", "1", "--quiet"}, 60, &out) == 2);
    CAPTURE(out);
    CHECK(contains(out, "/final/momentum: is an external link"));
  }
}
