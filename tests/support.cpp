#include "support.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

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

bool long_tests_enabled() {
  const char* v = std::getenv("ARNOLDWEB_LONG_TESTS");
  return v != nullptr && std::string(v) == "1";
}

namespace {

// Whether this process was started for the long suite by name (the command
// line, from /proc: the doctest context keeps its filters to itself).
bool long_suite_selected() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string cmdline((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t start = 0;
  while (start < cmdline.size()) {
    std::size_t end = cmdline.find('\0', start);
    if (end == std::string::npos) end = cmdline.size();
    const std::string arg = cmdline.substr(start, end - start);
    for (const char* opt : {"-ts=", "--test-suite=", "-test-suite="})
      if (arg.rfind(opt, 0) == 0 && arg.find("hard-long") != std::string::npos) return true;
    start = end + 1;
  }
  return false;
}

}  // namespace

bool require_long_tests(const std::string& what) {
  if (long_tests_enabled()) return true;
  std::cout << "SKIPPED: " << what
            << " is a long test (suite hard-long, ctest hard.long); set ARNOLDWEB_LONG_TESTS=1 to run it "
               "(bench/gpu/run.sh does)"
            << std::endl;
  if (long_suite_selected()) std::exit(77);
  return false;
}

}  // namespace awtest
