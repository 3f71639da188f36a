// arnoldweb: devices and the one host interface every backend implements.
// Backends: "cpu" (the device core compiled as C++, all cores), "opencl:N"
// (every OpenCL device, PoCL on CPUs), "cuda:N" (NVIDIA GPUs, where built).
// No OpenCL or CUDA header leaks out of this file.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "arnoldweb/device_info.hpp"
#include "arnoldweb/plan.hpp"

namespace arnoldweb {

// Every device present, cpu first. Never throws: backends that cannot be
// queried (no OpenCL platform, no CUDA driver) contribute nothing, and
// backend_problems() says why.
std::vector<DeviceInfo> list_devices();
std::vector<std::string> backend_problems();
// How long list_devices' one inventory took, by backend (Startup); empty
// before it was taken (opening "cpu" takes none).
std::map<std::string, double> inventory_seconds();

// What one launch computes: trajectories [first, first + count) over the
// segments [seg_first, seg_end) of their schedule (seg_end < 0: to its end;
// a segment is the steps between two energy samples). A plan with the carry
// (open runs: time slices, states from a file) gives each launch the
// trajectories' records as the previous launch left them (or as the states
// were read), laid out as the kernel writes them.
struct ChunkWork {
  std::uint64_t first = 0, count = 0;
  std::int64_t seg_first = 0, seg_end = -1;
  const std::vector<double>* rec_r = nullptr;
  const std::vector<std::int64_t>* rec_i = nullptr;
};

// What one chunk of trajectories produced (the histogram stays on the device
// until read_histograms()).
struct ChunkOutput {
  std::vector<std::uint32_t> counters;  // AW_C_COUNT
  std::vector<double> group_stats;      // (max, sum) pairs of max|dE|
  // The chunk's records, trajectory after trajectory, as the plan lays them
  // out (the output table: rec_reals reals and rec_ints integers each).
  std::vector<double> rec_r;
  std::vector<std::int64_t> rec_i;
  // Whatever a device holds on rec_r and rec_i's memory (CUDA: the pages
  // locked for its copies), let go when the last copy of these handles goes:
  // they travel with the records, so letting go is off the run's path.
  // Declared after the records: released before their memory is freed.
  std::vector<std::shared_ptr<void>> holds;
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual const DeviceInfo& info() const = 0;
  // Compile the kernel for the plan's configuration (cached) and allocate the
  // buffers for chunks of up to max_chunk trajectories. Throws DeviceError,
  // BuildError.
  virtual void prepare(const Plan& plan, std::uint64_t max_chunk) = 0;
  // The work of one launch, count <= max_chunk. Blocks until done.
  virtual void run_chunk(const ChunkWork& work, ChunkOutput& out) = 0;
  // Trajectories [first, first + count) over their whole schedule.
  void run_chunk(std::uint64_t first, std::uint64_t count, ChunkOutput& out) {
    ChunkWork w;
    w.first = first;
    w.count = count;
    run_chunk(w, out);
  }
  // Every histogram accumulated over all chunks since prepare(), 64-bit counts
  // in the plan's layout: plan.frames maps of plan.npix pixels, then the
  // plan.zoom_resolution^2 zoom bins (plan.hist_size in all).
  virtual std::vector<std::uint64_t> read_histograms() = 0;
  // Trajectories per launch that keep the device busy (a lower bound for chunks).
  virtual std::uint64_t preferred_chunk() const = 0;
  // Compiler options / variant used, for the summary.
  virtual std::string kernel_description() const = 0;

  // Its start-up, as far as it went: filled by open_backend (opening), by
  // prepare (the kernels, the buffers) and by the chunk loop (the first launch).
  DeviceStartup startup;
};

// Open a device by id: "cpu", "opencl:N", "cuda:N", or "auto" (the first GPU,
// else the first OpenCL device, else cpu). The environment variable
// ARNOLDWEB_DEVICE, when set, replaces "auto". Throws DeviceError with the
// list of devices and, where a platform is missing, how to install one; a
// value that names several devices (a list, or "all" on a machine with
// several GPUs) is a SceneError: open_backends opens them.
std::unique_ptr<Backend> open_backend(const std::string& id);

// The id "auto" resolves to on this machine.
std::string default_device_id();

// The devices a run.device value names, as ids of this machine, in order
// (docs/cluster.md): "auto" as open_backend resolves it (ARNOLDWEB_DEVICE may
// itself be a list or "all"); "all": every GPU, each once: the CUDA devices,
// else the OpenCL devices that are not CPUs, and on a machine without a GPU
// the default device alone; a list "cuda:0,cuda:1": its ids. Throws
// SceneError (exit 2) for a malformed value or an id listed twice, DeviceError
// (exit 4) for a device this machine lacks, with the list of those present.
std::vector<std::string> device_ids(const std::string& device);
// Opens every device of device_ids(device), in that order, each in a thread of
// its own (their contexts and drivers start at once). When some fail, the
// error of the first of them in the list's order, once every thread has ended.
std::vector<std::unique_ptr<Backend>> open_backends(const std::string& device);
// What a result names when several devices computed it: the ids joined by
// ",", the names ("2 x NVIDIA H200", or "AMD EPYC + pthread-..."), the compute
// units and memory summed. One device: its own description.
DeviceInfo describe_devices(const std::vector<DeviceInfo>& devices);

// The description of the device `id` ("auto" as open_backend resolves it)
// without opening it; throws DeviceError like open_backend when there is none.
DeviceInfo find_device(const std::string& id);

// Memory this process can still use (MemAvailable), in bytes; 0 if unknown.
std::uint64_t available_memory();

}  // namespace arnoldweb
