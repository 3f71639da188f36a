// arnoldweb run: the devices opened while the scene is planned (device_opening.hpp).
#include "device_opening.hpp"

namespace arnoldweb::cli {

DeviceOpening::DeviceOpening(const std::string& device) {
  std::packaged_task<std::vector<std::unique_ptr<Backend>>()> task([device] { return open_backends(device); });
  opened_ = task.get_future();
  thread_ = std::thread(std::move(task));
}

std::vector<std::unique_ptr<Backend>> DeviceOpening::take() {
  if (thread_.joinable()) thread_.join();
  return opened_.get();
}

DeviceOpening::~DeviceOpening() {
  if (thread_.joinable()) thread_.join();
}

}  // namespace arnoldweb::cli
