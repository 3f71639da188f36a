// arnoldweb tests: shared helpers. The test binary takes --backend=cpu|opencl|cuda
// to restrict the device-bound suites to one backend; with none present it
// exits 77 (CTest: skipped) and says why.
#pragma once

#include <string>
#include <vector>

#include "arnoldweb/arnoldweb.hpp"

namespace awtest {

// Devices the device-bound tests run on (all present, or those of --backend).
const std::vector<arnoldweb::DeviceInfo>& devices_under_test();

// A scene from TOML text, with overrides.
arnoldweb::Scene scene_from(const std::string& toml, const std::vector<std::string>& sets = {});

// Plan and run a scene on a device, quietly.
arnoldweb::Result run_on(const std::string& device, const arnoldweb::Plan& plan);

// A fresh empty temporary directory (removed at exit).
std::string temp_dir(const std::string& tag);

// Run the arnoldweb CLI with arguments; returns the exit code, output in *out.
int run_cli(const std::string& args, std::string* out = nullptr);

}  // namespace awtest
