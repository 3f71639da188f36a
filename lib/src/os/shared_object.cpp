// arnoldweb: loading a shared object from memory (shared_object.hpp): the
// bytes go into a memfd, which dlopen reads through /proc/self/fd (one open
// descriptor per object loaded).
#include "os/shared_object.hpp"

#include <dlfcn.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace arnoldweb::detail {

std::string this_library_dir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&this_library_dir), &info) == 0 || !info.dli_fname) return {};
  const std::string path = info.dli_fname;
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

void* load_shared_object_symbol(const std::string& image, const std::string& symbol) {
  const int fd = ::memfd_create("arnoldweb-kernel", MFD_CLOEXEC);
  if (fd < 0) throw std::runtime_error(std::string("memfd_create: ") + std::strerror(errno));
  std::size_t at = 0;
  while (at < image.size()) {
    const ssize_t n = ::write(fd, image.data() + at, image.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      throw std::runtime_error("writing the kernel into memory: " + why);
    }
    at += static_cast<std::size_t>(n);
  }
  // The loader knows an object by its path: were the descriptor closed, the
  // next object would get the same number, hence the same path, and dlopen
  // would return the first object again. The descriptor stays open as long
  // as the object stays loaded: for the life of the process.
  void* handle = ::dlopen(("/proc/self/fd/" + std::to_string(fd)).c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* load_error = ::dlerror();
    ::close(fd);
    throw std::runtime_error(std::string("dlopen: ") + (load_error ? load_error : "failed"));
  }
  ::dlerror();
  void* address = ::dlsym(handle, symbol.c_str());
  if (!address) {
    const char* e = ::dlerror();
    throw std::runtime_error("dlsym " + symbol + ": " + (e ? e : "not found"));
  }
  return address;
}

}  // namespace arnoldweb::detail
