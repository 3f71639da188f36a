// Outputs: summary.json, map.h5, states.h5 and pictures hold what the run
// computed; output directories are refused, replaced or left alone as asked;
// a write that fails leaves no partial file.
#include <doctest/doctest.h>
#include <hdf5.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <nlohmann/json.hpp>

#include "aw_params.h"
#include "support.hpp"

#ifdef ARNOLDWEB_HAVE_CAIRO
#include <cairo.h>
#endif
#ifdef ARNOLDWEB_HAVE_CFITSIO
#include <fitsio.h>
#endif
#ifdef ARNOLDWEB_HAVE_HEALPIX_CXX
#include <healpix_map.h>
#include <healpix_map_fitsio.h>
#endif

using namespace arnoldweb;
namespace fs = std::filesystem;

namespace {

Plan small_plan(int nside = 16) {
  return make_plan(awtest::scene_from(R"(
    [ensemble]
    trajectories = 400
    [integrator]
    step = 0.02
    [run]
    average = 2
    duration = 2
    [observe]
    energy_error = { every = 1 }
    final_states = true
    initial_states = true
    zoom = { resolution = 32 }
  )", {awtest::set("observe.velocity_map.nside", nside)}, "<output>"));
}

const Result& small_result() {
  static const Result r = awtest::run_on("cpu", small_plan());
  return r;
}

std::vector<std::uint64_t> read_u64(const std::string& file, const char* dataset, std::int64_t* nside) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(f >= 0);
  hid_t d = H5Dopen2(f, dataset, H5P_DEFAULT);
  REQUIRE(d >= 0);
  hid_t space = H5Dget_space(d);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<std::uint64_t> v(static_cast<std::size_t>(n));
  CHECK(H5Dread(d, H5T_NATIVE_UINT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
  if (nside) {
    hid_t a = H5Aopen(d, "nside", H5P_DEFAULT);
    REQUIRE(a >= 0);
    H5Aread(a, H5T_NATIVE_INT64, nside);
    H5Aclose(a);
  }
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  return v;
}

bool has_temporaries(const fs::path& dir) {
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_SUITE("output") {
  TEST_CASE("summary.json records counts, energy error, digests, device and the scene") {
    const Plan p = small_plan();
    const Result& r = small_result();
    const auto j = nlohmann::json::parse(summary_json(p, r));
    CHECK(j["trajectories"] == 400);
    CHECK(j["binned"].get<std::uint64_t>() + j["flagged"]["total"].get<std::uint64_t>() == 400);
    CHECK(j["energy_error"]["max"].get<double>() == r.energy.max);
    CHECK(j["energy_error"]["mean"].get<double>() == r.energy.mean);
    CHECK(j["digests"]["map"] == digest_map(r));
    CHECK(j["digests"]["final_states"] == digest_records(r, "final_states"));
    CHECK(j["device"]["id"] == "cpu");
    CHECK(j["trajectory_steps_per_second"].get<double>() > 0);
    CHECK(j["scene"]["model"]["energy"] == 15.0);
    CHECK(j["scene_toml"].get<std::string>().find("[integrator]") != std::string::npos);
    CHECK(j["schedule"]["steps_per_trajectory"] == 100);
    CHECK(j["effects"].size() >= 4);
  }

  TEST_CASE("map.h5 and states.h5 hold the result, with nside and ordering") {
    const Plan p = small_plan();
    const Result& r = small_result();
    const std::string dir = awtest::temp_dir("h5") + "/out";
    const auto files = write_outputs(p, r, dir, {});
    std::int64_t nside = 0;
    CHECK(read_u64(dir + "/map.h5", "map", &nside) == r.map);
    CHECK(nside == 16);
    CHECK(read_u64(dir + "/map.h5", "zoom", nullptr) == r.zoom);
    // states: momenta of the final states
    hid_t f = H5Fopen((dir + "/states.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(f >= 0);
    hid_t d = H5Dopen2(f, "final/momentum", H5P_DEFAULT);
    std::vector<double> mom(400 * 3);
    CHECK(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, mom.data()) >= 0);
    H5Dclose(d);
    H5Fclose(f);
    CHECK(mom[3 * 7 + 2] == r.reals("final_states")[7 * AW_STATE_REALS + 5]);
    CHECK_FALSE(has_temporaries(dir));
    CHECK_FALSE(fs::exists(dir + ".partial-" + std::to_string(::getpid())));
  }

#ifdef ARNOLDWEB_HAVE_CFITSIO
  TEST_CASE("map.fits (output.formats) is a HEALPix FITS map: RING, NSIDE, the counts of map.h5, listed with its digest") {
    Plan p = small_plan();
    const Result& r = small_result();
    const std::string plain = awtest::temp_dir("fits") + "/out";
    write_outputs(p, r, plain, {});
    CHECK_FALSE(fs::exists(plain + "/map.fits"));  // only where asked for
    p.scene.formats = {"hdf5", "fits"};
    const std::string dir = awtest::temp_dir("fits") + "/out [1]";  // CFITSIO's syntax in a name means nothing
    write_outputs(p, r, dir, {});
    const std::string path = dir + "/map.fits";
    REQUIRE(fs::exists(path));
    CHECK_FALSE(has_temporaries(dir));
    fitsfile* f = nullptr;
    int status = 0;
    REQUIRE(fits_open_diskfile(&f, path.c_str(), READONLY, &status) == 0);
    int hdutype = 0;
    fits_movabs_hdu(f, 2, &hdutype, &status);
    CHECK(hdutype == BINARY_TBL);
    char text[FLEN_VALUE];
    auto word = [&](const char* key) {
      fits_read_key(f, TSTRING, key, text, nullptr, &status);
      return std::string(text);
    };
    CHECK(word("PIXTYPE") == "HEALPIX");
    CHECK(word("ORDERING") == "RING");
    CHECK(word("INDXSCHM") == "IMPLICIT");
    CHECK(word("MAPDIGST") == digest_map(r));
    long long nside = 0, last = 0, rows = 0;
    fits_read_key(f, TLONGLONG, "NSIDE", &nside, nullptr, &status);
    fits_read_key(f, TLONGLONG, "LASTPIX", &last, nullptr, &status);
    fits_get_num_rowsll(f, &rows, &status);
    CHECK(nside == 16);
    CHECK(rows == 12 * 16 * 16);
    CHECK(last == rows - 1);
    std::vector<long long> counts(static_cast<std::size_t>(rows));
    fits_read_col(f, TLONGLONG, 1, 1, 1, rows, nullptr, counts.data(), nullptr, &status);
    fits_close_file(f, &status);
    CHECK(status == 0);
    CHECK(std::vector<std::uint64_t>(counts.begin(), counts.end()) == r.map);
    const auto summary = nlohmann::json::parse(std::ifstream(dir + "/summary.json"));
    CHECK(summary["file_digests"]["map.fits"]["bytes"] == fs::file_size(path));
    CHECK(std::find(summary["files"].begin(), summary["files"].end(), "map.fits") != summary["files"].end());
#ifdef ARNOLDWEB_HAVE_HEALPIX_CXX
    // Debian's HEALPix C++ library reads it as a RING map of NSIDE 16 (from a plain name: it
    // opens files with CFITSIO's extended syntax, where "[1]" would name an extension)
    const std::string plain_copy = plain + "-map.fits";
    fs::copy_file(path, plain_copy);
    Healpix_Map<double> m;
    read_Healpix_map_from_fits(plain_copy, m);
    CHECK(m.Nside() == 16);
    CHECK(m.Scheme() == RING);
    CHECK(m[100] == static_cast<double>(r.map[100]));
#endif
  }
#else
  TEST_CASE("a build without CFITSIO refuses output.formats \"fits\" when the scene is read, naming the package") {
    CHECK_THROWS_WITH_AS(awtest::scene_from("", {"output.formats=[\"hdf5\", \"fits\"]"}),
                         doctest::Contains("libcfitsio-dev"), SceneError);
  }
#endif

#ifdef ARNOLDWEB_HAVE_CAIRO
  TEST_CASE("pictures are PNGs of the right size, not blank") {
    const Plan p = small_plan();
    const std::string dir = awtest::temp_dir("png") + "/out";
    write_outputs(p, small_result(), dir, {});
    for (const char* name : {"map.png", "map_mollweide.png", "map_resonances.png", "zoom.png"}) {
      CAPTURE(name);
      cairo_surface_t* s = cairo_image_surface_create_from_png((dir + "/" + name).c_str());
      REQUIRE(cairo_surface_status(s) == CAIRO_STATUS_SUCCESS);
      CHECK(cairo_image_surface_get_width(s) == 900);
      const unsigned char* data = cairo_image_surface_get_data(s);
      const int stride = cairo_image_surface_get_stride(s);
      std::set<std::uint32_t> colours;
      for (int y = 0; y < cairo_image_surface_get_height(s); y += 7)
        for (int x = 0; x < 900; x += 7) colours.insert(*reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x));
      CHECK(colours.size() > 20);
      cairo_surface_destroy(s);
    }
  }
#endif

#ifdef ARNOLDWEB_HAVE_CAIRO
  TEST_CASE("render_saved draws the pictures of a saved run from summary.json and map.h5") {
    const Plan p = small_plan();
    const std::string dir = awtest::temp_dir("saved") + "/out";
    write_outputs(p, small_result(), dir, {});
    for (const char* name : {"map.png", "zoom.png"}) fs::remove(dir + "/" + name);
    const auto files = render_saved(dir);
    CHECK(fs::exists(dir + "/map.png"));
    CHECK(fs::exists(dir + "/zoom.png"));
    CHECK(files.size() >= 4);
    CHECK_THROWS_AS(render_saved(dir + "/nothing-here"), OutputError);
  }
#endif

  TEST_CASE("read_saved_maps gives back the maps of an output directory, or names what is missing") {
    const Plan p = small_plan();
    const Result& r = small_result();
    const std::string dir = awtest::temp_dir("saved-maps") + "/out";
    write_outputs(p, r, dir, {});
    const SavedMaps s = read_saved_maps(dir);
    CHECK(s.map == r.map);
    CHECK(s.nside == 16);
    CHECK(s.zoom == r.zoom);
    CHECK(s.zoom_resolution == 32);
    CHECK(s.frames.empty());
    CHECK(s.trajectories == 400);
    CHECK(s.binned == r.binned);
    CHECK(s.seed == std::optional<std::uint64_t>(p.scene.seed));
    CHECK(s.map_file == dir + "/map.h5");
    CHECK_THROWS_WITH_AS(read_saved_maps(dir + "/nothing-here"), doctest::Contains("nothing-here: no such directory"),
                         OutputError);
    const std::string missing = dir + "/map.h5: missing", broken = dir + "/map.h5: it is 8 bytes, but summary.json",
                      no_summary = dir + "/summary.json: cannot read it";
    fs::remove(dir + "/map.h5");
    CHECK_THROWS_WITH_AS(read_saved_maps(dir), doctest::Contains(missing.c_str()), SavedRunError);
    std::ofstream(dir + "/map.h5") << "not HDF5";
    CHECK_THROWS_WITH_AS(read_saved_maps(dir), doctest::Contains(broken.c_str()), SavedRunError);
    fs::remove(dir + "/summary.json");
    CHECK_THROWS_WITH_AS(read_saved_maps(dir), doctest::Contains(no_summary.c_str()), SavedRunError);
  }

  TEST_CASE("an existing output directory is refused without force; with it only arnoldweb's own is replaced") {
    const Plan p = small_plan();
    OutputOptions force;
    force.force = true;
    const std::string dir = awtest::temp_dir("exists") + "/out";
    fs::create_directories(dir);
    std::ofstream(dir + "/keep.txt") << "old";
    CHECK_THROWS_AS(write_outputs(p, small_result(), dir, {}), OutputError);
    // a directory that arnoldweb did not write is never replaced (exit 2)
    CHECK_THROWS_WITH_AS(write_outputs(p, small_result(), dir, force), doctest::Contains("written by arnoldweb"),
                         OutputRefused);
    CHECK(fs::exists(dir + "/keep.txt"));
    CHECK_FALSE(fs::exists(dir + "/summary.json"));
    // an earlier run's directory is replaced
    const std::string ours = awtest::temp_dir("exists") + "/ours";
    write_outputs(p, small_result(), ours, {});
    const auto listed = nlohmann::json::parse(std::ifstream(ours + "/summary.json"))["files"];
    CHECK(listed.size() >= 2);
    for (const auto& f : listed) CHECK(fs::exists(ours + "/" + f.get<std::string>()));
    // (a file this build writes: map.png only where cairo is built in)
    std::string older;
    for (const auto& f : listed)
      if (f.get<std::string>() != "summary.json") older = f.get<std::string>();
    REQUIRE_FALSE(older.empty());
    write_outputs(p, small_result(), ours, force);
    CHECK(fs::file_size(ours + "/" + older) > 100);
    // a file changed since the run wrote it is no longer the run's: its digest in summary.json
    // does not match, and --force leaves it, and the directory, alone (issue 37, item 8)
    std::ofstream(ours + "/" + older) << "an older file";
    const std::string changed = older + " (changed since the run wrote it)";
    CHECK_THROWS_WITH_AS(write_outputs(p, small_result(), ours, force), doctest::Contains(changed.c_str()),
                         OutputRefused);
    CHECK(fs::file_size(ours + "/" + older) == 13);
    fs::remove(ours + "/" + older);
    write_outputs(p, small_result(), ours, force);
    CHECK(fs::file_size(ours + "/" + older) > 100);
    // ... but not after the user put a file of their own into it
    std::ofstream(ours + "/notes.txt") << "mine";
    CHECK_THROWS_WITH_AS(write_outputs(p, small_result(), ours, force), doctest::Contains("notes.txt"),
                         OutputRefused);
    CHECK(fs::exists(ours + "/notes.txt"));
    CHECK(fs::exists(ours + "/summary.json"));
  }

  TEST_CASE("a write that fails (full disk) leaves no partial file and keeps what was complete") {
    // a file-size limit makes writes fail as a full disk would (EFBIG)
    const Plan p = small_plan(128);
    const Result r = awtest::run_on("cpu", p);
    // the limit lies between the sizes of summary.json and map.h5
    const std::string probe = awtest::temp_dir("probe") + "/out";
    write_outputs(p, r, probe, {});
    const auto summary_size = fs::file_size(probe + "/summary.json");
    const auto map_size = fs::file_size(probe + "/map.h5");
    REQUIRE(map_size > summary_size + 1024);
    const rlim_t limit = static_cast<rlim_t>((summary_size + map_size) / 2);
    const std::string dir = awtest::temp_dir("full") + "/out";
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      std::signal(SIGXFSZ, SIG_IGN);
      rlimit lim{limit, limit};
      setrlimit(RLIMIT_FSIZE, &lim);
      try {
        write_outputs(p, r, dir, {});
      } catch (const OutputError&) {
        _exit(3);
      }
      _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 3);
    // nothing half-written in place; what was complete is kept under a name of its own
    CHECK_FALSE(fs::exists(dir));
    const std::string kept = dir + ".incomplete-" + std::to_string(child);
    CHECK(fs::exists(kept + "/summary.json"));
    CHECK_FALSE(fs::exists(kept + "/map.h5"));  // failed: no partial file
    CHECK_FALSE(has_temporaries(fs::path(kept)));
    for (const auto& e : fs::directory_iterator(fs::path(dir).parent_path()))
      CHECK(e.path().filename().string().find(".partial-") == std::string::npos);
  }

  TEST_CASE("missing parent directories are made; an impossible place is refused before any work") {
    const std::string file = awtest::temp_dir("parents") + "/a-file";
    std::ofstream(file) << "not a directory";
    CHECK_THROWS_WITH_AS(check_output_dir(file + "/x/out", {}), doctest::Contains("is not a directory"), OutputError);
    const std::string dir = awtest::temp_dir("parents") + "/a/b/out";
    CHECK_NOTHROW(check_output_dir(dir, {}));
    CHECK_FALSE(fs::exists(fs::path(dir).parent_path()));  // nothing made before the run
    write_outputs(small_plan(), small_result(), dir, {});
    CHECK(fs::exists(dir + "/summary.json"));
  }
}
