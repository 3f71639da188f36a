// arnoldweb: caches of compiled CUDA kernel images. One compile per kernel
// configuration and target per process (in memory), and across processes a
// disk cache of images under $ARNOLDWEB_CACHE_DIR, else
// $XDG_CACHE_HOME/arnoldweb, else ~/.cache/arnoldweb (subfolder cuda/), keyed
// by a hash of the embedded sources, the NVRTC options, the NVRTC version and
// the target. Files are written atomically; a cache that cannot be read or
// written is skipped silently. ARNOLDWEB_CACHE_DIR=off disables the disk cache.
#pragma once

#include <memory>
#include <string>

#include "backends/cuda/nvrtc_compiler.hpp"

namespace arnoldweb::detail {

struct CachedImage {
  std::shared_ptr<const CudaImage> image;
  std::string origin;  // "compiled", "memory" or "disk"
};

// The ensemble kernel image for (defines, target); compiles it with NVRTC
// when neither cache has it. Throws what nvrtc_compile_ensemble throws.
// `model_source`: an expression model's header (part of the key), or "".
CachedImage cuda_ensemble_image(const std::string& defines, const CudaTarget& target,
                                const std::string& device, const std::string& model_source = "");

// Removes the image for (defines, target) from both caches (used when a
// cached image fails to load, before compiling it afresh).
void cuda_forget_image(const std::string& defines, const CudaTarget& target, const std::string& model_source = "");

// Empties this process's in-memory cache (the disk cache stays). For tests.
void cuda_clear_memory_cache();

// The disk cache folder for CUDA images, or "" when there is none.
std::string cuda_cache_dir();

}  // namespace arnoldweb::detail
