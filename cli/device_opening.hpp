// arnoldweb run: the devices of a run opened while its scene is planned. Once
// the scene is read, its devices are known; opening them (the drivers'
// inventory, a GPU's context) goes on in a thread of its own while the plan
// is made and checked (an auto step's pilot, state files, the output place).
// Errors keep their order: a scene or output problem found while planning is
// the one reported (the opening is waited for, and what it opened closed),
// then a device problem of the opening (DeviceError, exit 4).
#pragma once

#include <future>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "arnoldweb/device.hpp"

namespace arnoldweb::cli {

class DeviceOpening {
 public:
  // Starts open_backends(device) in a thread of its own.
  explicit DeviceOpening(const std::string& device);
  // The devices, or what opening them threw, once the thread has ended. Once.
  std::vector<std::unique_ptr<Backend>> take();
  // Waits for the thread if take() did not.
  ~DeviceOpening();
  DeviceOpening(const DeviceOpening&) = delete;
  DeviceOpening& operator=(const DeviceOpening&) = delete;

 private:
  // A thread joined before the result is taken (an async's future, once read, no longer
  // waits for its thread): no thread of the opening outlives take() or the destructor.
  std::future<std::vector<std::unique_ptr<Backend>>> opened_;
  std::thread thread_;
};

}  // namespace arnoldweb::cli
