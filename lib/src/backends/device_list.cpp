// arnoldweb: the devices a run.device value names (device.hpp: device_ids,
// open_backends, describe_devices): "auto", "all", one id or a list of ids.
#include <algorithm>
#include <cstdlib>

#include "arnoldweb/device.hpp"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/scene.hpp"
#include "backends/open_at_once.hpp"

namespace arnoldweb {
namespace {

// What "all" means on this machine: every GPU, each once (a GPU that both
// CUDA and OpenCL see is counted by CUDA only); without one, the default device.
std::vector<std::string> every_gpu() {
  std::vector<std::string> cuda, opencl_gpus;
  for (const DeviceInfo& d : list_devices()) {
    if (d.backend == "cuda") cuda.push_back(d.id);
    if (d.backend == "opencl" && !d.is_cpu) opencl_gpus.push_back(d.id);
  }
  if (!cuda.empty()) return cuda;
  if (!opencl_gpus.empty()) return opencl_gpus;
  return {default_device_id()};
}

}  // namespace

std::vector<std::string> device_ids(const std::string& device) {
  // where the value came from, for messages: the scene's run.device, or the environment
  std::string spec = device, source, from = "run.device";
  if (spec.empty() || spec == "auto") {
    const char* env = std::getenv("ARNOLDWEB_DEVICE");
    spec = (env && *env && std::string(env) != "auto") ? env : default_device_id();
    if (env && *env) source = "environment", from = "ARNOLDWEB_DEVICE";
  }
  if (spec == "all") return every_gpu();
  const std::vector<std::string> ids = device_entries(spec);
  for (const std::string& id : ids)
    if (!is_device_id(id))
      throw SceneError(source, 0, 0, from,
                       "\"" + printable(spec) + "\" is not a device: give \"auto\", \"all\", \"cpu\", \"opencl:N\", \"cuda:N\" "
                       "or a list of ids such as \"cuda:0,cuda:1\" (`arnoldweb devices` lists them)");
  if (const std::string twice = repeated_device(spec); !twice.empty())
    throw SceneError(source, 0, 0, from, "\"" + printable(spec) + "\" lists " + printable(twice) + " twice; a list names each device once");
  for (const std::string& id : ids) find_device(id);  // DeviceError for a device this machine lacks
  return ids;
}

std::vector<std::unique_ptr<Backend>> open_backends(const std::string& device) {
  return detail::open_at_once(device_ids(device), [](const std::string& id) { return open_backend(id); });
}

DeviceInfo describe_devices(const std::vector<DeviceInfo>& devices) {
  if (devices.size() == 1) return devices.front();
  DeviceInfo all;
  bool same_name = true;
  for (const DeviceInfo& d : devices) same_name &= d.name == devices.front().name;
  auto join = [&](std::string DeviceInfo::*field, const char* sep) {  // each value once
    std::vector<std::string> seen;
    std::string s;
    for (const DeviceInfo& d : devices) {
      if (std::find(seen.begin(), seen.end(), d.*field) != seen.end()) continue;
      seen.push_back(d.*field);
      s += (s.empty() ? "" : sep) + d.*field;
    }
    return s;
  };
  for (const DeviceInfo& d : devices) {
    all.id += (all.id.empty() ? "" : ",") + d.id;
    all.fp64 = all.fp64 && d.fp64;
    all.compute_units += d.compute_units;
    all.memory += d.memory;
    all.is_cpu = all.is_cpu || d.is_cpu;
  }
  all.backend = join(&DeviceInfo::backend, "+");
  all.name = same_name ? std::to_string(devices.size()) + " x " + devices.front().name : join(&DeviceInfo::name, " + ");
  all.vendor = join(&DeviceInfo::vendor, " + ");
  all.version = join(&DeviceInfo::version, " + ");
  return all;
}

}  // namespace arnoldweb
