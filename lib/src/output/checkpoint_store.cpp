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
#include <filesystem>
#include <fstream>
#include <sstream>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "output/atomic_file.hpp"
#include "output/output_dir.hpp"

namespace arnoldweb {
namespace fs = std::filesystem;

namespace {

// Alive and not a zombie (a killed rank whose parent died too waits as a
// zombie until init reaps it).
bool running(long pid) {
  if (pid <= 0 || pid == ::getpid()) return false;
  if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno != EPERM) return false;
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!std::getline(in, stat)) return true;
  const auto close = stat.rfind(')');
  return close == std::string::npos || close + 2 >= stat.size() || stat[close + 2] != 'Z';
}

}  // namespace

std::vector<FoundCheckpoint> find_checkpoints(const std::string& dir) {
  std::vector<FoundCheckpoint> found;
  const fs::path final_dir(detail::normalise_output_dir(dir));
  const fs::path parent = final_dir.has_parent_path() ? final_dir.parent_path() : fs::path(".");
  const std::string prefix = final_dir.filename().string() + ".partial-";
  std::error_code ec;
  for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.empty() || digits.size() > 10 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    struct stat st {};
    const fs::path file = it->path() / detail::kCheckpointFile;
    if (::lstat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    FoundCheckpoint f;
    f.staging_dir = (parent == "." && !final_dir.has_parent_path() ? fs::path(name) : it->path()).string();
    f.file = (fs::path(f.staging_dir) / detail::kCheckpointFile).string();
    f.pid = std::strtol(digits.c_str(), nullptr, 10);
    f.running = running(f.pid);
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
  std::ifstream in(found.file, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  if (!in) throw OutputError(found.file, std::string("cannot read the checkpoint: ") + std::strerror(errno));
  const std::string mine = dir_ + ".partial-" + std::to_string(::getpid());
  if (found.staging_dir != mine) {
    if (std::rename(found.staging_dir.c_str(), mine.c_str()) != 0)
      throw OutputError(found.staging_dir, std::string("cannot take over the checkpoint's directory: ") +
                                               std::strerror(errno));
    detail::write_file_atomically(mine + "/.arnoldweb-staging",
                                  "arnoldweb staging directory of process " + std::to_string(::getpid()) + "\n");
  }
  staging_ = mine;
  return bytes.str();
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
