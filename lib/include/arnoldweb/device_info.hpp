// arnoldweb: what a device is, as values (its memory bounds plans before they
// run: check_memory, plan.hpp); device.hpp lists, opens and runs devices.
#pragma once

#include <cstdint>
#include <string>

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

}  // namespace arnoldweb
