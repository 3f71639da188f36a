// arnoldweb: checkpoints beside an output directory (output.hpp:
// find_checkpoints, CheckpointStore). A checkpoint lives in the run's staging
// directory, so the staging rules hold: the directory carries the marker, the
// outputs are written into it and it is moved into place at the end (then the
// checkpoint is removed: consumed); a dead process's staging directory that
// holds a checkpoint is never removed automatically.
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cstdint>
#include <filesystem>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/checkpoint.hpp"
#include "arnoldweb/output.hpp"
#include "os/regular_file.hpp"
#include "output/atomic_file.hpp"
#include "output/output_dir.hpp"

namespace arnoldweb {
namespace fs = std::filesystem;


std::string read_checkpoint_file(const std::string& path) {
  detail::RegularFile f = detail::read_regular_file(path, UINT64_MAX);
  if (!f.why.empty()) throw CheckpointError(path, "cannot read the checkpoint: " + f.why);
  return std::move(f.bytes);
}

std::vector<FoundCheckpoint> find_checkpoints(const std::string& dir) {
  std::vector<FoundCheckpoint> found;
  const fs::path final_dir(detail::normalise_output_dir(dir));
  const fs::path parent = final_dir.has_parent_path() ? final_dir.parent_path() : fs::path(".");
  for (const detail::StagingSibling& sib : detail::staging_siblings(final_dir.string())) {
    struct stat st {};
    const fs::path file = fs::path(sib.path) / detail::kCheckpointFile;
    if (::lstat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    FoundCheckpoint f;
    f.staging_dir = (parent == "." && !final_dir.has_parent_path() ? fs::path(sib.name) : fs::path(sib.path)).string();
    f.file = (fs::path(f.staging_dir) / detail::kCheckpointFile).string();
    f.pid = sib.pid;
    f.running = detail::process_running(f.pid);
    found.push_back(f);
  }
  return found;
}

CheckpointStore::CheckpointStore(std::string dir, OutputOptions options)
    : dir_(detail::normalise_output_dir(dir)), options_(std::move(options)) {}

std::string CheckpointStore::file() const {
  return staging_.empty() ? std::string() : (fs::path(staging_) / detail::kCheckpointFile).string();
}

std::string CheckpointStore::adopt(const FoundCheckpoint& found) {
  if (found.running)
    throw OutputError(found.staging_dir, "its run (process " + std::to_string(found.pid) +
                                             ") is still going; wait for it or stop it (kill -TERM " +
                                             std::to_string(found.pid) + " writes a checkpoint) first");
  const std::string bytes = read_checkpoint_file(found.file);
  const std::string mine = dir_ + ".partial-" + std::to_string(::getpid());
  if (found.staging_dir != mine) {
    if (std::rename(found.staging_dir.c_str(), mine.c_str()) != 0)
      throw OutputError(found.staging_dir, std::string("cannot take over the checkpoint's directory: ") +
                                               std::strerror(errno));
    detail::write_file_atomically(mine + "/.arnoldweb-staging",
                                  "arnoldweb staging directory of process " + std::to_string(::getpid()) + "\n");
  }
  staging_ = mine;
  return bytes;
}

void CheckpointStore::save(const std::string& image) {
  if (staging_.empty()) {
    detail::Staging s(dir_, options_);  // the same checks and marker as the outputs' staging
    s.hold();
    staging_ = s.path();
  }
  detail::write_file_atomically(file(), image);
}

}  // namespace arnoldweb
