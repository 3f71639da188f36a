// arnoldweb: what a plan will need in memory, on the device and in this
// process, and the refusal (before anything is computed) of what does not fit,
// naming the key to change and the numbers (plan.hpp).
#include <algorithm>
#include <cstdio>

#include "arnoldweb/device_info.hpp"
#include "arnoldweb/plan.hpp"
#include "aw_params.h"
#include "plan/checks.hpp"
#include "plan/plan_params.hpp"

namespace arnoldweb {
namespace {

constexpr std::uint64_t kMaxChunkStates = 1u << 20;  // trajectories per launch with state records
constexpr std::uint64_t kMaxChunk = 1ull << 30;
constexpr double kMaxSeriesBytes = 2.0 * (1ull << 30);  // the work memory of one launch (frequency samples)
// On a CPU only the trajectories in flight (threads x lanes) use their series at a time: a smaller
// launch costs nothing there, while every byte of a fresh buffer is a page the kernel must clear
// (2 GB of them were 28 % of a 100,000-trajectory frequency run on 2 cores).
constexpr double kCpuSeriesBytes = 256.0 * (1ull << 20);

std::string mib(double bytes) {
  char b[32];
  std::snprintf(b, sizeof b, "%.0f MiB", bytes / 1048576.0);
  return b;
}

// Per-trajectory records (the output table's outputs), whatever they are.
bool has_states(const Plan& p) {
  const detail::IntParams& ip = detail::params(p).ints;
  return ip.rec_reals + ip.rec_ints > 0;
}

// Bytes of the records of one trajectory on the device, and on the host.
double state_bytes(const Plan& p, double real_size) {
  const detail::IntParams& ip = detail::params(p).ints;
  return static_cast<double>(ip.rec_reals) * real_size + static_cast<double>(ip.rec_ints) * 8;
}

// Bytes of one trajectory's work memory on the device.
double series_bytes(const Plan& p, double real_size) {
  return static_cast<double>(detail::params(p).ints.series_reals) * real_size;
}

// The key that makes the histograms large.
std::string histogram_key(const Plan& p) {
  const double zoom = static_cast<double>(p.zoom_resolution) * p.zoom_resolution;
  const double maps = static_cast<double>(p.frames) * static_cast<double>(p.npix);
  if (zoom > maps) return "observe.zoom.resolution";
  if (p.frames > 1 && maps > 4.0 * static_cast<double>(p.npix)) return "observe.frames.times";
  return "observe.velocity_map.nside";
}

// NVIDIA's OpenCL: the series buffer's addresses below 2^31 bytes (largest_chunk).
constexpr double kNvidiaOpenclSeriesBytes = 2147483647.0 - 64.0 * (1ull << 20);
bool nvidia_opencl(const DeviceInfo& d) {
  const bool nvidia = d.vendor.find("NVIDIA") != std::string::npos || d.name.find("NVIDIA") != std::string::npos;
  return d.backend == "opencl" && !d.is_cpu && nvidia;
}

// The largest launch whose frequency series fit in `series_budget` bytes.
std::uint64_t largest_chunk_within(const Plan& plan, double series_budget) {
  std::uint64_t m = has_states(plan) ? kMaxChunkStates : kMaxChunk;
  // 32-bit counts per launch: the windows a launch bins * chunk must stay below 2^32 (a launch of a
  // time-sliced plan bins the windows that end in its slice: at most one more than fit in it)
  const std::int64_t windows = plan.slices > 1 ? plan.slice_segments / std::max<std::int64_t>(plan.segments_per_window, 1) + 1
                                               : plan.windows;
  m = std::min<std::uint64_t>(m, 4000000000ull / static_cast<std::uint64_t>(std::max<std::int64_t>(windows, 1)));
  const double series = series_bytes(plan, 8);
  if (series > 0) m = std::min<std::uint64_t>(m, std::max<std::uint64_t>(1, static_cast<std::uint64_t>(series_budget / series)));
  if (plan.scene.chunk) m = plan.scene.chunk;
  return std::max<std::uint64_t>(1, std::min(m, plan.scene.trajectories));
}

}  // namespace

std::uint64_t largest_chunk(const Plan& plan) { return largest_chunk_within(plan, kMaxSeriesBytes); }

std::uint64_t largest_chunk(const Plan& plan, const DeviceInfo& device) {
  if (device.is_cpu) return largest_chunk_within(plan, kCpuSeriesBytes);
  if (nvidia_opencl(device)) {
    // NVIDIA's OpenCL stops a kernel that reaches past the first 2^31 bytes of
    // the series buffer (clFinish: CL_INVALID_COMMAND_QUEUE from 44,000
    // trajectories of 2 x 512 samples on an H200, driver of 2026-11; CUDA and
    // PoCL run the same launches): its launches keep the series below that,
    // ensemble.chunk included.
    const double series = series_bytes(plan, 8);
    const std::uint64_t m = largest_chunk_within(plan, kNvidiaOpenclSeriesBytes);
    return series > 0 ? std::min<std::uint64_t>(m, std::max(1.0, kNvidiaOpenclSeriesBytes / series)) : m;
  }
  if (device.memory == 0) return largest_chunk(plan);
  double room = static_cast<double>(device.memory) / 4;
  if (device.max_allocation) room = std::min(room, static_cast<double>(device.max_allocation));
  return largest_chunk_within(plan, std::max(room, kMaxSeriesBytes));
}

MemoryEstimate estimate_memory(const Plan& plan) {
  MemoryEstimate e;
  e.max_chunk = largest_chunk(plan);
  const double rs = plan.kernel.precision == Precision::Float ? 4 : 8;
  const double hist = static_cast<double>(std::max<std::uint64_t>(plan.hist_size, 1));
  e.histogram_bytes = hist * 12;  // 32-bit chunk counts and 64-bit totals
  e.device_bytes = e.histogram_bytes + (state_bytes(plan, rs) + series_bytes(plan, rs)) * static_cast<double>(e.max_chunk) + 1e6;
  // in this process: the totals read back, the result's maps and frames, and
  // the state records of every trajectory (kept per chunk, then joined, then
  // written), besides the cpu backend's own buffers when it is the device
  const double n = static_cast<double>(plan.scene.trajectories);
  e.state_bytes = state_bytes(plan, 8) * n;
  e.host_bytes = hist * 8 * 3 + e.state_bytes * 3 + 64e6;
  return e;
}

void check_memory(const Plan& plan, const DeviceInfo& dev, std::uint64_t host_available) {
  const MemoryEstimate e = estimate_memory(plan);
  const std::uint64_t max_allocation = dev.max_allocation ? dev.max_allocation : dev.memory;
  const double avail = static_cast<double>(dev.memory);
  const std::string where = dev.id + " (" + dev.name + ")";
  if (plan.hist_size && avail > 0 &&
      (e.histogram_bytes > 0.5 * avail || plan.hist_size * 8.0 > static_cast<double>(max_allocation)))
    detail::fail_at(plan.scene, histogram_key(plan),
                    "the histograms need " + mib(e.histogram_bytes) + " on the device; " + where + " has " +
                        mib(avail) + " (largest buffer " + mib(static_cast<double>(max_allocation)) +
                        "): choose a smaller value");
  if (avail > 0 && e.device_bytes > 0.8 * avail)
    detail::fail_at(plan.scene, "ensemble.chunk",
                    "state records of " + std::to_string(e.max_chunk) + " trajectories per launch need " +
                        mib(e.device_bytes) + " on " + where + ", which has " + mib(avail) +
                        ": set ensemble.chunk smaller");
  // a CPU device (the cpu backend, PoCL) holds its buffers in this process's
  // memory too: the run holds both at once
  const double host_need = e.host_bytes + (dev.is_cpu ? e.device_bytes : 0);
  if (host_available > 0 && host_need > static_cast<double>(host_available)) {
    const bool states = e.state_bytes * 3 > e.host_bytes / 2;
    detail::fail_at(plan.scene, states ? "ensemble.trajectories" : histogram_key(plan),
                    "the run needs about " + mib(host_need) + " of memory in this process (" +
                        (states ? "state records of " + std::to_string(plan.scene.trajectories) + " trajectories"
                                : std::string("the histograms")) +
                        (dev.is_cpu ? ", with the buffers of " + where + ", which computes in this memory" : "") +
                        ") and " + mib(static_cast<double>(host_available)) +
                        " are available: choose a smaller value" +
                        (states ? " or leave observe.initial_states / observe.final_states out" : ""));
  }
}

}  // namespace arnoldweb
