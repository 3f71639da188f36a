// arnoldweb: opening the pictures' plugin (picture_plugin.hpp).
#include "output/picture_plugin.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <mutex>

#include "arnoldweb/version.hpp"
#include "os/shared_object.hpp"

namespace arnoldweb::detail {
namespace {

constexpr const char* kPluginName = "libarnoldweb_pictures.so";

std::string plugin_path() {
  if (const char* forced = std::getenv("ARNOLDWEB_PICTURES"); forced && *forced) return forced;
  const std::string dir = this_library_dir();
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
#ifndef ARNOLDWEB_HAVE_CAIRO
    // no plugin was built beside this library; one named by $ARNOLDWEB_PICTURES is still tried
    const char* forced = std::getenv("ARNOLDWEB_PICTURES");
    if (!forced || !*forced) {
      problem = "this build has no pictures (cairo was not found when it was configured)";
      return;
    }
#endif
    functions = open_picture_plugin(plugin_path(), &problem);
  });
  if (!functions && why) *why = problem;
  return functions;
}

}  // namespace arnoldweb::detail
