// arnoldweb: the thin device layer under every backend. A ComputeDevice is
// what truly differs between the cpu backend, OpenCL and CUDA: memory, copies,
// compiling the kernels for a configuration, launching them and waiting. The
// run of an ensemble on it (buffers, launches, folding, reading back) is
// written once, in EnsembleBackend (ensemble_backend.hpp). This is the idea of
// CLBlast's clpp11.hpp / cupp11.hpp twins and of OpenMM's ComputeContext.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "arnoldweb/device.hpp"
#include "aw_params.h"

namespace arnoldweb::detail {

// A buffer in a device's memory (host memory for the cpu backend). Made by
// ComputeDevice::allocate and usable only with that device.
class DeviceMemory {
 public:
  explicit DeviceMemory(std::size_t bytes) : bytes_(bytes) {}
  virtual ~DeviceMemory() = default;
  DeviceMemory(const DeviceMemory&) = delete;
  DeviceMemory& operator=(const DeviceMemory&) = delete;
  std::size_t bytes() const { return bytes_; }

 private:
  std::size_t bytes_;
};

// How a launch over `count` trajectories is shaped.
struct LaunchShape {
  std::uint64_t groups = 0;      // work-groups (blocks); each writes AW_GROUP_STATS reals
  std::uint64_t group_size = 0;  // work-items per group
  std::uint64_t items = 0;       // work-items in all (groups * group_size)
};

// What one launch of the ensemble kernel covers: trajectories
// [first, first + count) over the segments [seg_first, seg_end) of their schedule.
struct LaunchRange {
  std::uint64_t first = 0, count = 0;
  std::int64_t seg_first = 0, seg_end = 0;
};

// The buffers of the ensemble kernel, in its argument order (AW_BUFFERS,
// aw_params.h); those the plan does not need are null.
struct EnsembleBuffers {
  DeviceMemory* at[AW_BUF_COUNT] = {};
  DeviceMemory*& operator[](int i) { return at[i]; }
};

class ComputeDevice {
 public:
  virtual ~ComputeDevice() = default;
  virtual const DeviceInfo& info() const = 0;
  // The largest single buffer, and the memory free now (0: unknown).
  virtual std::uint64_t max_allocation() const { return info().memory; }
  virtual std::uint64_t free_memory() const { return 0; }

  // Compiles (or finds in a cache) the ensemble and fold kernels for the
  // configuration. Throws BuildError, DeviceError.
  virtual void compile(const KernelConfig& config) = 0;
  virtual std::string kernel_description() const = 0;
  // Where the last compile's kernels came from (DeviceStartup::kernel_from).
  virtual std::string kernel_origin() const = 0;

  // `what` names the buffer in errors. Throws DeviceError.
  virtual std::unique_ptr<DeviceMemory> allocate(std::size_t bytes, const char* what) = 0;
  virtual void upload(DeviceMemory& to, const void* from, std::size_t bytes) = 0;
  virtual void download(const DeviceMemory& from, void* to, std::size_t bytes) = 0;
  // Host memory that a download will soon fill, `bytes` at `to`: a device may
  // lock it while its kernels run, so that the copy goes at the bus's speed
  // (CUDA). The handle lets go when its last copy goes, which must be before
  // the memory is freed (ChunkOutput::holds); null where nothing is held.
  virtual std::shared_ptr<void> hold_for_download(void* to, std::size_t bytes) {
    (void)to, (void)bytes;
    return nullptr;
  }
  virtual void zero(DeviceMemory& m) = 0;

  virtual LaunchShape shape(std::uint64_t count) const = 0;
  // The ensemble kernel over a range; may return before it is done.
  virtual void launch_ensemble(const LaunchRange& range, const LaunchShape& shape, const EnsembleBuffers& buffers) = 0;
  // The frequency analysis of trajectories [first, first + count) after their
  // ensemble launch over every segment (its samples are in the series buffer);
  // compiled, and called, only where the configuration has AW_F_FREQUENCIES.
  virtual void launch_frequencies(const LaunchRange& range, const LaunchShape& shape,
                                  const EnsembleBuffers& buffers) = 0;
  // total[i] += part[i], part[i] = 0 for i < n (64-bit totals of 32-bit counts).
  virtual void launch_fold(DeviceMemory& total, DeviceMemory& part, std::uint64_t n) = 0;
  // Waits for what was launched; errors raised inside kernels surface here,
  // reported with `what` (the launch's range of trajectories).
  virtual void finish(const std::string& what) = 0;

  // Trajectories per launch that keep the device busy.
  virtual std::uint64_t preferred_chunk() const = 0;
};

// The one Backend over a ComputeDevice.
std::unique_ptr<Backend> make_ensemble_backend(std::unique_ptr<ComputeDevice> device);

}  // namespace arnoldweb::detail
