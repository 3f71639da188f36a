// arnoldweb tests: shared helpers. The test binary takes --backend=cpu|opencl|cuda
// to restrict the device-bound suites to one backend; with none present it
// exits 77 (CTest: skipped) and says why.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <string>
#include <type_traits>
#include <vector>

#include "arnoldweb/arnoldweb.hpp"

namespace awtest {

// Whether this build runs under AddressSanitizer (scripts/build-asan.sh): a child process that
// crashes on purpose (a damaged HDF5 file read in a child, lib/src/os/isolated.hpp) is then a
// sanitizer's report, which check-sanitizers.sh counts as a failure; such cases run in the plain
// build's suites only.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

// Devices the device-bound tests run on (all present, or those of --backend).
const std::vector<arnoldweb::DeviceInfo>& devices_under_test();

// A scene from TOML text, with overrides (--set style "key=value"), read and
// checked by the library's own reader; `file` is the name used in messages.
arnoldweb::Scene scene_from(const std::string& toml, const std::vector<std::string>& sets = {},
                            const std::string& file = "<test>");

// The shortest text that reads back as exactly `x` (std::to_chars), for
// numbers held in variables that go into a scene: 15 -> "15", 0.1 -> "0.1",
// sqrt(15) -> "3.872983346207417", 1e-300 -> "1e-300".
std::string num(double x);
// A string as a TOML basic string, quoted and escaped.
std::string quoted(const std::string& s);

// An override "key=value" for scene_from, the value written in TOML so that it
// reads back exactly: numbers (num), integers, booleans, strings (quoted), and
// arrays of numbers (std::array, std::vector). E.g. set("integrator.step", h),
// set("ensemble.gaussian.mean", std::array<double, 2>{m, m}).
template <class T>
std::string set(const std::string& key, const T& value) {
  using V = std::decay_t<T>;
  if constexpr (std::is_same_v<V, bool>) {
    return key + "=" + (value ? "true" : "false");
  } else if constexpr (std::is_integral_v<V>) {
    return key + "=" + std::to_string(value);
  } else if constexpr (std::is_floating_point_v<V>) {
    return key + "=" + num(static_cast<double>(value));
  } else if constexpr (std::is_convertible_v<const T&, std::string>) {
    return key + "=" + quoted(value);
  } else {  // a sequence of numbers
    std::string text = key + "=[";
    bool first = true;
    for (const auto& x : value) {
      text += (first ? "" : ", ") + num(static_cast<double>(x));
      first = false;
    }
    return text + "]";
  }
}

// Plan and run a scene on a device, quietly.
arnoldweb::Result run_on(const std::string& device, const arnoldweb::Plan& plan);

// Index of the first element whose bits differ, -1 if none (0 if the sizes differ).
template <class T>
long first_difference(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::memcmp(&a[i], &b[i], sizeof(T)) != 0) return static_cast<long>(i);
  return -1;
}

// A fresh empty temporary directory (removed at exit).
std::string temp_dir(const std::string& tag);

// How to start the arnoldweb CLI in a test (no shell is involved: the
// arguments reach the program exactly as given).
struct CliOptions {
  std::vector<std::string> env;  // extra NAME=value entries
  std::string cwd;               // working directory ("" = this one)
  long long file_size_limit = 0; // RLIMIT_FSIZE in bytes (writes beyond fail like a full disk), 0 = none
  // A launcher (absolute path) and its arguments put before the CLI, e.g. mpirun -n 2
  std::vector<std::string> launcher;
};

// Run the arnoldweb CLI with arguments; returns the exit code (-1 if it did
// not exit normally), stdout and stderr together in *out.
int run_cli(const std::vector<std::string>& args, std::string* out = nullptr, const CliOptions& options = {});
inline int run_cli(std::initializer_list<std::string> args, std::string* out = nullptr,
                   const CliOptions& options = {}) {
  return run_cli(std::vector<std::string>(args), out, options);
}
// The same with the arguments split at spaces (for arguments without spaces).
int run_cli(const std::string& args, std::string* out = nullptr);

// A CLI started in the background (for signals): its pid and its output.
struct StartedCli {
  int pid = -1;
  int fd = -1;         // read end of its stdout+stderr
  std::string output;  // what has been read so far
  // Reads until `text` appears in the output or `seconds` pass; true if it appeared.
  bool wait_for(const std::string& text, double seconds);
  // Waits for the exit; returns the exit code, or 128 + signal if killed.
  int finish();
  // The same, but waits at most `seconds`: -2 (after killing it) if it had
  // not ended by then, so that a hang fails the test instead of stopping it.
  int finish_within(double seconds);
};
StartedCli start_cli(const std::vector<std::string>& args, const CliOptions& options = {});

// Long tests (doctest suite "hard-long", ctest hard.long) run only where the
// environment variable ARNOLDWEB_LONG_TESTS=1 is set (bench/gpu/run.sh sets
// it). Call require_long_tests() first in every such test case. Without the
// variable it says why and ends the process with exit code 77, which CTest
// reports as skipped, never as passed. The process ends only when the command
// line selects the suite by name (-ts=hard-long, as ctest does); in a run of
// the whole binary without filters the test case is passed over with a
// message instead, so that the other suites still run.
bool long_tests_enabled();

// For a test case that needs something this machine may lack (a tool, a
// device, root): returns true if `available`; otherwise prints "SKIPPED:"
// with the reason and, when the process was started for `suite` alone (as
// ctest starts it), exits with 77 so that CTest reports the test as skipped.
// Put such cases in a suite of their own, so nothing else is skipped with them.
bool require(bool available, const std::string& suite, const std::string& why_not);
bool require_long_tests(const std::string& what);

}  // namespace awtest
