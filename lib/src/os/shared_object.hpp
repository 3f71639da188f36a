// arnoldweb: loading a shared object held in memory (a kernel compiled at run
// time, possibly read from the disk cache) into this process, and finding a
// symbol in it. Loaded objects stay for the life of the process.
#pragma once

#include <string>

namespace arnoldweb::detail {

// Loads the shared object whose bytes are `image` (through an anonymous
// memory file, so no file is left behind) and returns the address of its
// symbol `symbol`. Throws std::runtime_error with the loader's message.
void* load_shared_object_symbol(const std::string& image, const std::string& symbol);

// The folder libarnoldweb was loaded from ("" if unknown): where its plugins
// and a wheel's neighbouring packages are looked for.
std::string this_library_dir();

}  // namespace arnoldweb::detail
