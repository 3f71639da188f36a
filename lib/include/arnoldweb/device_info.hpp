// arnoldweb: what a device is, as values (its memory bounds plans before they
// run: check_memory, plan.hpp); device.hpp lists, opens and runs devices.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace arnoldweb {

struct DeviceInfo {
  std::string id;        // "cpu", "opencl:0", "cuda:0"
  std::string backend;   // "cpu", "opencl", "cuda"
  std::string name;      // e.g. "NVIDIA H200", "pthread-skylake-avx512-..."
  std::string vendor;
  std::string version;   // driver / platform version
  bool fp64 = true;
  unsigned compute_units = 0;
  std::uint64_t memory = 0;  // bytes of global memory
  std::uint64_t max_allocation = 0;  // bytes of the largest single buffer (0: memory)
  bool is_cpu = false;
};

// Where a device's start-up went, in seconds (summary.json's "startup",
// docs/performance.md): opening it (context, queues; open_backend), its
// kernels for the plan (compiled, or found in a cache, and loaded on the
// device), the rest of preparing (buffers, parameters), and the first launch
// (from its start until its outputs are on the host; 0: the device ran none).
struct DeviceStartup {
  std::string id;
  double open_seconds = 0;
  double kernel_seconds = 0;
  // where the kernels came from: "compiled", "disk" (the kernel cache),
  // "memory" (compiled for another device or part of this process), "driver"
  // (built by the OpenCL driver, which may keep its own cache), "built in" (cpu)
  std::string kernel_from;
  double buffers_seconds = 0;
  double first_launch_seconds = 0;
};

// A run's start-up: asking the drivers for their devices, once per process
// (seconds by backend, "cuda" and "opencl"; none where only the cpu backend
// was asked for), then each device's.
struct Startup {
  std::map<std::string, double> inventory_seconds;
  std::vector<DeviceStartup> devices;
};

}  // namespace arnoldweb
