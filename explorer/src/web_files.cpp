#include "web_files.hpp"

#include <stdexcept>
#include <utility>

namespace arnoldweb::detail {
const std::vector<std::pair<const char*, std::string_view>>& explorer_web_files();  // generated
}

namespace arnoldweb::explorer {

std::optional<std::string_view> web_file(const std::string& name) {
  for (const auto& [n, bytes] : detail::explorer_web_files())
    if (name == n) return bytes;
  return std::nullopt;
}

std::vector<std::string> web_file_names() {
  std::vector<std::string> out;
  for (const auto& f : detail::explorer_web_files()) out.emplace_back(f.first);
  return out;
}

std::string content_type(const std::string& name) {
  const auto ends = [&](const char* ext) {
    const std::string e(ext);
    return name.size() >= e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0;
  };
  if (ends(".html")) return "text/html; charset=utf-8";
  if (ends(".js")) return "text/javascript; charset=utf-8";
  if (ends(".css")) return "text/css; charset=utf-8";
  if (ends(".json")) return "application/json";
  if (ends(".svg")) return "image/svg+xml";
  if (ends(".png")) return "image/png";
  return "application/octet-stream";
}

std::string page_with_scripts(const std::string& scripts) {
  static const std::string marker = "<!-- runs: arnoldweb view puts its data scripts here -->";
  std::string page(*web_file("index.html"));
  const auto at = page.find(marker);
  if (at == std::string::npos) throw std::logic_error("explorer/web/index.html lacks the data scripts' marker");
  return page.replace(at, marker.size(), scripts);
}

}  // namespace arnoldweb::explorer
