// arnoldweb: CUDA device discovery (see cuda_device.hpp).
#include "backends/cuda/cuda_device.hpp"

#include "backends/backends.hpp"
#include "backends/cuda/cuda_error.hpp"
#include "backends/cuda/nvrtc_api.hpp"

namespace arnoldweb::detail {
namespace {

// The runtime this library is linked with needs a driver of the same major
// CUDA version or newer (minor-version compatibility).
constexpr int kRuntimeVersion = CUDART_VERSION;
constexpr int kRequiredDriver = CUDART_VERSION / 1000 * 1000;

std::string version_text(int v) {
  return std::to_string(v / 1000) + "." + std::to_string(v % 1000 / 10);
}

std::string id_of(int ordinal) { return "cuda:" + std::to_string(ordinal); }

int attribute(cudaDeviceAttr a, int ordinal) {
  int v = 0;
  cuda_check(cudaDeviceGetAttribute(&v, a, ordinal), id_of(ordinal), "cudaDeviceGetAttribute");
  return v;
}

}  // namespace

int cuda_device_count(std::string& problem) {
  int driver = 0;
  const cudaError_t dv = cudaDriverGetVersion(&driver);
  if (dv != cudaSuccess || driver == 0) {
    cudaGetLastError();
    problem = "cuda: no CUDA driver found (libcuda.so.1 could not be loaded); install the NVIDIA "
              "driver to use NVIDIA GPUs";
    return 0;
  }
  if (driver < kRequiredDriver) {
    problem = "cuda: driver too old: driver supports CUDA " + version_text(driver) +
              ", this build needs " + version_text(kRequiredDriver) + " (CUDA runtime " +
              version_text(kRuntimeVersion) + "); update the NVIDIA driver";
    return 0;
  }
  int n = 0;
  const cudaError_t e = cudaGetDeviceCount(&n);
  cudaGetLastError();  // not sticky, but leave no trace for later calls
  if (e == cudaErrorNoDevice || (e == cudaSuccess && n <= 0)) {
    problem = "cuda: no CUDA device (the driver, CUDA " + version_text(driver) +
              ", reports none; check nvidia-smi and CUDA_VISIBLE_DEVICES)";
    return 0;
  }
  if (e == cudaErrorInsufficientDriver || e == cudaErrorCallRequiresNewerDriver) {
    problem = "cuda: driver too old: driver supports CUDA " + version_text(driver) +
              ", this build needs " + version_text(kRequiredDriver) + " (" + cuda_status_text(e) + ")";
    return 0;
  }
  if (e != cudaSuccess) {
    problem = "cuda: cudaGetDeviceCount returned " + std::to_string(static_cast<int>(e)) + " (" +
              cuda_status_text(e) + ")";
    return 0;
  }
  // the kernels are compiled at run time: without NVRTC the devices cannot run
  std::string nvrtc_problem;
  if (!nvrtc_api(&nvrtc_problem)) {
    problem = "cuda: " + std::to_string(n) + " device(s), but " + nvrtc_problem;
    return 0;
  }
  return n;
}

int cuda_compute_capability(int ordinal) {
  return attribute(cudaDevAttrComputeCapabilityMajor, ordinal) * 10 +
         attribute(cudaDevAttrComputeCapabilityMinor, ordinal);
}

DeviceInfo cuda_describe(int ordinal) {
  DeviceInfo info;
  info.id = id_of(ordinal);
  info.backend = "cuda";
  cudaDeviceProp prop{};
  cuda_check(cudaGetDeviceProperties(&prop, ordinal), info.id, "cudaGetDeviceProperties");
  info.name = prop.name;
  info.vendor = "NVIDIA";
  int driver = 0, runtime = 0;
  cudaDriverGetVersion(&driver);
  cudaRuntimeGetVersion(&runtime);
  info.version = "compute " + std::to_string(prop.major) + "." + std::to_string(prop.minor) +
                 ", driver " + version_text(driver) + ", runtime " + version_text(runtime);
  info.fp64 = true;  // every CUDA device has IEEE double
  info.compute_units = static_cast<unsigned>(prop.multiProcessorCount);
  info.memory = static_cast<std::uint64_t>(prop.totalGlobalMem);
  info.is_cpu = false;
  return info;
}

std::vector<DeviceInfo> cuda_devices(std::vector<std::string>& problems) {
  std::vector<DeviceInfo> out;
  std::string problem;
  const int n = cuda_device_count(problem);
  if (n == 0) problems.push_back(problem);
  for (int i = 0; i < n; ++i) {
    try {
      out.push_back(cuda_describe(i));
    } catch (const DeviceError& e) {
      problems.push_back(std::string("cuda: device ") + std::to_string(i) + " cannot be queried: " +
                         e.what());
    }
  }
  return out;
}

}  // namespace arnoldweb::detail
