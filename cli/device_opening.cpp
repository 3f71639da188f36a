// arnoldweb run: the devices opened while the scene is planned (device_opening.hpp).
#include "device_opening.hpp"

namespace arnoldweb::cli {

DeviceOpening::DeviceOpening(const std::string& device)
    : opened_(std::async(std::launch::async, [device] { return open_backends(device); })) {}

std::vector<std::unique_ptr<Backend>> DeviceOpening::take() { return opened_.get(); }

}  // namespace arnoldweb::cli
