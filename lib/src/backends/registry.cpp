// arnoldweb: finding devices and opening backends by id.
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "arnoldweb/device.hpp"
#include "arnoldweb/errors.hpp"
#include "aw_params.h"
#include "backends/backends.hpp"
#include "os/quit_signal.hpp"

namespace arnoldweb {
namespace {

struct Inventory {
  std::vector<DeviceInfo> devices;
  std::vector<std::string> problems;
  std::map<std::string, double> seconds;  // by backend
};

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void take_inventory(Inventory& inv) {
  const detail::KeepQuitSignal keep;  // PoCL's LLVM would take SIGQUIT (os/quit_signal.hpp)
  inv.devices.push_back(detail::cpu_device_info());
  auto t0 = std::chrono::steady_clock::now();
#ifdef ARNOLDWEB_HAVE_CUDA
  for (auto& d : detail::cuda_devices(inv.problems)) inv.devices.push_back(d);
  inv.seconds["cuda"] = since(t0);
#else
  inv.problems.push_back("cuda: this build has no CUDA backend (the CUDA toolkit was not found "
                         "when it was configured)");
#endif
  t0 = std::chrono::steady_clock::now();
  for (auto& d : detail::opencl_devices(inv.problems)) inv.devices.push_back(d);
  inv.seconds["opencl"] = since(t0);
}

std::atomic<const Inventory*> taken{nullptr};  // the inventory, once taken

// Devices do not come and go while a program runs: every backend is asked once.
const Inventory& inventory() {
  static const Inventory inv = [] {
    Inventory i;
    take_inventory(i);
    return i;
  }();
  taken.store(&inv);
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
std::map<std::string, double> inventory_seconds() {
  const Inventory* inv = taken.load();
  return inv ? inv->seconds : std::map<std::string, double>{};
}

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

namespace {

std::string resolve_id(const std::string& requested) {
  if (!requested.empty() && requested != "auto") return requested;
  const char* env = std::getenv("ARNOLDWEB_DEVICE");
  return (env && *env) ? env : default_device_id();
}

[[noreturn]] void no_such_device(const std::string& id) {
  const Inventory& inv = inventory();
  const std::string kind = id.substr(0, id.find(':'));
  std::string why;
  for (const auto& p : inv.problems)
    if (p.rfind(kind, 0) == 0) why += "\n" + p;
  throw DeviceError(id, "", 0, "no such device; devices present:" + device_list(inv.devices) + why);
}

}  // namespace

DeviceInfo find_device(const std::string& requested) {
  const std::string id = resolve_id(requested);
  // the library's own backend: no driver need be asked (CUDA's and OpenCL's inventory
  // take tens of milliseconds, a large part of a small run)
  if (id == "cpu") return detail::cpu_device_info();
  for (const auto& d : inventory().devices)
    if (d.id == id) return d;
  no_such_device(id);
}

std::uint64_t available_memory() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  const std::string key = "MemAvailable:";
  while (std::getline(in, line))
    if (line.compare(0, key.size(), key) == 0) return std::strtoull(line.c_str() + key.size(), nullptr, 10) * 1024;
  return 0;
}

namespace {

std::unique_ptr<Backend> open_device(std::string id) {
  if (id == "all" || id.find(',') != std::string::npos) {  // several devices, or "all" of one
    const auto ids = device_ids(id);
    if (ids.size() > 1)
      throw SceneError("", 0, 0, "run.device",
                       "\"" + id + "\" names " + std::to_string(ids.size()) +
                           " devices, and this runs on one: give one id (`arnoldweb run` runs a scene on a list)");
    id = ids.front();
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
  no_such_device(id);
}

}  // namespace

std::unique_ptr<Backend> open_backend(const std::string& requested) {
  const auto t0 = std::chrono::steady_clock::now();
  std::unique_ptr<Backend> b = open_device(resolve_id(requested));
  b->startup.id = b->info().id;
  b->startup.open_seconds = since(t0);
  return b;
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

void check_device_memory(const Plan& plan, const DeviceInfo& dev, std::uint64_t, std::uint64_t max_alloc) {
  DeviceInfo d = dev;
  d.max_allocation = max_alloc;
  check_memory(plan, d, 0);
}

}  // namespace detail
}  // namespace arnoldweb
