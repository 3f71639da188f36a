// arnoldweb: error types (messages are composed here, once).
#include "arnoldweb/errors.hpp"

namespace arnoldweb {
namespace {

std::string scene_what(const std::string& file, int line, int column, const std::string& key,
                       const std::string& message) {
  std::string where = file.empty() ? std::string("<scene>") : file;
  if (line > 0) where += ":" + std::to_string(line) + ":" + std::to_string(column);
  return where + ": " + (key.empty() ? "" : key + ": ") + message;
}

}  // namespace

SceneError::SceneError(std::string file, int line, int column, std::string key,
                       std::string message)
    : Error(scene_what(file, line, column, key, message)),
      file_(std::move(file)),
      key_(std::move(key)),
      message_(std::move(message)),
      line_(line),
      column_(column) {}

DeviceError::DeviceError(std::string device, std::string call, long status, std::string message)
    : Error((device.empty() ? std::string() : device + ": ") + message +
            (call.empty() ? std::string()
                          : " (" + call + " returned " + std::to_string(status) + ")")),
      device_(std::move(device)),
      call_(std::move(call)),
      status_(status) {}

BuildError::BuildError(std::string device, std::string options, std::string log)
    : Error(device + ": kernel build failed\noptions: " + options + "\nbuild log:\n" + log),
      options_(std::move(options)),
      log_(std::move(log)) {}

StateError::StateError(std::string source, std::string dataset, std::int64_t row, std::string message)
    : Error(source + ": " + (dataset.empty() ? std::string() : dataset + (row >= 0 ? ", " : ": ")) +
            (row >= 0 ? "row " + std::to_string(row) + ": " : std::string()) + message),
      source_(std::move(source)),
      dataset_(std::move(dataset)),
      message_(std::move(message)),
      row_(row) {}

OutputError::OutputError(std::string path, std::string message)
    : Error((path.empty() ? std::string() : path + ": ") + message), path_(std::move(path)) {}

}  // namespace arnoldweb
