// arnoldweb: error types (messages are composed here, once).
#include "arnoldweb/errors.hpp"

#include <cstdio>

namespace arnoldweb {
namespace {

// The length of the UTF-8 sequence of a printable character at s[i]; 0 for a
// control character (C0, DEL, C1 U+0080..U+009F) or a byte that begins no
// well-formed sequence.
std::size_t printable_length(const std::string& s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  if (c < 0x20 || c == 0x7f) return 0;
  if (c < 0x80) return 1;
  const std::size_t n = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return 0;
  if (c == 0xc2 && static_cast<unsigned char>(s[i + 1]) < 0xa0) return 0;  // a C1 control
  return n;
}

std::string scene_what(const std::string& file, int line, int column, const std::string& key,
                       const std::string& message) {
  std::string where = file.empty() ? std::string("<scene>") : printable(file);
  if (line > 0) where += ":" + std::to_string(line) + ":" + std::to_string(column);
  return where + ": " + (key.empty() ? "" : key + ": ") + message;
}

}  // namespace

std::string printable(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (const std::size_t n = printable_length(text, i)) {
      out.append(text, i, n);
      i += n;
      continue;
    }
    const auto c = static_cast<unsigned char>(text[i++]);
    char buf[8];
    if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (c == '\r') out += "\\r";
    else if (c < 0x80 || (c == 0xc2 && i < text.size() && static_cast<unsigned char>(text[i]) < 0xa0)) {
      // C0, DEL, or a C1 control (U+0080..U+009F, two bytes) as \u00XX
      const unsigned code = c < 0x80 ? c : static_cast<unsigned char>(text[i++]);
      std::snprintf(buf, sizeof buf, "\\u%04x", code);
      out += buf;
    } else {
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    }
  }
  return out;
}

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
