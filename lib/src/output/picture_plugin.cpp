// arnoldweb: opening the pictures' plugin (picture_plugin.hpp).
#include "output/picture_plugin.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <mutex>

#include "arnoldweb/version.hpp"

namespace arnoldweb::detail {
namespace {

constexpr const char* kPluginName = "libarnoldweb_pictures.so";

// The folder this library was loaded from ("" if unknown).
std::string own_dir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&picture_functions), &info) == 0 || !info.dli_fname) return {};
  std::string path = info.dli_fname;
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

std::string plugin_path() {
  if (const char* forced = std::getenv("ARNOLDWEB_PICTURES"); forced && *forced) return forced;
  const std::string dir = own_dir();
  return dir.empty() ? kPluginName : dir + "/" + kPluginName;
}

}  // namespace

const PictureFunctions* open_picture_plugin(const std::string& path, std::string* why) {
  auto fail = [&](const std::string& what) -> const PictureFunctions* {
    if (why) *why = what;
    return nullptr;
  };
  void* lib = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!lib) {
    const char* e = dlerror();
    return fail("the pictures' plugin could not be opened: " + std::string(e ? e : path));
  }
  using Entry = const PictureFunctions* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(lib, kPictureEntryPoint));
  const PictureFunctions* f = entry ? entry() : nullptr;
  if (!f) {
    dlclose(lib);
    return fail(path + " is not arnoldweb's pictures plugin (no " + kPictureEntryPoint + ")");
  }
  if (f->size != sizeof(PictureFunctions) || !f->version || std::strcmp(f->version, ARNOLDWEB_VERSION) != 0) {
    const std::string v = f->version ? f->version : "?";
    dlclose(lib);
    return fail(path + " is the pictures plugin of arnoldweb " + v + ", not of this library (" + ARNOLDWEB_VERSION +
                ")");
  }
  return f;  // stays open for the life of the process
}

const PictureFunctions* picture_functions(std::string* why) {
  static std::once_flag once;
  static const PictureFunctions* functions = nullptr;
  static std::string problem;
  std::call_once(once, [] {
#ifdef ARNOLDWEB_HAVE_CAIRO
    functions = open_picture_plugin(plugin_path(), &problem);
#else
    if (const char* forced = std::getenv("ARNOLDWEB_PICTURES"); forced && *forced)
      functions = open_picture_plugin(forced, &problem);
    else
      problem = "this build has no pictures (cairo was not found when it was configured)";
#endif
  });
  if (!functions && why) *why = problem;
  return functions;
}

}  // namespace arnoldweb::detail
