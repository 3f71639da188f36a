// arnoldweb (internal): reading back an output directory written earlier.
// Every reader of saved runs goes through here (render_saved,
// read_saved_maps and so `arnoldweb compare`, the Python package), so the
// read-side rules of docs/reliability.md hold for all of them:
//  - every file is read as a plain file, without blocking (os/regular_file.hpp);
//  - summary.json is a JSON object whose fields have the types arnoldweb writes;
//  - every other file has the size and XXH3-128 digest that summary.json
//    records for it ("file_digests"); a directory written before the digests
//    were recorded is read with a note saying that its files were not checked;
//  - HDF5 files are opened by the one HDF5 reader (output/h5_reader.hpp);
//  - the shapes summary.json declares ("maps": nside, frames, zoom) are those
//    of the data, so nothing is read past the end of a map.
// Every failure is a SavedRunError (exit 2) naming the file.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "arnoldweb/output.hpp"
#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

class SavedDir {
 public:
  // <dir>/summary.json, read and checked.
  explicit SavedDir(const std::string& dir);
  // <parent>/<subdir> (a panel's directory): its summary.json is checked
  // against the digest the parent's summary.json records for it.
  SavedDir(const SavedDir& parent, const std::string& subdir);

  const std::string& dir() const { return dir_; }
  std::string path(const std::string& name) const { return dir_ + "/" + name; }
  std::string summary_path() const { return path("summary.json"); }
  const nlohmann::json& summary() const { return j_; }
  // summary.json's text as it was read (for rewriting it with more files).
  const std::string& summary_text() const { return text_; }

  // Fields of summary.json by JSON pointer ("/maps/nside"): SavedRunError
  // naming summary.json and the field when it is missing or of another type.
  std::uint64_t count(const std::string& pointer) const;
  std::string text(const std::string& pointer) const;
  std::optional<std::uint64_t> optional_count(const std::string& pointer) const;

  // Whether the run wrote `name` (a file of the directory, e.g.
  // "panel-a/summary.json"): listed in summary.json (an older directory: it
  // exists).
  bool holds(const std::string& name) const;
  // The bytes of the file `name` of the directory, checked: a plain file with
  // the size and digest summary.json records for it. `missing` completes the
  // message when it does not exist.
  std::string read(const std::string& name, const std::string& missing = "") const;

  // Whether summary.json records the files' digests (directories written
  // before arnoldweb recorded them do not).
  bool checked() const { return digests() != nullptr; }
  // What summary.json records for `name` ({"bytes", "xxh3_128"}), or null.
  const nlohmann::json* recorded(const std::string& name) const;
  // SavedRunError naming the file when its size, or its size and digest,
  // differ from what summary.json records (nothing when it records none).
  void check_size(const std::string& name, std::uint64_t size) const;
  void check_digest(const std::string& name, const FileDigest& digest) const;

  // The output directory that holds `file`, when the directory of the file
  // (links resolved) has a summary.json written by arnoldweb; else none.
  static std::optional<SavedDir> holding(const std::string& file);
  // "" or a note for the user: the files of an older directory are read unchecked.
  std::string note() const;

 private:
  SavedDir(std::string dir, std::string text);
  void check_fields() const;
  const nlohmann::json* digests() const;  // "file_digests", or null
  [[noreturn]] void bad_field(const std::string& pointer, const std::string& expected) const;

  std::string dir_, text_;
  nlohmann::json j_;
};

// When `file` is a file that a run wrote (its directory's summary.json
// records its digest), checks the open file against that size and digest, as
// `continue` and every reader of saved runs do: SavedRunError naming it when
// it was changed. A file that no summary.json records is the user's own and
// is left alone. (state files: ensemble.file)
class OpenPlainFile;
void check_run_file(const std::string& file, const OpenPlainFile& open);

// <dir>/map.h5 into r.map, r.frames (one map per frame), r.zoom and r.nside,
// each checked against the shape summary.json declares for it ("maps").
// Returns the zoom's resolution (0: none).
int read_saved_map_h5(const SavedDir& saved, Result& r);

// A saved run as render draws it: the plan of its scene as run (summary.json's
// scene_toml, which must declare the maps map.h5 holds), the counts of
// summary.json and the maps of map.h5.
struct SavedRun {
  Plan plan;
  Result result;
};
SavedRun read_saved_run(const SavedDir& saved);

}  // namespace arnoldweb::detail
