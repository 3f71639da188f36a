// arnoldweb scene layer: the forms of run.device (scene.hpp, docs/cluster.md):
// "auto", "all", one device id, or a comma-separated list of ids.
#include <algorithm>

#include "scene/scene_internal.hpp"

namespace arnoldweb {

std::vector<std::string> device_entries(const std::string& device) {
  std::vector<std::string> entries;
  std::size_t at = 0;
  for (;;) {
    const std::size_t comma = device.find(',', at);
    entries.push_back(device.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
    if (comma == std::string::npos) return entries;
    at = comma + 1;
  }
}

bool is_device_id(const std::string& id) {
  if (id == "cpu") return true;
  for (const std::string prefix : {"opencl:", "cuda:"}) {
    if (id.compare(0, prefix.size(), prefix) != 0) continue;
    // N as `arnoldweb devices` writes it: decimal digits without a leading zero
    // ("opencl:00" names no device, so it is no id either)
    const std::string n = id.substr(prefix.size());
    return !n.empty() && n.size() <= 9 && (n == "0" || n[0] != '0') &&
           std::all_of(n.begin(), n.end(), [](char c) { return c >= '0' && c <= '9'; });
  }
  return false;
}

std::string repeated_device(const std::string& device) {
  const auto entries = device_entries(device);
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (std::find(entries.begin(), entries.begin() + static_cast<std::ptrdiff_t>(i), entries[i]) !=
        entries.begin() + static_cast<std::ptrdiff_t>(i))
      return entries[i];
  return "";
}

namespace scene_detail {

bool valid_device(const std::string& device) {
  if (device == "auto" || device == "all") return true;
  const auto entries = device_entries(device);
  return std::all_of(entries.begin(), entries.end(), is_device_id);
}

}  // namespace scene_detail
}  // namespace arnoldweb
