// arnoldweb tests: the CUDA kernels compile with NVRTC for every kind of
// configuration (no GPU needed: NVRTC only), compile errors come back as
// BuildError with the log and the options, and the kernel image cache works.
#ifdef ARNOLDWEB_HAVE_CUDA

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "arnoldweb/arnoldweb.hpp"
#include "aw_params.h"
#include "backends/cuda/kernel_cache.hpp"
#include "backends/cuda/nvrtc_compiler.hpp"
#include "physics/model_table.hpp"
#include "support.hpp"

namespace {

using arnoldweb::BuildError;
using arnoldweb::DeviceError;
using arnoldweb::KernelConfig;
using arnoldweb::MathMode;
using arnoldweb::Precision;
namespace detail = arnoldweb::detail;

const detail::CudaTarget kSm90{90, true};

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

bool is_elf(const std::string& image) { return image.size() > 4 && image.compare(0, 4, "\x7f" "ELF") == 0; }

KernelConfig config(std::uint32_t features, Precision precision, MathMode math, bool kick_first, int stages) {
  KernelConfig k;
  k.features = features;
  k.precision = precision;
  k.math = math;
  k.kick_first = kick_first;
  k.stages = stages;
  return k;
}

// Every precision, math mode, stepper kind and stage count (1, 7, 15) with the
// given features.
constexpr int kStepperConfigs = 2 * 2 * 2 * 3;
std::vector<KernelConfig> stepper_configs(std::uint32_t features) {
  std::vector<KernelConfig> all;
  for (Precision precision : {Precision::Double, Precision::Float})
    for (MathMode math : {MathMode::Portable, MathMode::Native})
      for (bool kick_first : {false, true})
        for (int stages : {1, 7, 15}) all.push_back(config(features, precision, math, kick_first, stages));
  return all;
}

// Compiles the ensemble kernel of k for sm_90 and checks the image: 1 when it
// compiled, 0 (and a failed check with NVRTC's log) when not.
int compiles(const KernelConfig& k) {
  const std::string defines = k.defines();
  CAPTURE(defines);
  detail::CudaImage img;
  try {
    img = detail::nvrtc_compile_ensemble(defines, kSm90, "nvrtc test");
  } catch (const BuildError& e) {
    FAIL_CHECK(e.what());
    return 0;
  }
  CHECK(img.target.cubin);
  CHECK(is_elf(img.data));
  CHECK(contains(img.data, "aw_ensemble"));
  CHECK(contains(img.data, "aw_fold"));
  CHECK(contains(img.options, defines));
  return 1;
}

// Sets an environment variable for the lifetime of the object.
struct ScopedEnv {
  std::string name, old;
  bool had = false;
  ScopedEnv(const std::string& n, const std::string& value) : name(n) {
    if (const char* v = std::getenv(n.c_str())) {
      had = true;
      old = v;
    }
    setenv(n.c_str(), value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (had)
      setenv(name.c_str(), old.c_str(), 1);
    else
      unsetenv(name.c_str());
  }
};

}  // namespace

TEST_SUITE("nvrtc") {
  TEST_CASE("NVRTC reports its version and knows sm_90") {
    const std::string v = detail::nvrtc_version();
    CHECK(v != "unknown");
    const auto archs = detail::nvrtc_supported_archs();
    REQUIRE_FALSE(archs.empty());
    CHECK(std::find(archs.begin(), archs.end(), 90) != archs.end());
  }

  TEST_CASE("targets: CUBIN for known chips, PTX for newer ones, an error for older ones") {
    const auto t90 = detail::nvrtc_target(90, "test");
    CHECK(t90.cubin);
    CHECK(t90.name() == "sm_90");
    const auto archs = detail::nvrtc_supported_archs();
    const auto future = detail::nvrtc_target(999, "test");
    CHECK_FALSE(future.cubin);
    CHECK(future.arch == archs.back());
    CHECK(future.name() == "compute_" + std::to_string(archs.back()));
    CHECK_THROWS_AS(detail::nvrtc_target(10, "test"), DeviceError);
  }

  TEST_CASE("the options keep FP contraction off and IEEE arithmetic, and carry the defines") {
    KernelConfig k;
    k.features = AW_F_VELOCITY_MAP | AW_F_ENERGY;
    k.stages = 7;
    k.precision = Precision::Float;
    const std::string line = detail::nvrtc_option_line(k.defines(), kSm90);
    CHECK(contains(line, "--gpu-architecture=sm_90"));
    CHECK(contains(line, "--fmad=false"));
    CHECK(contains(line, "--prec-div=true"));
    CHECK(contains(line, "--prec-sqrt=true"));
    CHECK(contains(line, "--ftz=false"));
    CHECK_FALSE(contains(line, "fast"));
    CHECK(contains(line, k.defines()));
    CHECK(contains(line, "-DAW_FLOAT"));
  }

  TEST_CASE("the ensemble kernel compiles for sm_90: every feature, precision, math, stepper kind and stage count") {
    // No feature bit and all of them in the whole cross product of the rest;
    // every single bit twice, with the other choice of each of the rest
    // (a covering set: every value of every axis meets every bit). The whole
    // cross product of every bit: ctest nvrtc.long (ARNOLDWEB_LONG_TESTS=1).
    int compiled = 0;
    for (std::uint32_t features : {0u, static_cast<std::uint32_t>(AW_F_ALL)})
      for (const KernelConfig& k : stepper_configs(features)) compiled += compiles(k);
    int bits = 0;
    for (std::uint32_t bit = 1; bit <= AW_F_ALL; bit <<= 1, ++bits) {
      compiled += compiles(config(bit, Precision::Double, MathMode::Portable, false, 7));
      compiled += compiles(config(bit, Precision::Float, MathMode::Native, true, 15));
    }
    CHECK(compiled == 2 * kStepperConfigs + 2 * bits);
  }

  TEST_CASE("the kernel levers compile for sm_90 (bench/gpu/sass_count.py, docs/performance.md round four)") {
    // Each NVRTC-option lever of the CUDA kernel, alone and together, in the
    // reference configuration (Figure 3 (a): Yoshida-6, double, map and
    // energy) and together with the other stepper kinds, float and every effect.
    // Unrolled stages and the 32-bit quadrant are the default; =0 keeps the old forms
    // (the last lever, both old forms, is the one compiled with the other configurations).
    const std::vector<std::string> levers = {"-DAW_CUDA_UNROLL_STAGES=0", "-DAW_CUDA_QUADRANT32=0",
                                             "-DAW_CUDA_UNROLL_STAGES=0 -DAW_CUDA_QUADRANT32=0"};
    KernelConfig fig3 = config(AW_F_VELOCITY_MAP | AW_F_ENERGY, Precision::Double, MathMode::Portable, true, 7);
    KernelConfig drift_first = config(AW_F_ALL, Precision::Double, MathMode::Portable, false, 15);
    KernelConfig in_float = config(AW_F_ALL, Precision::Float, MathMode::Portable, true, 7);
    KernelConfig gradient = config(AW_F_VELOCITY_MAP, Precision::Double, MathMode::Portable, true, 5);
    gradient.gradient = true;
    std::vector<std::pair<KernelConfig, std::string>> cases;
    for (const std::string& lever : levers) cases.emplace_back(fig3, lever);
    for (const KernelConfig& k : {drift_first, in_float, gradient}) cases.emplace_back(k, levers.back());
    for (const auto& [k, lever] : cases) {
      const std::string defines = k.defines() + " " + lever;
      CAPTURE(defines);
      try {
        const detail::CudaImage img = detail::nvrtc_compile_ensemble(defines, kSm90, "nvrtc test");
        CHECK(is_elf(img.data));
        CHECK(contains(img.options, lever));
      } catch (const BuildError& e) {
        FAIL_CHECK(e.what());
      }
    }
  }

  TEST_CASE("every model's kernel compiles for sm_90 (double and float, every effect, both stepper kinds)") {
    int models = 0;
    for (const detail::ModelDescriptor& m : detail::models()) {
      // the table's built-ins but the default, compiled in every configuration above (an
      // expression model's kernel: tests/backends/test_expression_nvrtc.cpp)
      if (!m.host || m.id == KernelConfig{}.model) continue;
      ++models;
      const int model = m.id;
      CAPTURE(m.name);
      for (Precision precision : {Precision::Double, Precision::Float})
        for (int kick_first : {0, 1}) {
          KernelConfig k;
          k.model = model;
          k.precision = precision;
          k.features = AW_F_ALL;
          k.kick_first = kick_first != 0;
          k.stages = 7;
          CAPTURE(k.defines());
          CHECK(contains(k.defines(), "-DAW_MODEL=" + std::to_string(model)));
          try {
            const detail::CudaImage img = detail::nvrtc_compile_ensemble(k.defines(), kSm90, "nvrtc test");
            CHECK(is_elf(img.data));
          } catch (const BuildError& e) {
            FAIL_CHECK(e.what());
          }
        }
    }
    CHECK(models > 0);
  }

  TEST_CASE("PTX for a chip newer than NVRTC knows") {
    KernelConfig k;
    k.features = AW_F_VELOCITY_MAP;
    k.stages = 7;
    const auto img = detail::nvrtc_compile_ensemble(k.defines(), detail::nvrtc_target(999, "test"), "test");
    CHECK_FALSE(img.target.cubin);
    CHECK(contains(img.data, ".entry aw_ensemble"));
    CHECK(img.data.back() == '\0');  // the loader wants NUL-terminated PTX
  }

  TEST_CASE("a broken define is a BuildError with NVRTC's log and the options") {
    KernelConfig k;
    k.features = AW_F_VELOCITY_MAP;
    k.stages = 7;
    const std::string defines = k.defines() + " -DAW_STAGES=seven_and_a_half";
    try {
      detail::nvrtc_compile_ensemble(defines, kSm90, "nvrtc test");
      FAIL("a broken define compiled");
    } catch (const BuildError& e) {
      CAPTURE(e.log());
      CHECK(contains(e.log(), "seven_and_a_half"));
      CHECK(contains(e.log(), "error"));
      CHECK(contains(e.options(), "-DAW_FEATURES=1u"));
      CHECK(contains(e.options(), "-DAW_STAGES=seven_and_a_half"));
      CHECK(contains(e.options(), "--fmad=false"));
      CHECK(contains(e.what(), "nvrtc test"));
    }
  }

  TEST_CASE("kernel images are cached in memory and on disk") {
    const std::string dir = awtest::temp_dir("cuda-cache");
    ScopedEnv env("ARNOLDWEB_CACHE_DIR", dir);
    REQUIRE(detail::cuda_cache_dir() == (std::filesystem::path(dir) / "cuda").string());
    KernelConfig k;
    k.features = AW_F_VELOCITY_MAP | AW_F_ENERGY;
    k.stages = 15;
    k.kick_first = false;
    detail::cuda_forget_image(k.defines(), kSm90);

    const auto first = detail::cuda_ensemble_image(k.defines(), kSm90, "test");
    CHECK(first.origin == "compiled");
    const auto again = detail::cuda_ensemble_image(k.defines(), kSm90, "test");
    CHECK(again.origin == "memory");
    CHECK(again.image == first.image);

    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(detail::cuda_cache_dir())) files.push_back(e.path());
    REQUIRE(files.size() == 1);
    CHECK(files[0].extension() == ".cubin");

    detail::cuda_clear_memory_cache();
    const auto disk = detail::cuda_ensemble_image(k.defines(), kSm90, "test");
    CHECK(disk.origin == "disk");
    CHECK(disk.image->data == first.image->data);
    CHECK(disk.image->options == first.image->options);

    // A damaged file is ignored (and replaced).
    {
      std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(100);
      f.put('\x55');
      f.put('\xaa');
    }
    detail::cuda_clear_memory_cache();
    CHECK(detail::cuda_ensemble_image(k.defines(), kSm90, "test").origin == "compiled");
    detail::cuda_clear_memory_cache();
    CHECK(detail::cuda_ensemble_image(k.defines(), kSm90, "test").origin == "disk");

    detail::cuda_forget_image(k.defines(), kSm90);
    CHECK_FALSE(std::filesystem::exists(files[0]));
  }

