#include "support.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace awtest {

std::string g_backend;  // set by main.cpp from --backend

const std::vector<arnoldweb::DeviceInfo>& devices_under_test() {
  static const std::vector<arnoldweb::DeviceInfo> devs = [] {
    std::vector<arnoldweb::DeviceInfo> out;
    for (const auto& d : arnoldweb::list_devices())
      if (g_backend.empty() || d.backend == g_backend) out.push_back(d);
    return out;
  }();
  return devs;
}

arnoldweb::Scene scene_from(const std::string& toml, const std::vector<std::string>& sets) {
  return arnoldweb::parse_scene(toml, "<test>", sets);
}

arnoldweb::Result run_on(const std::string& device, const arnoldweb::Plan& plan) {
  auto backend = arnoldweb::open_backend(device);
  return arnoldweb::run(plan, *backend);
}

std::string temp_dir(const std::string& tag) {
  namespace fs = std::filesystem;
  static const fs::path root = [] {
    std::string templ = (fs::temp_directory_path() / "arnoldweb-test-XXXXXX").string();
    if (!mkdtemp(templ.data())) std::abort();
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(root, ec);
    });
    return fs::path(templ);
  }();
  static int counter = 0;
  fs::path p = root / (tag + "-" + std::to_string(counter++));
  fs::create_directories(p);
  return p.string();
}

int run_cli(const std::string& args, std::string* out) {
  const std::string cmd = std::string(ARNOLDWEB_CLI) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return -1;
  std::string text;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) text.append(buf.data(), n);
  const int status = pclose(pipe);
  if (out) *out = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace awtest
