// arnoldweb: finding devices and opening backends by id.
#include <cstdlib>
#include <sstream>

#include "arnoldweb/device.hpp"
#include "arnoldweb/errors.hpp"
#include "aw_params.h"
#include "backends/backends.hpp"

namespace arnoldweb {
namespace {

struct Inventory {
  std::vector<DeviceInfo> devices;
  std::vector<std::string> problems;
};

void take_inventory(Inventory& inv) {
  inv.devices.push_back(detail::cpu_device_info());
#ifdef ARNOLDWEB_HAVE_CUDA
  for (auto& d : detail::cuda_devices(inv.problems)) inv.devices.push_back(d);
#else
  inv.problems.push_back("cuda: this build has no CUDA backend (the CUDA toolkit was not found "
                         "when it was configured)");
#endif
  for (auto& d : detail::opencl_devices(inv.problems)) inv.devices.push_back(d);
}

// Devices do not come and go while a program runs: every backend is asked once.
const Inventory& inventory() {
  static const Inventory inv = [] {
    Inventory i;
    take_inventory(i);
    return i;
  }();
  return inv;
}

std::string device_list(const std::vector<DeviceInfo>& devs) {
  std::ostringstream o;
  for (const auto& d : devs) o << "\n  " << d.id << "  " << d.name;
  return o.str();
}

}  // namespace

std::vector<DeviceInfo> list_devices() { return inventory().devices; }
std::vector<std::string> backend_problems() { return inventory().problems; }

std::string default_device_id() {
  const auto devs = list_devices();
  for (const auto& d : devs)
    if (d.backend == "cuda") return d.id;
  for (const auto& d : devs)
    if (d.backend == "opencl" && !d.is_cpu) return d.id;
  for (const auto& d : devs)
    if (d.backend == "opencl") return d.id;
  return "cpu";
}

std::unique_ptr<Backend> open_backend(const std::string& requested) {
  std::string id = requested;
  if (id.empty() || id == "auto") {
    const char* env = std::getenv("ARNOLDWEB_DEVICE");
    id = (env && *env) ? env : default_device_id();
  }
  if (id == "cpu") return detail::make_cpu_backend();
  auto colon = id.find(':');
  const std::string kind = id.substr(0, colon);
  int index = -1;
  if (colon != std::string::npos) {
    try {
      std::size_t used = 0;
      index = std::stoi(id.substr(colon + 1), &used);
      if (used != id.size() - colon - 1) index = -1;
    } catch (...) {
      index = -1;
    }
  }
  const Inventory& inv = inventory();
  auto known = [&](const std::string& k) {
    for (const auto& d : inv.devices)
      if (d.id == k) return true;
    return false;
  };
  if ((kind == "opencl" || kind == "cuda") && index >= 0 && known(id)) {
    if (kind == "opencl") return detail::make_opencl_backend(index);
#ifdef ARNOLDWEB_HAVE_CUDA
    return detail::make_cuda_backend(index);
#endif
  }
  std::string why;
  for (const auto& p : inv.problems)
    if (p.rfind(kind, 0) == 0) why += "\n" + p;
  throw DeviceError(id, "", 0,
                    "no such device; devices present:" + device_list(inv.devices) + why);
}

namespace detail {

void require_fp64(const Plan& plan, const DeviceInfo& dev) {
  if (plan.kernel.precision == Precision::Double && !dev.fp64)
    throw DeviceError(dev.id, "", 0,
                      dev.name + " has no double precision (fp64); set integrator.precision = \"float\" "
                      "or choose another device (arnoldweb devices lists them)");
}

std::uint64_t floor_pow2(std::uint64_t n) {
  std::uint64_t p = 1;
  while (p * 2 <= n) p *= 2;
  return p;
}

void check_device_memory(const Plan& plan, const DeviceInfo& dev, std::uint64_t max_chunk,
                         std::uint64_t max_alloc) {
  const double map_bytes = static_cast<double>(plan.hist_size) * 12.0;  // 32-bit chunk + 64-bit total
  const double avail = static_cast<double>(dev.memory);
  if (plan.hist_size && avail > 0 &&
      (map_bytes > 0.5 * avail || plan.hist_size * 8.0 > static_cast<double>(max_alloc))) {
    SourcePos p = plan.scene.pos("observe.velocity_map.nside");
    throw SceneError(plan.scene.file, p.line, p.column, "observe.velocity_map.nside",
                     "nside = " + std::to_string(plan.scene.nside) + " needs " +
                         std::to_string(static_cast<long long>(map_bytes / 1048576.0)) +
                         " MiB for the map; " + dev.id + " (" + dev.name + ") has " +
                         std::to_string(static_cast<long long>(avail / 1048576.0)) +
                         " MiB (largest buffer " +
                         std::to_string(static_cast<long long>(max_alloc / 1048576)) +
                         " MiB): choose a smaller nside");
  }
  const int real_size = plan.kernel.precision == Precision::Float ? 4 : 8;
  double state_bytes = 0;
  if (plan.kernel.features & AW_F_INITIAL_STATES) state_bytes += AW_STATE_REALS * real_size;
  if (plan.kernel.features & AW_F_FINAL_STATES) state_bytes += AW_STATE_REALS * real_size + AW_STATE_INTS * 8;
  if (avail > 0 && state_bytes * static_cast<double>(max_chunk) + map_bytes > 0.8 * avail)
    throw DeviceError(dev.id, "", 0,
                      "not enough memory for state records of " + std::to_string(max_chunk) +
                          " trajectories per chunk; set ensemble.chunk smaller");
}

}  // namespace detail
}  // namespace arnoldweb
