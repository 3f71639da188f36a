// arnoldweb: reading a file that must be a plain file (a scene, a summary.json,
// a map.h5, a checkpoint) without ever blocking on it. The file is opened with
// O_NONBLOCK (a FIFO does not wait for a writer) and checked with fstat before
// a byte is read: FIFOs, devices, directories and sockets are refused, and so
// are the files of the kernel's pseudo file systems (/proc, /sys, ...), whose
// sizes mean nothing and whose reads may block or consume (/proc/kmsg).
#pragma once

#include <cstdint>
#include <string>

namespace arnoldweb::detail {

struct RegularFile {
  std::string bytes;      // the contents, when it was read
  std::uint64_t size = 0; // its size as fstat gives it (0 if it could not be opened)
  int error = 0;          // errno of a failed open or read (ENOENT: missing), 0 otherwise
  std::string why;        // "" when read, else a phrase completing "cannot read it: "
                          // ("it is a pipe (FIFO), not a file", "No such file or directory")
};

// Reads `path` if it is a regular file of at most max_bytes.
RegularFile read_regular_file(const std::string& path, std::uint64_t max_bytes);

// A plain file held open for a reader that opens it again by name (HDF5):
// the checks of read_regular_file, without reading it. name() reaches this
// very file (/proc/self/fd/N) even if its path is replaced by a FIFO after
// the checks.
class OpenPlainFile {
 public:
  explicit OpenPlainFile(const std::string& path);
  ~OpenPlainFile();
  OpenPlainFile(const OpenPlainFile&) = delete;
  OpenPlainFile& operator=(const OpenPlainFile&) = delete;

  const std::string& why() const { return why_; }  // "" when it is a plain file
  int error() const { return error_; }              // errno of a failed open (ENOENT: missing)
  std::uint64_t size() const { return size_; }
  int fd() const { return fd_; }
  std::string name() const;

 private:
  std::string path_, why_;
  int fd_ = -1, error_ = 0;
  std::uint64_t size_ = 0;
};

}  // namespace arnoldweb::detail
