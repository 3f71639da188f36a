// arnoldweb: the output directory: checks before computing, staging, commit,
// and the rules for replacing an earlier run's directory (output_dir.hpp).
#include "output/output_dir.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <map>

#include "arnoldweb/errors.hpp"
#include "os/regular_file.hpp"
#include "output/atomic_file.hpp"
#include "output/file_digest.hpp"

namespace arnoldweb {
namespace fs = std::filesystem;

namespace detail {
namespace {

constexpr const char* kMarker = ".arnoldweb-staging";  // in every staging directory
constexpr std::size_t kMaxEntries = 200000;             // a directory this full is not ours
constexpr std::uintmax_t kMaxSummaryBytes = 64u << 20;

std::string errno_text() { return std::strerror(errno); }

// Canonical form of an existing path, or its weakly canonical form.
fs::path canonical_or_weak(const fs::path& p) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(p, ec);
  return ec ? fs::absolute(p, ec).lexically_normal() : c;
}

// a == b or a is an ancestor of b
bool contains_path(const fs::path& a, const fs::path& b) {
  auto ai = a.begin(), bi = b.begin();
  for (; ai != a.end(); ++ai, ++bi) {
    if (ai->empty()) continue;  // trailing separator
    if (bi == b.end() || *ai != *bi) return false;
  }
  return true;
}

// What summary.json says arnoldweb wrote into its directory: the files whose
// sizes and digests it records ("file_digests"). A file is arnoldweb's only
// while it still has them (a user's file listed in a copied summary.json, or
// an output edited since, is not); summary.json itself is the manifest.
struct Manifest {
  bool ours = false;                          // a summary.json with arnoldweb's signature
  std::map<std::string, FileDigest> digests;  // relative path -> as written
  std::string problem;
};

Manifest read_manifest(const fs::path& dir) {
  Manifest m;
  const fs::path summary = dir / "summary.json";
  struct stat st {};
  if (::lstat(summary.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) {
    m.problem = "it holds no summary.json written by arnoldweb";
    return m;
  }
  const RegularFile f = read_regular_file(summary.string(), kMaxSummaryBytes);
  if (!f.why.empty()) {
    m.problem = "its summary.json cannot be read (" + f.why + ")";
    return m;
  }
  const nlohmann::json j = nlohmann::json::parse(f.bytes, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("arnoldweb") || !j["arnoldweb"].is_string()) {
    m.problem = "its summary.json was not written by arnoldweb";
    return m;
  }
  const auto digests = j.find("file_digests");
  if (digests == j.end() || !digests->is_object()) {
    m.problem = "its summary.json records no file digests (an arnoldweb before 2026-11-26 wrote it), and --force "
                "deletes only files whose digests summary.json records; remove it yourself, or choose another --out";
    return m;
  }
  for (const auto& [name, d] : digests->items()) {
    const auto bytes = d.is_object() ? d.find("bytes") : d.end();
    const auto hex = d.is_object() ? d.find("xxh3_128") : d.end();
    if (bytes == d.end() || !bytes->is_number_unsigned() || hex == d.end() || !hex->is_string()) {
      m.problem = "its summary.json records file_digests." + name + " in a form arnoldweb does not write";
      return m;
    }
    m.digests[name] = {bytes->get<std::uint64_t>(), hex->get<std::string>()};
  }
  m.ours = true;
  return m;
}

// Whether the file `rel` of `dir` is one arnoldweb wrote and nobody changed.
bool written_by_run(const Manifest& m, const fs::path& dir, const std::string& rel) {
  if (rel == "summary.json") return true;
  const auto it = m.digests.find(rel);
  if (it == m.digests.end()) return false;
  const OpenPlainFile f((dir / rel).string());
  if (!f.why().empty() || f.size() != it->second.bytes) return false;
  try {
    return digest_file(f.fd(), (dir / rel).string()).xxh3_128 == it->second.xxh3_128;
  } catch (const OutputError&) {
    return false;  // unreadable: not known to be ours
  }
}

bool listed_dir(const Manifest& m, const std::string& rel) {
  const std::string prefix = rel + "/";
  for (const auto& [name, d] : m.digests)
    if (name.compare(0, prefix.size(), prefix) == 0) return true;
  return false;
}

// Entries of `dir` that arnoldweb did not write (at most `limit` names).
std::vector<std::string> unknown_entries(const fs::path& dir, const Manifest& m, std::size_t limit) {
  std::vector<std::string> unknown;
  std::error_code ec;
  std::size_t seen = 0;
  for (fs::recursive_directory_iterator it(dir, fs::directory_options::none, ec), end; !ec && it != end;
       it.increment(ec)) {
    if (++seen > kMaxEntries) {
      unknown.push_back("(more than " + std::to_string(kMaxEntries) + " entries)");
      break;
    }
    const std::string rel = it->path().lexically_relative(dir).string();
    const fs::file_status s = it->symlink_status(ec);
    bool ok = false;
    if (fs::is_regular_file(s)) ok = written_by_run(m, dir, rel);
    else if (fs::is_directory(s)) ok = listed_dir(m, rel);
    if (!ok) {
      const bool changed = fs::is_regular_file(s) && m.digests.count(rel);
      unknown.push_back(rel + (fs::is_symlink(s)     ? " (a symbolic link)"
                               : fs::is_directory(s) ? "/"
                               : changed             ? " (changed since the run wrote it)"
                                                     : ""));
      if (fs::is_directory(s)) it.disable_recursion_pending();
      if (unknown.size() >= limit) break;
    }
  }
  if (ec) unknown.push_back("(cannot list it: " + ec.message() + ")");
  return unknown;
}

// Removes the files of `dir` that arnoldweb wrote, then the directories left
// empty; true if `dir` itself is gone.
bool remove_written(const fs::path& dir) {
  const Manifest m = read_manifest(dir);
  if (!m.ours) return false;
  std::vector<fs::path> dirs;
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, fs::directory_options::none, ec), end; !ec && it != end;
       it.increment(ec)) {
    const std::string rel = it->path().lexically_relative(dir).string();
    const fs::file_status s = it->symlink_status(ec);
    if (fs::is_regular_file(s) && written_by_run(m, dir, rel)) files.push_back(it->path());
    else if (fs::is_directory(s)) dirs.push_back(it->path());
  }
  // summary.json last: while anything else is left, the directory stays recognisably ours
  std::stable_partition(files.begin(), files.end(), [&](const fs::path& p) { return p != dir / "summary.json"; });
  for (const fs::path& f : files) ::unlink(f.c_str());
  std::sort(dirs.begin(), dirs.end(), [](const fs::path& a, const fs::path& b) { return a.string() > b.string(); });
  for (const fs::path& d : dirs) ::rmdir(d.c_str());
  return ::rmdir(dir.c_str()) == 0;
}

}  // namespace

