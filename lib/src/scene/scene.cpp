// arnoldweb scene layer: the entry points. A scene is read in four steps:
// TOML syntax, --set overrides applied on top, every section and key known,
// every value of the right type and range. All problems are collected; the
// first one (in file order, then the overrides in order) is thrown.
#include "arnoldweb/scene.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "arnoldweb/errors.hpp"
#include "scene/scene_internal.hpp"

namespace arnoldweb {

const char* to_string(Precision p) {
  for (const auto& n : scene_detail::precision_names())
    if (n.value == p) return n.name;
  return "?";
}

const char* to_string(MathMode m) {
  for (const auto& n : scene_detail::math_names())
    if (n.value == m) return n.name;
  return "?";
}

SourcePos Scene::pos(const std::string& key) const {
  auto it = where.find(key);
  return it == where.end() ? SourcePos{} : it->second;
}

std::string Scene::origin(const std::string& key) const {
  const SourcePos p = pos(key);
  if (p.set_index > 0 && static_cast<std::size_t>(p.set_index) <= overrides.size()) {
    const auto i = static_cast<std::size_t>(p.set_index - 1);
    if (i < override_labels.size() && !override_labels[i].empty()) return override_labels[i];
    return "--set " + overrides[i];
  }
  if (p.line > 0) return file + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
  return "default";
}

Scene parse_scene(const std::string& text, const std::string& file,
                  const std::vector<std::string>& overrides, const std::vector<std::string>& labels) {
  using namespace scene_detail;
  Scene scene;
  scene.file = file.empty() ? "<string>" : file;
  scene.overrides = overrides;
  scene.override_labels = labels;
  scene.override_labels.resize(overrides.size());
  scene.text = text;

  check_text_limits(text, scene.file);
  toml::table root;
  try {
    root = toml::parse(text, scene.file);
  } catch (const toml::parse_error& e) {
    throw SceneError(scene.file, static_cast<int>(e.source().begin.line),
                     static_cast<int>(e.source().begin.column), "",
                     "TOML syntax error: " + std::string(e.description()));
  }

  Origins origins;
  origins.file = scene.file;
  origins.labels = scene.override_labels;
  Problems problems(origins);
  apply_overrides(root, overrides, origins, problems);
  check_structure(root, problems);
  read_values(root, origins, problems, scene);
  if (!problems.empty()) problems.throw_first();
  return scene;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides,
                 const std::vector<std::string>& labels) {
  using scene_detail::kMaxSceneBytes;
  auto fail = [&](const std::string& what) {
    throw SceneError(path, 0, 0, "", "cannot read the scene file: " + what);
  };
  if (path.empty()) fail("no file name given");
  // O_NONBLOCK: opening a FIFO must not wait for a writer
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) fail(std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    fail(S_ISDIR(st.st_mode)    ? "it is a directory"
         : S_ISFIFO(st.st_mode) ? "it is a pipe (FIFO), not a file"
         : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "it is a device, not a file"
                                                      : "it is not a regular file");
  }
  if (static_cast<std::uint64_t>(st.st_size) > kMaxSceneBytes) {
    ::close(fd);
    fail("it is " + std::to_string(st.st_size) + " bytes; scenes of at most " + std::to_string(kMaxSceneBytes) +
         " bytes are read");
  }
  std::string text;
  char buf[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      const int err = errno;
      ::close(fd);
      fail(std::strerror(err));
    }
    text.append(buf, static_cast<std::size_t>(n));
    if (text.size() > kMaxSceneBytes) {  // it grew while being read
      ::close(fd);
      fail("it is larger than " + std::to_string(kMaxSceneBytes) + " bytes");
    }
  }
  ::close(fd);
  return parse_scene(text, path, overrides, labels);
}

}  // namespace arnoldweb
