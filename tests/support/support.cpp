#include "support.hpp"

#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <csignal>
#include <sstream>
#include <thread>

#include <array>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

extern char** environ;

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

arnoldweb::Scene scene_from(const std::string& toml, const std::vector<std::string>& sets,
                            const std::string& file) {
  return arnoldweb::parse_scene(toml, file, sets);
}

std::string num(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);  // shortest form that reads back exactly
  if (r.ec != std::errc()) std::abort();
  return std::string(buf, r.ptr);
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
          char u[8];
          std::snprintf(u, sizeof u, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += u;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

arnoldweb::Result run_on(const std::string& device, const arnoldweb::Plan& plan) {
  auto backend = arnoldweb::open_backend(device);
  return arnoldweb::run(plan, *backend);
}

std::string temp_dir(const std::string& tag) {
  namespace fs = std::filesystem;
  // never destroyed: the atexit handler below, registered while root is initialised, runs after
  // root's destructor would (valgrind: it read the freed path)
  static const fs::path& root = *[] {
    std::string templ = (fs::temp_directory_path() / "arnoldweb-test-XXXXXX").string();
    if (!mkdtemp(templ.data())) std::abort();
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(root, ec);
    });
    return new fs::path(templ);
  }();
  static int counter = 0;
  fs::path p = root / (tag + "-" + std::to_string(counter++));
  fs::create_directories(p);
  return p.string();
}

StartedCli start_cli(const std::vector<std::string>& args, const CliOptions& o) {
  StartedCli c;
  int fds[2];
  if (pipe(fds) != 0) return c;
  // ARNOLDWEB_TEST_CLI runs the CLI tests against another build (e.g. an older
  // one, to see a regression test fail there)
  const char* other = std::getenv("ARNOLDWEB_TEST_CLI");
  std::vector<std::string> argv_s = o.launcher;
  argv_s.push_back(other && *other ? other : ARNOLDWEB_CLI);
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_s;  // ours, then the options' (which replace ours of the same name)
  auto name_of = [](const std::string& e) { return e.substr(0, e.find('=')); };
  for (char** e = environ; *e; ++e) {
    bool replaced = false;
    for (const auto& x : o.env) replaced |= name_of(x) == name_of(*e);
    if (!replaced) env_s.emplace_back(*e);
  }
  env_s.insert(env_s.end(), o.env.begin(), o.env.end());
  std::vector<char*> envp;
  for (auto& e : env_s) envp.push_back(e.data());
  envp.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(fds[1], 1);
    dup2(fds[1], 2);
    close(fds[0]);
    close(fds[1]);
    if (!o.cwd.empty() && chdir(o.cwd.c_str()) != 0) _exit(126);
    std::signal(SIGQUIT, SIG_DFL);  // as at a terminal (a background job of a shell starts with it ignored)
    if (o.file_size_limit > 0) {
      std::signal(SIGXFSZ, SIG_IGN);
      rlimit lim{static_cast<rlim_t>(o.file_size_limit), static_cast<rlim_t>(o.file_size_limit)};
      setrlimit(RLIMIT_FSIZE, &lim);
    }
    execve(argv[0], argv.data(), envp.data());
    _exit(127);
  }
  close(fds[1]);
  c.pid = pid;
  c.fd = fds[0];
  return c;
}

bool StartedCli::wait_for(const std::string& text, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (output.find(text) == std::string::npos) {
    const double left = std::chrono::duration<double>(end - std::chrono::steady_clock::now()).count();
    if (left <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(left * 1000) + 1) <= 0) continue;
    char buf[4096];
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n <= 0) return output.find(text) != std::string::npos;
    output.append(buf, static_cast<std::size_t>(n));
  }
  return true;
}

int StartedCli::finish() {
  char buf[4096];
  ssize_t n;
  while ((n = read(fd, buf, sizeof buf)) > 0) output.append(buf, static_cast<std::size_t>(n));
  close(fd);
  fd = -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

int StartedCli::finish_within(double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > end) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      close(fd);
      fd = -1;
      output += "\n(killed: still running after " + std::to_string(seconds) + " s)";
      return -2;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  char buf[4096];
  ssize_t n;
  while ((n = read(fd, buf, sizeof buf)) > 0) output.append(buf, static_cast<std::size_t>(n));
  close(fd);
  fd = -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int run_cli(const std::vector<std::string>& args, std::string* out, const CliOptions& options) {
  StartedCli c = start_cli(args, options);
  if (c.pid < 0) return -1;
  const int rc = c.finish();
  if (out) *out = c.output;
  return rc >= 128 ? -1 : rc;
}

int run_cli(const std::string& args, std::string* out) {
  std::vector<std::string> v;
  std::istringstream in(args);
  for (std::string a; in >> a;) v.push_back(a);
  return run_cli(v, out);
}

bool long_tests_enabled() {
  const char* v = std::getenv("ARNOLDWEB_LONG_TESTS");
  return v != nullptr && std::string(v) == "1";
}

namespace {

// Whether this process was started for `suite` by name (the command line,
// from /proc: the doctest context keeps its filters to itself).
bool suite_selected(const std::string& suite) {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string cmdline((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t start = 0;
  while (start < cmdline.size()) {
    std::size_t end = cmdline.find('\0', start);
    if (end == std::string::npos) end = cmdline.size();
    const std::string arg = cmdline.substr(start, end - start);
    for (const char* opt : {"-ts=", "--test-suite=", "-test-suite="})
      if (arg.rfind(opt, 0) == 0 && arg.substr(std::strlen(opt)) == suite) return true;
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
  if (suite_selected("hard-long")) std::exit(77);
  return false;
}

bool require(bool available, const std::string& suite, const std::string& why_not) {
  if (available) return true;
  std::cout << "SKIPPED: " << why_not << std::endl;
  if (suite_selected(suite)) std::exit(77);
  return false;
}

}  // namespace awtest
