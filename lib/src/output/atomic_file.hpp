// arnoldweb: atomic file writes. A file is produced under a temporary name in
// its final directory, flushed to disk, then renamed into place: a reader never
// sees a partial file, and a failure (full disk) leaves none behind.
#pragma once

#include <functional>
#include <string>

namespace arnoldweb::detail {

// Calls produce(temporary_path) to write the file, then fsyncs it and renames
// it to `path`. Throws OutputError (and removes the temporary) if producing,
// flushing or renaming fails; produce() reports its errors against `path`.
void write_atomically(const std::string& path, const std::function<void(const std::string&)>& produce);

// Makes sure what produce() wrote is on disk (throws OutputError otherwise).
void sync_file(const std::string& path);

}  // namespace arnoldweb::detail
