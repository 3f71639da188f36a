// libFuzzer target for what `arnoldweb render` and `arnoldweb compare` read
// back: an output directory's summary.json and map.h5, through the one reader
// of saved runs (lib/src/output/saved_run.hpp; docs/reliability.md, "Reading
// back").
//
// Input: the bytes of summary.json, a NUL byte, the bytes of map.h5 (no NUL:
// no map.h5 at all). The harness writes them into a directory of its own and
// reads it as compare does (read_saved_maps) and as render does
// (read_saved_run: the scene as run planned, its declared maps checked, the
// counts and maps read; the drawing itself is left out).
//
// A map.h5 whose bytes were mutated fails its digest check, as damage on disk
// would. So that mutated HDF5 files also reach the HDF5 reader and the shape
// checks, a summary.json whose file_digests give "trust" as the digest of
// map.h5 gets the true size and digest of the map.h5 at hand written in
// before it is read (the seeds hold both kinds).
//
// A FIFO, fifo.h5, lies beside them: the seeds whose map.h5 leads out of the
// file (an external link, external storage, a virtual dataset) name it.
//
// HDF5 reads map.h5 in a child process (lib/src/os/isolated.hpp), as for every user: a
// crash of HDF5 1.10.8 on damaged metadata is then a SavedRunError ("HDF5 could not read it"),
// an expected outcome. With ARNOLDWEB_HDF5_IN_PROCESS=1 (check-fuzz.sh --long) it reads here,
// the fuzzer sees the reader's coverage, and such a crash is a finding.
//
// Expected outcomes: the maps, or an arnoldweb::Error with a message.
// Findings: any other exception, a crash, a hang, a sanitizer report, an
// HDF5 object left open.
// Declared shapes are bounded (nside <= 256, zoom <= 1024) so that an input
// cannot ask for gigabytes of map: larger ones only allocate more.
#include <hdf5.h>
#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "output/file_digest.hpp"
#include "output/saved_run.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

std::string g_dir;

[[noreturn]] void finding(const char* stage, const std::string& what) {
  std::fprintf(stderr, "\nFUZZ FINDING in %s: %s\n", stage, what.c_str());
  std::fflush(stderr);
  std::abort();
}

template <class Read>
void expect_clean(const char* stage, Read read) {
  try {
    read();
  } catch (const arnoldweb::Error& e) {
    if (std::string(e.what()).empty()) finding(stage, "an arnoldweb::Error without a message");
  } catch (const std::exception& e) {
    finding(stage, std::string("unexpected exception ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    finding(stage, "unexpected exception of a type not derived from std::exception");
  }
}

// The summary as the harness writes it, or "" to skip the input (declared
// shapes beyond the bounds). "trust" digests of map.h5 are filled in.
std::string prepare(const std::string& summary, const std::string& map, bool has_map) {
  const json j = json::parse(summary, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return summary;
  if (j.contains("maps") && j["maps"].is_object()) {
    const json& m = j["maps"];
    auto above = [&](const char* k, std::uint64_t most) {
      return m.contains(k) && m[k].is_number_unsigned() && m[k].get<std::uint64_t>() > most;
    };
    if (above("nside", 256) || above("zoom_resolution", 1024)) return "";
  }
  const json::json_pointer trust("/file_digests/map.h5/xxh3_128");
  if (!has_map || !j.contains(trust) || j.at(trust) != "trust") return summary;
  json fixed = j;
  fixed["file_digests"]["map.h5"] = arnoldweb::detail::file_digest_json(arnoldweb::detail::digest_bytes(map));
  return fixed.dump();
}

void write(const std::string& name, const std::string& bytes) {
  std::ofstream out(g_dir + "/" + name, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) finding("the harness", "cannot write " + g_dir + "/" + name);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::string templ = (fs::temp_directory_path() / "arnoldweb-fuzz-saved-XXXXXX").string();
  if (!mkdtemp(templ.data())) finding("the harness", "cannot make a temporary directory");
  g_dir = templ;
  // what the seeds' external links, external storage and virtual datasets of map.h5 name: a
  // read of it blocks, which libFuzzer reports as a timeout (the reader must refuse them first)
  if (::mkfifo((g_dir + "/fifo.h5").c_str(), 0600) != 0) finding("the harness", "cannot make its FIFO");
  std::atexit([] {
    std::error_code ec;
    fs::remove_all(g_dir, ec);
  });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t nul = input.find('\0');
  const bool has_map = nul != std::string::npos;
  const std::string map = has_map ? input.substr(nul + 1) : std::string();
  const std::string summary = prepare(input.substr(0, nul), map, has_map);
  if (summary.empty()) return 0;
  write("summary.json", summary);
  std::error_code ec;
  fs::remove(g_dir + "/map.h5", ec);
  if (has_map) write("map.h5", map);

  expect_clean("read_saved_maps (compare)", [] { arnoldweb::read_saved_maps(g_dir); });
  expect_clean("read_saved_run (render)", [] {
    const arnoldweb::detail::SavedDir saved(g_dir);
    arnoldweb::detail::read_saved_run(saved);
  });
  // every HDF5 object the reader opened is closed again, on every path (HDF5's
  // own leaks are suppressed by library name: tests/fuzz/hdf5.supp)
  if (const ssize_t open = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL); open != 0)
    finding("the reader", std::to_string(open) + " HDF5 object(s) left open");
  return 0;
}
