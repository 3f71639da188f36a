// arnoldweb: the digest of every file of an output directory (FileDigest,
// output.hpp), taken where the file is written. The atomic writers
// (atomic_file.hpp) record each file they put in place into the ledger open
// on their thread; whoever lists files in a summary.json (write_job,
// render_saved) takes their digests from it. A writer added later gets its
// files' digests for free, as long as it writes through the atomic writers.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "arnoldweb/output.hpp"

namespace arnoldweb::detail {

FileDigest digest_bytes(const std::string& bytes);
// The digest of an open file's contents, read in pieces (a file of gigabytes
// is not held in memory); OutputError naming `path` if it cannot be read.
FileDigest digest_file(int fd, const std::string& path);

// summary.json's "file_digests": {"map.h5": {"bytes": 12345, "xxh3_128": "..."}, ...},
// and one entry of it.
nlohmann::ordered_json file_digests_json(const FileDigests& digests);
nlohmann::ordered_json file_digest_json(const FileDigest& digest);

// Records the digests of the files written atomically on this thread while
// it is open (ledgers nest: the innermost records).
class DigestLedger {
 public:
  DigestLedger();
  ~DigestLedger();
  DigestLedger(const DigestLedger&) = delete;
  DigestLedger& operator=(const DigestLedger&) = delete;

  // The digests of `names` (paths relative to `dir`) as they were written; a
  // file written some other way is read back (OutputError if it cannot be).
  FileDigests of(const std::string& dir, const std::vector<std::string>& names) const;

  // Called by the atomic writers for each file they put in place.
  static void record(const std::string& path, const FileDigest& digest);

 private:
  std::map<std::string, FileDigest> by_path_;
  DigestLedger* previous_;
};

}  // namespace arnoldweb::detail
