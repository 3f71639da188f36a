// arnoldweb: atomic file writes. A file's bytes are produced in memory, written
// under a temporary name in its final directory with every write and close
// checked, flushed to disk, then renamed into place: a reader never sees a
// partial file, and a failure (full disk) leaves none behind and says how many
// bytes were needed and how many were free. Each file put in place is
// recorded, with its size and digest, in the DigestLedger open on this
// thread (file_digest.hpp), for the summary.json that lists it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace arnoldweb::detail {

// Writes `bytes` to `path` atomically. Throws OutputError naming `path`; on a
// full disk (ENOSPC, EDQUOT, EFBIG) the message gives the bytes needed and free.
void write_file_atomically(const std::string& path, const std::string& bytes);

// Calls produce(temporary_path) to write the file (for programs that write
// files themselves), then fsyncs it and renames it to `path`. Throws
// OutputError (and removes the temporary) if producing, flushing or renaming
// fails; produce() reports its errors against `path`.
void write_atomically(const std::string& path, const std::function<void(const std::string&)>& produce);

// Makes sure what was written to `path` is on disk (throws OutputError otherwise).
void sync_file(const std::string& path);

// Bytes free for an unprivileged writer on the file system holding `path`
// (or its nearest existing ancestor); 0 if unknown.
std::uint64_t free_bytes(const std::string& path);

// "12.3 MB" for messages.
std::string show_bytes(double bytes);

}  // namespace arnoldweb::detail
