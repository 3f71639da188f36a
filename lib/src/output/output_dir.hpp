// arnoldweb: the output directory of a run, and the rules that keep a user's
// files safe:
//  - it is checked before anything is computed (and by `check`): the path is
//    normalised, the place can be made and written (a probe is created and
//    removed), and the file system has room for the estimated outputs;
//  - results are produced in a staging directory beside it, marked as
//    arnoldweb's, and moved into place at the end: a directory is either
//    absent or complete;
//  - an existing directory is replaced only with --force, and only if a run of
//    arnoldweb wrote it: its summary.json records the size and digest of every
//    other file in it ("file_digests"), each file still has them, and nothing
//    else is inside; then only those files are deleted (a directory whose
//    summary.json records no digests, written before 2026-11-26, is refused:
//    nothing tells its files from a user's). The
//    current directory, its parents, the scene file's directory and its
//    parents, / and $HOME are never replaced;
//  - staging directories left by processes that died are removed on the next
//    run into the same place (only those that carry arnoldweb's marker), except
//    those holding a checkpoint (kCheckpointFile): a checkpoint is removed only
//    when a resumed run that consumed it commits its outputs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "arnoldweb/output.hpp"

namespace arnoldweb::detail {

// The checkpoint of a run, inside its staging directory.
constexpr const char* kCheckpointFile = "checkpoint.awck";

// `dir` without trailing slashes and with "." and ".." parts resolved
// lexically; throws OutputRefused for an empty name.
std::string normalise_output_dir(const std::string& dir);

// Why `dir` may not be replaced by a run's outputs, or "" if it may (it was
// written by arnoldweb and holds nothing else). Looks, changes nothing.
std::string why_not_replaceable(const std::string& dir, const std::string& scene_file);

// The staging directories beside `final_dir` (<name>.partial-PID, PID in
// decimal), whatever their state, with the process id in their name.
struct StagingSibling {
  std::string path;  // as found (parent / name)
  std::string name;
  long pid = 0;
};
std::vector<StagingSibling> staging_siblings(const std::string& final_dir);

// Whether process `pid` is running: alive and not a zombie (a killed rank whose
// parent died too waits as a zombie until init reaps it); never this process.
bool process_running(long pid);

// Removes, in a staging directory this process owns, the files that other
// (dead) processes' atomic writes left half-written (".NAME.tmp-PID-N").
void remove_dead_temporaries(const std::string& staging);

// A staging directory for the outputs of one run: created beside the final
// directory with a marker file; commit() moves it into place. If it is
// neither committed nor kept, the destructor removes it.
class Staging {
 public:
  Staging(const std::string& final_dir, const OutputOptions& options);
  ~Staging();
  Staging(const Staging&) = delete;
  Staging& operator=(const Staging&) = delete;

  const std::string& path() const { return path_; }
  const std::string& final_dir() const { return final_; }

  // Moves the outputs into place (replacing an earlier arnoldweb directory
  // only if options.force). Returns a warning, or "" (e.g. the old directory
  // could not be removed completely).
  std::string commit();
  // Keeps what was written under a name that nothing removes automatically,
  // and returns that name (after a failed write). A staging directory holding
  // a checkpoint keeps its name (it stays resumable).
  std::string keep(const std::string& suffix);
  // Leaves the directory in place when this object goes (it holds a checkpoint).
  void hold() { done_ = true; }

 private:
  std::string final_, path_;
  std::vector<std::string> made_;  // parent directories this run created
  OutputOptions options_;
  bool done_ = false;
  bool adopted_ = false;  // options.staging: made earlier (it holds the run's checkpoint)
};

}  // namespace arnoldweb::detail
