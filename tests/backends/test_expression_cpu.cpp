// Expression models on the cpu backend (issue 25, item 5): the kernel is
// compiled at run time by the host C++ compiler from the embedded variant
// template, struct and body, and gives PoCL's bits (initial and final states,
// map, energy statistics) in double and float; the shared object is cached in
// memory and on disk and used again; a missing or broken compiler is a clear
// error (exit 4) naming what to install or the OpenCL device to use instead,
// and nothing is written. Suite "expression-cpu" needs a C++ compiler and
// PoCL; the error cases (suite "expression") need neither.
#include <doctest/doctest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <nlohmann/json.hpp>

#include "arnoldweb/arnoldweb.hpp"
#include "../physics/expression_cases.hpp"
#include "backends/cpu/cpu_runtime_kernel.hpp"
#include "backends/kernel_sources.hpp"
#include "run_outputs.hpp"
#include "support.hpp"

using namespace arnoldweb;
namespace fs = std::filesystem;

namespace {

const std::string kScene = R"(
[model]
kind = "expression"
energy = 15
[ensemble]
trajectories = 3000
seed = 7
[integrator]
step = 0.01
[run]
average = 2
duration = 2
[observe]
velocity_map = { nside = 8 }
energy_error = { every = 1 }
initial_states = true
final_states = true
[output]
images = false
)";

Scene expression_scene(const std::string& potential, const std::vector<std::string>& sets = {}) {
  std::vector<std::string> all = {awtest::set("model.potential", potential)};
  all.insert(all.end(), sets.begin(), sets.end());
  return awtest::scene_from(kScene, all, "<expression-cpu>");
}

// ARNOLDWEB_CACHE_DIR set for the life of the object (a test's own cache), then restored.
class CacheDir {
 public:
  explicit CacheDir(const std::string& dir) {
    if (const char* old = std::getenv("ARNOLDWEB_CACHE_DIR")) old_ = old, had_ = true;
    ::setenv("ARNOLDWEB_CACHE_DIR", dir.c_str(), 1);
    detail::cpu_runtime_clear_memory_cache();
  }
  ~CacheDir() {
    if (had_) ::setenv("ARNOLDWEB_CACHE_DIR", old_.c_str(), 1);
    else ::unsetenv("ARNOLDWEB_CACHE_DIR");
    detail::cpu_runtime_clear_memory_cache();
  }

 private:
  std::string old_;
  bool had_ = false;
};

void check_same_bits(const Result& a, const Result& b) {
  REQUIRE(a.completed == b.completed);
  CHECK(awtest::first_difference(a.reals("initial_states"), b.reals("initial_states")) == -1);
  CHECK(awtest::first_difference(a.reals("final_states"), b.reals("final_states")) == -1);
  CHECK(awtest::first_difference(a.ints("final_states"), b.ints("final_states")) == -1);
  CHECK(digest_records(a, "initial_states") == digest_records(b, "initial_states"));
  CHECK(digest_records(a, "final_states") == digest_records(b, "final_states"));
  CHECK(digest_map(a) == digest_map(b));
  CHECK(a.binned == b.binned);
  CHECK(a.energy.max == b.energy.max);
  CHECK(a.energy.mean == b.energy.mean);
}

bool ready() {
  return awtest::require(!detail::runtime_cxx().empty(), "expression-cpu", "no C++ compiler on PATH") &&
         awtest::require(!awtest::first_opencl().empty(), "expression-cpu", "no OpenCL device here (install pocl-opencl-icd)");
}

}  // namespace

