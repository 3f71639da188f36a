// arnoldweb: the disk cache of kernels compiled at run time, shared by the
// backends that compile (the CUDA backend's NVRTC images, the cpu backend's
// expression-model kernels from the host C++ compiler). A cache file is 8
// bytes of magic, the XXH64 of the payload (8 bytes, little end first), then
// the payload; it is written atomically (temporary name, rename). A file that
// cannot be read, is short, has other magic or a wrong sum is a miss; a cache
// that cannot be written is skipped silently.
#pragma once

#include <string>

namespace arnoldweb::detail {

// The cache folder for one kind of kernel ("cuda", "cpu"):
// $ARNOLDWEB_CACHE_DIR/<kind>, else $XDG_CACHE_HOME/arnoldweb/<kind>, else
// ~/.cache/arnoldweb/<kind>; "" when there is none (ARNOLDWEB_CACHE_DIR set
// to "", "off" or "0" disables the disk cache).
std::string kernel_cache_dir(const std::string& kind);

// A file name for what `fingerprint` describes (everything that makes the
// kernel: sources, options, compiler version): its XXH3-128 in hex, then `extension`.
std::string kernel_cache_file_name(const std::string& fingerprint, const std::string& extension);

// The payload of the cache file `path` if it is whole and has `magic`.
bool read_cache_file(const std::string& path, const char (&magic)[8], std::string& payload);

// Stores `payload` as the cache file `path` (its folder made as needed); never throws.
void write_cache_file(const std::string& path, const char (&magic)[8], const std::string& payload);

}  // namespace arnoldweb::detail
