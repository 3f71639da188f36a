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

// Why `path` is not a plain file that another reader (HDF5) may open, or ""
// when it is one: the same checks, without reading it.
std::string plain_file_problem(const std::string& path);

}  // namespace arnoldweb::detail
