// arnoldweb: a job over several devices of this process (cluster.hpp:
// run_job_on_devices): one worker thread per device, the coordinator in the
// calling thread, linked by LocalLinks. Also rank 0's own device under MPI.
#include <exception>
#include <thread>

#include "arnoldweb/cluster.hpp"
#include "arnoldweb/errors.hpp"
#include "scale/coordinator.hpp"
#include "scale/local_devices.hpp"
#include "scale/messages.hpp"
#include "scale/worker.hpp"

namespace arnoldweb {
namespace detail {

void local_worker(const Job& job, Backend& backend, Channel& channel, const RunOptions& options,
                  const std::string& who) {
  try {
    work_job(job, backend, channel, options);
  } catch (const std::exception& e) {
    Message m;
    m.type = MessageType::Error;
    m.text = who + " (device " + backend.info().id + ", " + backend.info().name + ") failed: " + e.what();
    channel.send(encode(m));
  }
}

namespace {

// The kernels of several devices, for the result: one description if they
// share it, else each device's; and how many devices ran.
std::string kernels_of(const std::vector<Backend*>& devices) {
  std::string one = devices[0]->kernel_description(), each;
  bool same = true;
  for (Backend* d : devices) {
    same &= d->kernel_description() == one;
    each += (each.empty() ? "" : " | ") + d->info().id + ": " + d->kernel_description();
  }
  return (same ? one : each) + "; " + std::to_string(devices.size()) + " devices of this process (threads)";
}

}  // namespace
}  // namespace detail

JobResult run_job_on_devices(const Job& job, const std::vector<Backend*>& devices, const RunOptions& options,
                             JobObserver* observer) {
  if (devices.empty()) throw DeviceError("", "", 0, "run_job_on_devices without a device");
  detail::LocalLinks links(static_cast<int>(devices.size()));
  detail::LocalTransport transport(links);
  std::vector<std::thread> threads;
  for (std::size_t w = 0; w < devices.size(); ++w)
    threads.emplace_back(detail::local_worker, std::cref(job), std::ref(*devices[w]), std::ref(links.channel(static_cast<int>(w))),
                         std::cref(options), "worker " + std::to_string(w));
  JobResult r;
  try {
    std::vector<DeviceInfo> infos;
    for (Backend* d : devices) infos.push_back(d->info());
    r = detail::coordinate_job(job, transport, options, observer, describe_devices(infos), [&](Result& part) {
      part.kernel = detail::kernels_of(devices);
      part.startup.inventory_seconds = inventory_seconds();
      for (const Backend* d : devices) part.startup.devices.push_back(d->startup);
    });
  } catch (...) {
    detail::Message end;
    end.type = detail::MessageType::End;
    for (std::size_t w = 0; w < devices.size(); ++w) links.send(static_cast<int>(w), detail::encode(end));
    for (auto& t : threads) t.join();
    throw;
  }
  for (auto& t : threads) t.join();
  return r;
}

JobResult run_job_on(const Job& job, const std::vector<Backend*>& devices, const RunOptions& options,
                     JobObserver* observer) {
  if (devices.size() == 1) return run_job(job, *devices[0], options, observer);
  return run_job_on_devices(job, devices, options, observer);
}

}  // namespace arnoldweb
