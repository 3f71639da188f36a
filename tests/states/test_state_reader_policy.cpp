// State files as an outside campaign wrote them (issue 37, items 1-6), read by
// the one HDF5 reader (lib/src/output/h5_reader.hpp): links, storage and
// virtual datasets that lead out of the file are refused before any read (a
// FIFO behind them hung check before), row counts are compared across all
// datasets (a short status was read past its end), what h5py writes by
// default is read and its errors named, windings and times are range-checked,
// a file that declares more than it stores is refused without allocating it,
// and a run's states.h5 is checked against its summary.json as `continue`
// checks it. Files are made here with the HDF5 C API; each case failed before.
#include <doctest/doctest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>

#include "arnoldweb/arnoldweb.hpp"
#include "h5_test_file.hpp"
#include "support.hpp"

using namespace arnoldweb;
namespace fs = std::filesystem;

namespace {

const std::string kScene =
    "[model]\nenergy = 15.0\n[ensemble]\nseed = 5\n[integrator]\nstep = 0.02\n"
    "[run]\naverage = 1.0\nduration = 1.0\n[observe]\nvelocity_map = { nside = 4 }\nenergy_error = false\n"
    "[output]\nimages = false\n";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// n states at E = 15 of the paper's model, H = |P|^2/2 + cos x cos y (1 + cos 2z): at X = 0,
// V = 2 and |P| = sqrt(26), in the direction angle k of the (p_x, p_y) plane.
struct States {
  std::vector<double> x, p;  // 3 per state: position in turns, momentum
};
States simple_states(std::size_t n) {
  States s;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 0.7 * static_cast<double>(k), r = std::sqrt(26.0);
    s.x.insert(s.x.end(), {0.0, 0.0, 0.0});
    s.p.insert(s.p.end(), {r * std::cos(a), r * std::sin(a), 0.0});
  }
  return s;
}

StateError error_of(const std::string& path) {
  try {
    read_state_file(path);
  } catch (const StateError& e) {
    return e;
  }
  FAIL("no StateError for " << path);
  return StateError("", "", -1, "");
}

std::string scene_file(const std::string& dir) {
  std::ofstream(dir + "/scene.toml") << kScene;
  return dir + "/scene.toml";
}

// `arnoldweb check` of kScene with the states of `file`, within `seconds` (-2: still running).
int check_within(const std::string& dir, const std::string& file, double seconds, std::string* out) {
  awtest::StartedCli cli = awtest::start_cli({"check", scene_file(dir), "--set", "ensemble.initial=file", "--set",
                                              "ensemble.file=" + file});
  const int rc = cli.finish_within(seconds);
  *out = cli.output;
  return rc;
}

// `check` of a copy of tests/fuzz/hdf5-defects/<file> as a state file: exit 2 within 60 s; what it
// printed, from the copy's path on.
std::string check_defect(const std::string& file) {
  const std::string dir = awtest::temp_dir("states-defect");
  const std::string path = dir + "/" + file + ".h5";
  fs::copy_file(std::string(ARNOLDWEB_SOURCE_DIR) + "/tests/fuzz/hdf5-defects/" + file, path);
  std::string out;
  CHECK(check_within(dir, path, 60, &out) == 2);
  const std::size_t at = out.find(path);
  return at == std::string::npos ? out : out.substr(at + path.size());
}

}  // namespace