TEST_SUITE("expression-cpu") {
  TEST_CASE("an expression model on the cpu backend gives PoCL's bits: the paper's potential and every construct") {
    if (!ready()) return;
    CacheDir cache(awtest::temp_dir("expr-cpu-cache"));
    const std::string mixed = "exp(cos(x - y))*sqrt(2 + sin(z)) + sin(x)^3*cos(2*y + z)^2/(3 + cos(z))";
    // no structured binding: clang 14 (build-asan) cannot capture one in CAPTURE's lambda
    for (const auto& c :
         std::vector<std::pair<std::string, std::vector<std::string>>>{
             {awtest::paper_potential(), {}},
             {mixed, {"model.energy=6", "integrator.precision=\"float\""}}}) {  // a compile each (~40 s on 2 cores)
      const std::string& potential = c.first;
      const std::vector<std::string>& sets = c.second;
      CAPTURE(potential);
      CAPTURE(sets.size());
      const Plan plan = make_plan(expression_scene(potential, sets));
      const Result cpu = awtest::run_on("cpu", plan);
      const Result pocl = awtest::run_on(awtest::first_opencl(), plan);
      CHECK(cpu.kernel.find("compiled at run time") != std::string::npos);
      CHECK(cpu.flagged_nonfinite == 0);
      CHECK(cpu.energy.max > 0);
      check_same_bits(cpu, pocl);
    }
  }

  TEST_CASE("the compiled kernel is cached: in memory, then on disk for the next process; the cache can be off") {
    if (!ready()) return;
    const std::string dir = awtest::temp_dir("expr-cpu-reuse");
    const std::string header = make_plan(expression_scene(awtest::paper_potential())).kernel.model_source;
    REQUIRE_FALSE(header.empty());
    {
      CacheDir cache(dir);
      const auto first = detail::cpu_expression_kernel(header, false, false);
      CHECK(first.origin == "compiled");
      const auto again = detail::cpu_expression_kernel(header, false, false);
      CHECK(again.origin == "memory");
      CHECK((again.kernel == first.kernel));
      std::size_t files = 0;
      for (const auto& e : fs::directory_iterator(dir + "/cpu")) {
        CHECK(e.path().extension() == ".so");
        std::ifstream in(e.path(), std::ios::binary);
        char magic[8] = {};
        in.read(magic, 8);
        CHECK(std::string(magic, 8) == "AWCPUSO1");
        ++files;
      }
      CHECK(files == 1);
      detail::cpu_runtime_clear_memory_cache();  // as a new process finds it
      CHECK(detail::cpu_expression_kernel(header, false, false).origin == "disk");
    }
    // through the CLI: a second process reuses the object (the summary says so), same digests
    const std::string root = awtest::temp_dir("expr-cpu-cli");
    const std::string scene = root + "/scene.toml";
    std::ofstream(scene) << kScene << "";
    awtest::CliOptions o;
    o.env = {"ARNOLDWEB_CACHE_DIR=" + root + "/cache"};
    const std::vector<std::string> pot = {"--set", awtest::set("model.potential", awtest::paper_potential())};
    auto run = [&](const std::string& out) {
      std::vector<std::string> a = {"run", scene, "--quiet", "--device", "cpu", "--out", root + "/" + out};
      a.insert(a.end(), pot.begin(), pot.end());
      return awtest::run_cli(a, nullptr, o);
    };
    REQUIRE(run("one") == 0);
    REQUIRE(run("two") == 0);
    auto summary = [&](const std::string& out) {
      std::ifstream in(root + "/" + out + "/summary.json");
      return nlohmann::json::parse(in);
    };
    CHECK(summary("one")["kernel"].get<std::string>().find("; compiled)") != std::string::npos);
    CHECK(summary("two")["kernel"].get<std::string>().find("; disk)") != std::string::npos);
    CHECK(summary("one")["digests"] == summary("two")["digests"]);
    // with the disk cache off, it compiles each time and still runs
    o.env = {"ARNOLDWEB_CACHE_DIR=off"};
    REQUIRE(run("three") == 0);
    CHECK(summary("three")["kernel"].get<std::string>().find("; compiled)") != std::string::npos);
    CHECK(summary("one")["digests"] == summary("three")["digests"]);
  }
}

TEST_SUITE("expression") {
  TEST_CASE("the run-time source is the embedded variant template, struct and body, with the model's header") {
    const std::string header = make_plan(expression_scene(awtest::paper_potential())).kernel.model_source;
    const std::string source = detail::cpu_expression_source(header, false, false);
    CHECK(source.find("struct CpuChunk {") != std::string::npos);
    CHECK(source.find("void run_chunk(const CpuChunk& c) {") != std::string::npos);
    CHECK(source.find("#define AW_MODEL 1000") != std::string::npos);
    CHECK(source.find("AW_EXPRESSION_MODEL_H") != std::string::npos);
    CHECK(source.find("cpu_chunk_expression_double_portable") != std::string::npos);
    CHECK(source.find("arnoldweb_cpu_kernel()") != std::string::npos);
    CHECK_FALSE(std::regex_search(source, std::regex("@[A-Z_]+@")));  // every placeholder filled
    const std::string single = detail::cpu_expression_source(header, true, false);
    CHECK(single.find("#define AW_FLOAT 1") != std::string::npos);
  }

  TEST_CASE("a missing or broken C++ compiler: exit 4, what to install or which device to use, nothing written") {
    const std::string root = awtest::temp_dir("expr-no-cxx");
    const std::string scene = root + "/scene.toml";
    std::ofstream(scene) << kScene;
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"/nonexistent/c++", "ARNOLDWEB_CXX=/nonexistent/c++ is not an executable program"},
        {"/bin/false", "/bin/false does not work as one"},
        {"/bin/true", "/bin/true made no shared object"}};
    for (std::size_t k = 0; k < cases.size(); ++k) {
      CAPTURE(cases[k].first);
      awtest::CliOptions o;
      o.env = {"ARNOLDWEB_CXX=" + cases[k].first, "ARNOLDWEB_CACHE_DIR=off"};
      std::string text;
      const std::string out = root + "/out" + std::to_string(k);
      CHECK(awtest::run_cli({"run", scene, "--quiet", "--device", "cpu", "--out", out, "--set",
                             awtest::set("model.potential", awtest::paper_potential())},
                            &text, o) == 4);
      CAPTURE(text);
      CHECK(text.find(cases[k].second) != std::string::npos);
      CHECK(text.find("--device opencl:0") != std::string::npos);
      if (k < 2) CHECK(text.find("apt-get install g++") != std::string::npos);
      CHECK_FALSE(fs::exists(out));
    }
  }
}