std::vector<StagingSibling> staging_siblings(const std::string& final_dir_name) {
  const fs::path final_dir(final_dir_name);
  const fs::path parent = final_dir.has_parent_path() ? final_dir.parent_path() : fs::path(".");
  const std::string prefix = final_dir.filename().string() + ".partial-";
  std::vector<StagingSibling> found;
  std::error_code ec;
  for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.empty() || digits.size() > 10 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    found.push_back({it->path().string(), name, std::strtol(digits.c_str(), nullptr, 10)});
  }
  return found;
}

bool process_running(long pid) {
  if (pid <= 0 || pid == ::getpid()) return false;
  if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno != EPERM) return false;
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!std::getline(in, stat)) return true;
  const auto close = stat.rfind(')');
  return close == std::string::npos || close + 2 >= stat.size() || stat[close + 2] != 'Z';
}

namespace {

// Staging directories (<name>.partial-PID) that a dead process left beside
// `final_dir`: removed if they carry arnoldweb's marker.
void remove_stale_staging(const fs::path& final_dir) {
  for (const StagingSibling& sib : staging_siblings(final_dir.string())) {
    if (sib.pid == ::getpid() || process_running(sib.pid)) continue;
    const fs::path dir(sib.path);
    struct stat st {};
    if (::lstat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) continue;
    if (::lstat((dir / kMarker).c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    // a checkpoint is kept until a resumed run consumes it
    if (::lstat((dir / kCheckpointFile).c_str(), &st) == 0) continue;
    // everything in it was written by the dead run: files of outputs, temporaries, the marker
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
}

// Makes `dir`'s missing ancestors; records those it made (deepest last).
void make_parents(const fs::path& dir, std::vector<std::string>& made, const std::string& shown) {
  std::vector<fs::path> missing;
  std::error_code ec;
  fs::path existing = dir.parent_path();
  for (; !existing.empty() && !fs::exists(fs::symlink_status(existing, ec)); existing = existing.parent_path()) {
    missing.push_back(existing);
    if (existing == existing.parent_path()) break;
  }
  if (existing.empty()) existing = ".";
  if (!fs::is_directory(existing, ec))
    throw OutputError(shown, existing.string() + " is not a directory, so the output directory cannot be made there");
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (::mkdir(it->c_str(), 0777) != 0 && errno != EEXIST)
      throw OutputError(shown, "cannot create " + it->string() + ": " + errno_text());
    made.push_back(it->string());
  }
}

// Removes the parent directories a run created, if they are still empty.
void remove_made(std::vector<std::string>& made) {
  for (auto it = made.rbegin(); it != made.rend(); ++it) ::rmdir(it->c_str());
  made.clear();
}

// The staging directory: created with its marker (and a probe write).
void create_staging(const fs::path& staging, const std::string& shown) {
  if (::mkdir(staging.c_str(), 0777) != 0)
    throw OutputError(shown, "cannot create the staging directory " + staging.string() + ": " + errno_text());
  const std::string marker = "arnoldweb staging directory of process " + std::to_string(::getpid()) + "\n";
  try {
    write_file_atomically((staging / kMarker).string(), marker);
  } catch (const OutputError& e) {
    std::error_code ec;
    fs::remove_all(staging, ec);
    throw OutputError(shown, std::string("cannot write there: ") + e.what());
  }
}

fs::path staging_name(const fs::path& final_dir, const char* kind) {
  return fs::path(final_dir.string() + kind + std::to_string(::getpid()));
}

void check_place(const fs::path& dir, const OutputOptions& o, const std::string& shown) {
  struct stat st {};
  if (::lstat(dir.c_str(), &st) == 0) {
    if (!o.force) throw OutputError(shown, "exists; use --force to replace it, or choose another with --out");
    const std::string why = why_not_replaceable(dir.string(), o.scene_file);
    if (!why.empty()) throw OutputRefused(shown, "refusing to replace it: " + why);
  } else if (errno != ENOENT && errno != ENOTDIR) {
    throw OutputError(shown, "cannot look at it: " + errno_text());
  }
}

void check_space(const fs::path& dir, const OutputOptions& o, const std::string& shown) {
  if (!o.expected_bytes) return;
  const std::uint64_t free = free_bytes(dir.string());
  if (free && free < o.expected_bytes)
    throw OutputError(shown, "the outputs need about " + show_bytes(static_cast<double>(o.expected_bytes)) +
                                 " and the file system has " + show_bytes(static_cast<double>(free)) +
                                 " free; free space or choose another place with --out (nothing was computed)");
}

}  // namespace

std::string normalise_output_dir(const std::string& dir) {
  if (dir.empty()) throw OutputRefused(dir, "the output directory name is empty");
  std::string d = dir;
  while (d.size() > 1 && d.back() == '/') d.pop_back();
  fs::path p = fs::path(d).lexically_normal();
  std::string s = p.string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s.empty() ? std::string(".") : s;
}

std::string why_not_replaceable(const std::string& dir, const std::string& scene_file) {
  const fs::path p(dir);
  struct stat st {};
  if (::lstat(p.c_str(), &st) != 0) return "";
  if (S_ISLNK(st.st_mode)) return "it is a symbolic link";
  if (!S_ISDIR(st.st_mode)) return "it is not a directory";
  const fs::path target = canonical_or_weak(p);
  std::error_code ec;
  if (target == target.root_path()) return "it is the root directory";
  if (const char* home = std::getenv("HOME"); home && *home && target == canonical_or_weak(home))
    return "it is your home directory";
  const fs::path cwd = canonical_or_weak(fs::current_path(ec));
  if (contains_path(target, cwd)) return target == cwd ? "it is the current directory" : "it holds the current directory";
  if (!scene_file.empty() && scene_file != "<string>" && scene_file != "<test>") {
    const fs::path scene_dir = canonical_or_weak(fs::absolute(scene_file, ec).parent_path());
    if (contains_path(target, scene_dir)) return "it holds the scene file " + scene_file;
  }
  const Manifest m = read_manifest(p);
  if (!m.ours)
    return m.problem + (m.problem.find("--force") == std::string::npos
                            ? "; --force only replaces a directory that a run of arnoldweb wrote"
                            : "");
  const auto unknown = unknown_entries(p, m, 4);
  if (!unknown.empty()) {
    std::string list;
    for (const auto& u : unknown) list += (list.empty() ? "" : ", ") + u;
    return "it holds files that arnoldweb did not write (" + list + "); move them away or choose another --out";
  }
  return "";
}

Staging::Staging(const std::string& final_dir, const OutputOptions& options) : options_(options) {
  final_ = normalise_output_dir(final_dir);
  const fs::path dir(final_);
  check_place(dir, options_, final_);
  if (!options_.staging.empty()) {  // made earlier by this run (its checkpoints are in it)
    path_ = options_.staging;
    adopted_ = true;
    return;
  }
  try {
    make_parents(dir, made_, final_);
    remove_stale_staging(dir);
    check_space(dir, options_, final_);
    path_ = staging_name(dir, ".partial-").string();
    create_staging(path_, final_);
  } catch (...) {
    remove_made(made_);
    throw;
  }
}

namespace {

// ".NAME.tmp-PID-N" with PID not this process: a file that another process's
// write_file_atomically had not finished
bool is_foreign_temporary(const std::string& name) {
  const auto at = name.rfind(".tmp-");
  if (name.empty() || name[0] != '.' || at == std::string::npos || at == 0) return false;
  const std::string tail = name.substr(at + 5);
  const auto dash = tail.find('-');
  if (dash == std::string::npos || dash == 0 || dash + 1 == tail.size()) return false;
  const std::string p = tail.substr(0, dash), n = tail.substr(dash + 1);
  auto digits = [](const std::string& t) { return t.find_first_not_of("0123456789") == std::string::npos; };
  if (!digits(p) || !digits(n)) return false;
  return std::to_string(::getpid()) != p;
}

}  // namespace

// The half-written temporaries of other (killed) processes in a staging
// directory that a resumed run took over: checkpoints, or outputs that were
// being written when the process died. The directory is arnoldweb's own
// (its marker, its checkpoint), so nothing of a user's is touched.
void remove_dead_temporaries(const std::string& staging) {
  std::error_code ec;
  for (fs::recursive_directory_iterator it(staging, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec) && is_foreign_temporary(it->path().filename().string()))
      ::unlink(it->path().c_str());
}

Staging::~Staging() {
  if (done_ || adopted_) return;
  std::error_code ec;
  fs::remove_all(path_, ec);  // all of it was written by this run
  remove_made(made_);
}

std::string Staging::keep(const std::string& suffix) {
  struct stat st {};
  if (::lstat((fs::path(path_) / kCheckpointFile).c_str(), &st) == 0) {
    done_ = true;
    return path_;  // resumable: `arnoldweb resume` finds it under this name
  }
  const fs::path kept = staging_name(final_, suffix.c_str());
  ::unlink((fs::path(path_) / kMarker).c_str());
  done_ = true;
  if (std::rename(path_.c_str(), kept.c_str()) == 0) path_ = kept.string();
  return path_;
}

std::string Staging::commit() {
  const fs::path dir(final_);
  ::unlink((fs::path(path_) / kCheckpointFile).c_str());  // consumed: the outputs are complete
  remove_dead_temporaries(path_);
  ::unlink((fs::path(path_) / kMarker).c_str());
  done_ = true;
  struct stat st {};
  if (::lstat(dir.c_str(), &st) != 0) {
    if (::renameat2(AT_FDCWD, path_.c_str(), AT_FDCWD, dir.c_str(), RENAME_NOREPLACE) == 0) return "";
    if (errno == EINVAL && ::lstat(dir.c_str(), &st) != 0 && std::rename(path_.c_str(), dir.c_str()) == 0)
      return "";  // a file system without RENAME_NOREPLACE
    if (errno != EEXIST && errno != ENOTEMPTY && errno != EINVAL)
      throw OutputError(final_, "cannot move the results into place: " + errno_text() + " (they are in " + path_ + ")");
  }
  // it exists: from the start (--force), or it appeared while the run was computing
  if (!options_.force) throw OutputError(final_, "appeared while the run was computing; the results are in " + path_);
  const std::string why = why_not_replaceable(final_, options_.scene_file);
  if (!why.empty())
    throw OutputRefused(final_, "refusing to replace it: " + why + " (the results are in " + path_ + ")");
  // swap the new directory in; the old one is then at the staging path
  fs::path old(path_);
  if (::renameat2(AT_FDCWD, path_.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) != 0) {
    old = staging_name(dir, ".old-");
    if (std::rename(dir.c_str(), old.c_str()) != 0)
      throw OutputError(final_, "cannot move the existing directory aside: " + errno_text() + " (the results are in " +
                                    path_ + ")");
    if (std::rename(path_.c_str(), dir.c_str()) != 0) {
      const std::string err = errno_text();
      std::rename(old.c_str(), dir.c_str());  // put the old directory back
      throw OutputError(final_, "cannot move the results into place: " + err + " (they are in " + path_ + ")");
    }
  }
  if (!remove_written(old))
    return "the earlier outputs were replaced, but " + old.string() +
           " still holds files that arnoldweb did not write (left as they are)";
  return "";
}

}  // namespace detail

std::string check_output_dir(const std::string& dir, const OutputOptions& options) {
  // the same checks as a run's staging directory, which is created (with a
  // probe file) and removed again
  detail::Staging probe(dir, options);
  return probe.final_dir();
}

}  // namespace arnoldweb