TEST_SUITE("states") {
  TEST_CASE("1. links, external storage and virtual datasets that lead out of the file are refused before any read") {
    const std::string dir = awtest::temp_dir("states-out");
    const std::string fifo = dir + "/fifo.h5";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);  // a read of it blocks until a writer comes: never
    const States s = simple_states(8);
    struct Case {
      std::string name, says;
      std::function<void(awtest::H5TestFile&)> write;
    };
    const std::vector<Case> cases = {
        {"external-link", "/momentum: is an external link to " + fifo + ":/momentum",
         [&](awtest::H5TestFile& f) {
           f.reals("position_turns", s.x);
           f.external_link("momentum", fifo);
         }},
        {"external-group", "/final: is an external link to " + fifo + ":/final",
         [&](awtest::H5TestFile& f) { f.external_link("final", fifo, "/final"); }},
        {"external-storage", "/momentum: stores its data in the external file " + fifo,
         [&](awtest::H5TestFile& f) {
           f.reals("position_turns", s.x);
           f.external_storage("momentum", 8, fifo);
         }},
        {"virtual", "/momentum: is a virtual dataset",
         [&](awtest::H5TestFile& f) {
           f.reals("position_turns", s.x);
           f.virtual_dataset("momentum", 8, fifo, false);
         }},
        {"virtual-unlimited", "/momentum: is a virtual dataset",
         [&](awtest::H5TestFile& f) {
           f.reals("position_turns", s.x);
           f.virtual_dataset("momentum", 8, fifo, true);
         }},
        // a soft link to an external one is the external link
        {"soft-to-external", "/elsewhere: is an external link to " + fifo + ":/momentum",
         [&](awtest::H5TestFile& f) {
           f.reals("position_turns", s.x);
           f.external_link("elsewhere", fifo);
           REQUIRE(H5Lcreate_soft("/elsewhere", f.id(), "momentum", H5P_DEFAULT, H5P_DEFAULT) >= 0);
         }},
    };
    for (const Case& c : cases) {
      CAPTURE(c.name);
      const std::string path = dir + "/" + c.name + ".h5";
      {
        awtest::H5TestFile f(path);
        c.write(f);
      }
      std::string out;
      CHECK(check_within(dir, path, 60, &out) == 2);  // before: blocked for ever on the FIFO (or ran)
      CAPTURE(out);
      CHECK(contains(out, path + ": " + c.says));
      CHECK(contains(out, "docs/reliability.md"));
      // and the same in this process (nothing blocks: the refusal comes first)
      const StateError e = error_of(path);
      CHECK(e.exit_code() == 2);
      CHECK(contains(e.what(), c.says));
    }
    // a link that leads out but is not on the way to what is read is never followed: the states are read
    const std::string beside = dir + "/external-beside.h5";
    {
      awtest::H5TestFile f(beside);
      f.reals("position_turns", s.x);
      f.reals("momentum", s.p);
      f.external_link("notes", fifo);
    }
    std::string out;
    CHECK(check_within(dir, beside, 60, &out) == 0);
    CHECK(read_state_file(beside).count == 8);
  }

  TEST_CASE("1. HDF5 1.10.8's defects on damaged heaps, on which it never ends: refused before HDF5 reads the file") {
    // the fuzzers' reproducers (tests/fuzz/hdf5-defects/), each read by `check` as a state file
    // a free-space object of size 0: `check` blocked on it before
    CHECK(contains(check_defect("global-heap-size-0"),
                   ": holds a global heap collection at byte 2056 whose object 0 has a size (0) on which HDF5 "
                   "1.10.8 loops for ever (a damaged file)"));
    // a mutated map.h5 of the saved-run fuzzer (the heap's only free block names itself as the next):
    // HDF5 took 2 GB in 6 s at the first lookup of a name before
    CHECK(contains(check_defect("local-heap-free-list-cycle"),
                   ": holds a local heap at byte 680 whose free list returns to its block at offset 16: HDF5 "
                   "1.10.8 would take memory for ever reading it (a damaged file)"));
  }

  // Under ASan the child's crash is a sanitizer's report (in check-sanitizers.sh's log directory,
  // which fails the check): the plain build's suite runs this case.
  TEST_CASE("1. a damaged symbol table on which HDF5 1.10.8 reads through a null pointer: refused, not a crash" *
            doctest::skip(awtest::kSanitized)) {
    // a SIGSEGV in H5F__accum_read at the first lookup of a name: exit 139 before HDF5 read state
    // files in a child process (os/isolated.hpp)
    CHECK(contains(check_defect("local-heap-null-read"),
                   ": HDF5 could not read it: its reader (a child process) killed by signal 11"));
    const std::string dir = awtest::temp_dir("states-null-read");
    const std::string path = dir + "/null.h5";
    fs::copy_file(std::string(ARNOLDWEB_SOURCE_DIR) + "/tests/fuzz/hdf5-defects/local-heap-null-read", path);
    // the library's caller (Python) gets an error to catch, and goes on
    CHECK_THROWS_WITH_AS(read_state_file(path), doctest::Contains("HDF5 could not read it"), arnoldweb::StateError);
    const States good = simple_states(8);
    {
      awtest::H5TestFile f(dir + "/good.h5");
      f.reals("position_turns", good.x);
      f.reals("momentum", good.p);
    }
    const arnoldweb::StateSet read = read_state_file(dir + "/good.h5");  // read in a child, then here
    CHECK(read.count == 8);
    CHECK(read.momentum == good.p);
    CHECK(read.status == std::vector<std::int64_t>(8, 0));
    CHECK(read.source == dir + "/good.h5");
  }

  TEST_CASE("2. every dataset's row count is compared with the others, before anything is read") {
    const std::string dir = awtest::temp_dir("states-rows");
    const States s = simple_states(4), twice = simple_states(8);
    struct Case {
      std::string name, dataset, says;
      std::function<void(awtest::H5TestFile&)> write;
    };
    const std::vector<Case> cases = {
        // fewer status rows than states: read past the end of the status before (valgrind)
        {"short-status", "/status", "has 2 rows and /momentum 4",
         [&](awtest::H5TestFile& f) {
           f.reals("position_turns", s.x);
           f.reals("momentum", s.p);
           f.ints("status", {0, 0}, false);
         }},
        // status and positions of 2N rows with momenta of N: accepted before
        {"double-status-positions", "/status", "has 8 rows and /momentum 4",
         [&](awtest::H5TestFile& f) {
           f.reals("position_turns", twice.x);
           f.reals("momentum", s.p);
           f.ints("status", std::vector<std::int64_t>(8, 0), false);
         }},
        {"long-winding", "/winding", "has 8 rows and /momentum 4",
         [&](awtest::H5TestFile& f) {
           f.reals("position_turns", s.x);
           f.reals("momentum", s.p);
           f.ints("winding", std::vector<std::int64_t>(24, 0));
         }},
    };
    for (const Case& c : cases) {
      CAPTURE(c.name);
      const std::string path = dir + "/" + c.name + ".h5";
      {
        awtest::H5TestFile f(path);
        c.write(f);
      }
      const StateError e = error_of(path);
      const std::string what = e.what();
      CAPTURE(what);
      CHECK(e.dataset() == c.dataset);
      CHECK(e.row() == -1);
      CHECK(contains(e.what(), c.says));
      // no heap address (a status read past its end printed one); the message after the file's name,
      // since the test's temporary directory has a random name that may hold "0x" itself
      const std::string message = what.rfind(path, 0) == 0 ? what.substr(path.size()) : what;
      CHECK_FALSE(contains(message, "0x"));
    }
  }

  TEST_CASE("3. what h5py writes by default: a variable-length UTF-8 units, and the real problem named") {
    const std::string dir = awtest::temp_dir("states-h5py");
    const States s = simple_states(4);
    std::vector<double> radians = s.x;  // 0 radians, and 0.1 for z: H stays within 0.02 of E
    for (std::size_t i = 2; i < radians.size(); i += 3) radians[i] = 0.1;
    auto file = [&](const std::string& name, const std::string& units, const std::vector<double>& x) {
      const std::string path = dir + "/" + name + ".h5";
      awtest::H5TestFile f(path);
      f.reals("position", x);
      f.h5py_text("/position", "units", units);  // f['position'].attrs['units'] = units
      f.reals("momentum", s.p);
      return path;
    };
    // read (before: "cannot read the attribute units")
    const StateSet ok = read_state_file(file("radians", "radians", radians));
    REQUIRE(ok.count == 4);
    CHECK(ok.position_turns[2] == 0.1 / (2 * M_PI));
    // the problems behind that message, named
    const StateError degrees = error_of(file("degrees", "degrees", radians));
    CHECK(contains(degrees.what(), "/position: the attribute units is \"degrees\"; it must be \"radians\" or \"turns\""));
    std::vector<double> nan = radians;
    nan[3 * 1 + 2] = std::numeric_limits<double>::quiet_NaN();
    const StateError not_finite = error_of(file("nan", "radians", nan));
    CHECK(not_finite.dataset() == "/position");
    CHECK(not_finite.row() == 1);
    CHECK(contains(not_finite.what(), "is not finite"));
    // and an attribute of another type says which
    const std::string number = dir + "/units-number.h5";
    {
      awtest::H5TestFile f(number);
      f.reals("position", radians);
      f.number("/position", "units", 1.0);
      f.reals("momentum", s.p);
    }
    CHECK(contains(error_of(number).what(), "the attribute units must be a string; it is a floating-point number"));
    // the whole path: `arnoldweb check` plans the states (their energies are E)
    std::string out;
    CHECK(check_within(dir, dir + "/radians.h5", 60, &out) == 0);
    CAPTURE(out);
  }

  TEST_CASE("4. windings stay in range (no overflow, no clipping), float16 is refused, a time too large for the duration") {
    const std::string dir = awtest::temp_dir("states-ranges");
    const States s = simple_states(4);
    auto with_winding = [&](const std::string& name, auto winding, hid_t type) {
      const std::string path = dir + "/" + name + ".h5";
      awtest::H5TestFile f(path);
      f.reals("position_turns", s.x);
      f.dataset("winding", winding, {4, 3}, type);
      f.reals("momentum", s.p);
      return path;
    };
    const std::int64_t most = std::int64_t{1} << 52;
    std::vector<std::int64_t> w(12, 0);
    w[3 * 2 + 1] = std::numeric_limits<std::int64_t>::max() - 1;  // 2^63 - 2: overflowed to -2^63 before
    const StateError overflow = error_of(with_winding("overflow", w, H5T_STD_I64LE));
    CHECK(overflow.dataset() == "/winding");
    CHECK(overflow.row() == 2);
    CHECK(contains(overflow.what(), "the winding count 9223372036854775806 is out of range: at most 2^52"));
    w[3 * 2 + 1] = -most - 1;
    CHECK(contains(error_of(with_winding("below", w, H5T_STD_I64LE)).what(), "-4503599627370497 is out of range"));
    w[3 * 2 + 1] = -most;  // the bound itself is a winding
    CHECK(read_state_file(with_winding("bound", w, H5T_STD_I64LE)).winding[3 * 2 + 1] == -most);
    // unsigned 64-bit windings: in range they are read, above int64 refused by row, not clipped
    std::vector<std::uint64_t> u(12, 3);
    CHECK(read_state_file(with_winding("unsigned", u, H5T_STD_U64LE)).winding == std::vector<std::int64_t>(12, 3));
    u[3 * 1] = std::numeric_limits<std::uint64_t>::max();
    const StateError clipped = error_of(with_winding("unsigned-huge", u, H5T_STD_U64LE));
    CHECK(clipped.dataset() == "/winding");
    CHECK(clipped.row() == 1);
    CHECK(contains(clipped.what(), "the value 18446744073709551615 is out of range"));
    // float16 momenta, against the docs' float64 or float32
    const std::string half = dir + "/float16.h5";
    {
      awtest::H5TestFile f(half);
      f.reals("position_turns", s.x);
      const hid_t f16 = H5Tcopy(H5T_IEEE_F32LE);
      REQUIRE(H5Tset_fields(f16, 15, 10, 5, 0, 10) >= 0);
      REQUIRE(H5Tset_size(f16, 2) >= 0);
      REQUIRE(H5Tset_ebias(f16, 15) >= 0);
      f.reals("momentum", s.p, f16);
      H5Tclose(f16);
    }
    const StateError f16 = error_of(half);
    CHECK(f16.dataset() == "/momentum");
    CHECK(contains(f16.what(), "stores floating-point numbers of 2 bytes (float16); it must hold float64 or float32"));
    // a start time so large that time + run.duration is the time: refused naming run.duration
    const std::string late = dir + "/late.h5";
    {
      awtest::H5TestFile f(late);
      f.reals("position_turns", s.x);
      f.reals("momentum", s.p);
      f.number("/", "time", 1e17);
    }
    const Scene scene = awtest::scene_from(kScene, {"ensemble.initial=file", awtest::set("ensemble.file", late)});
    CHECK_THROWS_WITH_AS(read_plan_inputs(scene), doctest::Contains("the attribute time is 1e+17 T, too large for run.duration = 1"),
                         StateError);
    std::string out;
    CHECK(check_within(dir, late, 60, &out) == 2);
    CHECK(contains(out, "with this run.duration the time must be below 8589934591 T"));
    const std::string soon = dir + "/soon.h5";
    {
      awtest::H5TestFile f(soon);
      f.reals("position_turns", s.x);
      f.reals("momentum", s.p);
      f.number("/", "time", 8.5e9);
    }
    const Scene on_time = awtest::scene_from(kScene, {"ensemble.initial=file", awtest::set("ensemble.file", soon)});
    CHECK(make_plan(on_time, read_plan_inputs(on_time)).start_time() == 8.5e9);
  }

  TEST_CASE("5. a file that declares more than it stores is refused before anything is allocated") {
    const std::string dir = awtest::temp_dir("states-declared");
    const std::string path = dir + "/declared.h5";
    {
      awtest::H5TestFile f(path);
      f.unwritten("position_turns", hsize_t{1} << 24);
      f.unwritten("momentum", hsize_t{1} << 24);
    }
    CHECK(fs::file_size(path) < 4096);  // 1.7 KB that took 1.7 GB before
    const StateError e = error_of(path);
    const std::string what = e.what();
    CAPTURE(what);
    CHECK(contains(what, "declares 50331648 values (402653184 bytes) and stores 0 bytes in 0 of its 256 chunks: "
                             "the others were never written"));
    // a contiguous dataset is the same: its storage must hold its bytes
    const std::string contiguous = dir + "/contiguous.h5";
    {
      awtest::H5TestFile f(contiguous);
      f.reals("position_turns", simple_states(4).x);
      f.dataset<double>("momentum", {}, {hsize_t{1} << 24, 3}, H5T_IEEE_F64LE);
    }
    CHECK(contains(error_of(contiguous).what(), "/momentum: declares 50331648 values (402653184 bytes) and stores 0 bytes"));
  }

  TEST_CASE("6. a run's states.h5 whose digest disagrees with its summary.json is refused, as continue refuses it") {
    const std::string dir = awtest::temp_dir("states-digest");
    const std::string scene = scene_file(dir), run = dir + "/run";
    std::string out;
    REQUIRE(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", run, "--set",
                             "observe.final_states=true", "--set", "ensemble.trajectories=200"},
                            &out) == 0);
    const std::string states = run + "/states.h5";
    fs::copy_file(states, run + "/mine.h5");  // a user's file beside the run's: no summary.json records it
    {  // the same size, another digest: a momentum negated (the same energy)
      const hid_t f = H5Fopen(states.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
      REQUIRE(f >= 0);
      const hid_t d = H5Dopen2(f, "/final/momentum", H5P_DEFAULT);
      std::vector<double> p(600);
      REQUIRE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data()) >= 0);
      p[0] = -p[0];
      REQUIRE(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data()) >= 0);
      H5Dclose(d);
      H5Fclose(f);
    }
    const std::string says = "states.h5: its XXH3-128 digest is ";
    CHECK(check_within(dir, states, 60, &out) == 2);  // accepted without a word before
    CAPTURE(out);
    CHECK(contains(out, says));
    CHECK(contains(out, "but summary.json records"));
    CHECK(awtest::run_cli({"continue", run, "--for", "1", "--quiet"}, &out) == 2);
    CHECK(contains(out, says));
    // the user's own file in the run's directory is theirs: read as any state file
    CHECK(check_within(dir, run + "/mine.h5", 60, &out) == 0);
  }
}
