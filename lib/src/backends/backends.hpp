// arnoldweb: what each backend offers the registry (registry.cpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "arnoldweb/device.hpp"

namespace arnoldweb::detail {

DeviceInfo cpu_device_info();
std::unique_ptr<Backend> make_cpu_backend();

// Devices of every OpenCL platform, numbered opencl:0, opencl:1, ... in
// platform order. Appends to `problems` why there are none, if so.
std::vector<DeviceInfo> opencl_devices(std::vector<std::string>& problems);
std::unique_ptr<Backend> make_opencl_backend(int index);

#ifdef ARNOLDWEB_HAVE_CUDA
std::vector<DeviceInfo> cuda_devices(std::vector<std::string>& problems);
std::unique_ptr<Backend> make_cuda_backend(int index);
#endif

// Helpers shared by the backends.
// Throws DeviceError if the plan computes in double and the device has no fp64.
void require_fp64(const Plan& plan, const DeviceInfo& dev);
// Largest power of two <= n (n >= 1).
std::uint64_t floor_pow2(std::uint64_t n);
// Checks that the plan's buffers fit the device; throws SceneError naming the
// key to change (nside, states) or DeviceError.
void check_device_memory(const Plan& plan, const DeviceInfo& dev, std::uint64_t max_chunk,
                         std::uint64_t max_alloc);

}  // namespace arnoldweb::detail