  TEST_CASE("the disk cache can be switched off") {
    ScopedEnv env("ARNOLDWEB_CACHE_DIR", "off");
    CHECK(detail::cuda_cache_dir().empty());
  }
}

// The whole cross product of every feature bit (480 compiles, about 4 CPU
// minutes): ctest nvrtc.long, with ARNOLDWEB_LONG_TESTS=1 (bench/gpu/run.sh).
TEST_SUITE("nvrtc-long") {
  TEST_CASE("the ensemble kernel compiles for sm_90 in every configuration of every feature bit") {
    if (!awtest::require_long_tests("nvrtc-long")) return;
    std::vector<std::uint32_t> masks = {0u, AW_F_ALL};
    for (std::uint32_t bit = 1; bit <= AW_F_ALL; bit <<= 1) masks.push_back(bit);
    int compiled = 0;
    for (std::uint32_t features : masks)
      for (const KernelConfig& k : stepper_configs(features)) compiled += compiles(k);
    CHECK(compiled == static_cast<int>(masks.size()) * kStepperConfigs);
  }
}

// A suite of its own (ctest nvrtc.no-cuda): skipped, with the reason, where a
// CUDA device is present.
TEST_SUITE("nvrtc-no-cuda") {
  TEST_CASE("without a usable CUDA device the registry says why, and cuda:0 is a DeviceError") {
    bool have_cuda = false;
    for (const auto& d : arnoldweb::list_devices()) have_cuda |= d.backend == "cuda";
    if (!awtest::require(!have_cuda, "nvrtc-no-cuda",
                         "this machine has a usable CUDA device (cuda:0), so the registry's account of a missing "
                         "one cannot be tested here"))
      return;
    bool explained = false;
    for (const auto& p : arnoldweb::backend_problems()) explained |= p.rfind("cuda: ", 0) == 0;
    CHECK(explained);
    try {
      arnoldweb::open_backend("cuda:0");
      FAIL("cuda:0 opened without a CUDA device");
    } catch (const DeviceError& e) {
      CHECK(contains(e.what(), "cuda:0"));
      CHECK(contains(e.what(), "cpu"));
      CHECK(e.exit_code() == 4);
    }
  }
}

#endif  // ARNOLDWEB_HAVE_CUDA
