// arnoldweb: an expression model's cpu kernel, compiled at run time
// (cpu_runtime_kernel.hpp).
#include "backends/cpu/cpu_runtime_kernel.hpp"

#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "arnoldweb/errors.hpp"
#include "backends/kernel_disk_cache.hpp"
#include "backends/kernel_sources.hpp"
#include "backends/cpu/cpu_isa.hpp"
#include "cpu_runtime_config.hpp"  // generated: the options of the variants compiled ahead of time
#include "os/process.hpp"
#include "os/shared_object.hpp"

namespace fs = std::filesystem;

namespace arnoldweb::detail {
namespace {

constexpr char kMagic[8] = {'A', 'W', 'C', 'P', 'U', 'S', 'O', '1'};
constexpr const char* kEntry = "arnoldweb_cpu_kernel";
constexpr const char* kDevice = "cpu";

std::mutex cache_mutex;
std::map<std::string, CpuKernel>& memory_cache() {
  static std::map<std::string, CpuKernel> m;
  return m;
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

std::string variant_name(bool single_precision, bool native_math) {
  return std::string("expression_") + (single_precision ? "float" : "double") + "_" +
         (native_math ? "native" : "portable");
}

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const auto& w : words) s += (s.empty() ? "" : " ") + w;
  return s;
}

[[noreturn]] void no_compiler(const std::string& why) {
  throw DeviceError(kDevice, "", 0,
                    "model.kind = \"expression\" on the cpu backend compiles its kernel at run time with a C++ "
                    "compiler, and " + why +
                        ": install one (Debian: apt-get install g++) or set ARNOLDWEB_CXX to a C++17 compiler "
                        "with OpenMP, or run the model on an OpenCL device such as PoCL (--device opencl:0; "
                        "`arnoldweb devices` lists them)");
}

// The compiler's own description of itself (part of the disk cache's key).
std::string compiler_version(const std::string& cxx) {
  const ProgramRun r = run_program({cxx, "--version"});
  if (r.exit_code != 0)
    no_compiler(cxx + " does not work as one (`" + cxx + " --version` " +
                (r.signal ? "was killed by signal " + std::to_string(r.signal)
                          : "exited with " + std::to_string(r.exit_code)) +
                ")");
  return r.output;
}

// A private folder for the compiler's input and output; removes what it made.
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (fs::temp_directory_path() / "arnoldweb-cxx-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
      throw DeviceError(kDevice, "mkdtemp", errno, "no temporary folder for the kernel's compiler under " +
                                                      fs::temp_directory_path().string());
    dir_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ec;
    for (const char* f : {"kernel.cpp", "kernel.so"}) fs::remove(fs::path(dir_) / f, ec);
    fs::remove(dir_, ec);  // only if empty: nothing but what this object made is ever removed
  }
  std::string file(const char* name) const { return (fs::path(dir_) / name).string(); }

 private:
  std::string dir_;
};

std::string compile_shared_object(const std::string& cxx, const std::string& source) {
  ScratchDir scratch;
  const std::string input = scratch.file("kernel.cpp"), output = scratch.file("kernel.so");
  {
    std::ofstream out(input, std::ios::binary);
    out << source;
    if (!out) throw DeviceError(kDevice, "", 0, "could not write the kernel's source to " + input);
  }
  std::vector<std::string> argv = {cxx};
  for (const auto& o : cpu_runtime_options()) argv.push_back(o);
  argv.insert(argv.end(), {"-o", output, input});
  const ProgramRun r = run_program(argv);
  std::string image;
  if (r.exit_code == 0) {
    std::ifstream in(output, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    image = bytes.str();
  }
  if (r.exit_code != 0 || image.empty()) {
    const std::string what = r.signal           ? " was killed by signal " + std::to_string(r.signal)
                             : r.exit_code != 0 ? " exited with " + std::to_string(r.exit_code)
                                                : " made no shared object";
    throw BuildError(kDevice, joined(argv),
                     (r.output.empty() ? std::string("(no output)") : r.output) + "\n" + cxx + what +
                         " compiling the cpu kernel of model.kind = \"expression\"; set ARNOLDWEB_CXX to a working "
                         "C++17 compiler with OpenMP, or run the model on an OpenCL device such as PoCL "
                         "(--device opencl:0)");
  }
  return image;
}

CpuKernel load(const std::string& image) {
  using Entry = CpuKernel (*)();
  return reinterpret_cast<Entry>(load_shared_object_symbol(image, kEntry))();
}

}  // namespace

std::string runtime_cxx() {
  if (const char* env = std::getenv("ARNOLDWEB_CXX"); env && *env) return find_program(env);
  if (const std::string built = find_program(ARNOLDWEB_CPU_RUNTIME_CXX); !built.empty()) return built;
  for (const char* name : {"c++", "g++", "clang++"})
    if (std::string p = find_program(name); !p.empty()) return p;
  return "";
}

std::vector<std::string> cpu_runtime_options() {
  std::vector<std::string> options = {ARNOLDWEB_CPU_RUNTIME_OPTIONS};
  const std::string isa = cpu_isa_selected().name;  // the set the ahead-of-time variants run in
  if (!isa.empty() && isa != "default") options.push_back("-march=" + isa);
  return options;
}

std::string cpu_expression_source(const std::string& model_source, bool single_precision, bool native_math) {
  const std::string variant = variant_name(single_precision, native_math);
  std::string text(embedded_file("backends/cpu/cpu_kernel_variant.cpp.in"));
  replace_all(text, "@VARIANT@", variant);
  replace_all(text, "@MODEL_ID@", "1000");  // aw_models.h: an expression model
  replace_all(text, "@MODEL_HEADER_DEFINE@", "");  // the sources are flattened: the dispatch includes its header
  replace_all(text, "@PRECISION_DEFINE@", single_precision ? "#define AW_FLOAT 1" : "");
  replace_all(text, "@MATH_DEFINE@", native_math ? "#define AW_NATIVE_MATH 1" : "");
  const CpuIsa& isa = cpu_isa_selected();
  replace_all(text, "@LANES@", std::to_string(single_precision ? isa.lanes_float : isa.lanes_double));
  std::smatch left;
  if (std::regex_search(text, left, std::regex("@[A-Z_]+@")))
    throw std::logic_error("cpu_kernel_variant.cpp.in has a placeholder the run-time compile does not fill: " +
                           left.str());
  text += "\nextern \"C\" __attribute__((visibility(\"default\"))) arnoldweb::detail::CpuKernel " +
          std::string(kEntry) + "() {\n  return &arnoldweb::detail::cpu_chunk_" + variant + ";\n}\n";
  const std::string name = "cpu_kernel_" + variant + ".cpp";
  return flatten_source(name, {{name, text}, {expression_model_header(), model_source}});
}

CpuRuntimeKernel cpu_expression_kernel(const std::string& model_source, bool single_precision, bool native_math) {
  CpuRuntimeKernel k;
  k.variant = "cpu_" + variant_name(single_precision, native_math);
  k.compiler = runtime_cxx();
  if (k.compiler.empty()) {
    const char* env = std::getenv("ARNOLDWEB_CXX");
    no_compiler(env && *env ? std::string("ARNOLDWEB_CXX=") + env + " is not an executable program"
                            : "none was found (ARNOLDWEB_CXX is not set; " ARNOLDWEB_CPU_RUNTIME_CXX
                              ", c++, g++ and clang++ are not there or not on PATH)");
  }
  const std::string source = cpu_expression_source(model_source, single_precision, native_math);
  const std::string options = joined(cpu_runtime_options());
  std::lock_guard<std::mutex> lock(cache_mutex);
  const std::string key = k.compiler + "\n" + options + "\n" + source;
  if (auto it = memory_cache().find(key); it != memory_cache().end()) {
    k.kernel = it->second;
    k.origin = "memory";
    return k;
  }
  const std::string fingerprint =
      "arnoldweb cpu kernel v1\n" + compiler_version(k.compiler) + "\n" + options + "\n" + source;
  const std::string dir = kernel_cache_dir("cpu");
  const std::string file = dir.empty() ? "" : (fs::path(dir) / kernel_cache_file_name(fingerprint, ".so")).string();
  std::string image;
  if (!file.empty() && read_cache_file(file, kMagic, image)) {
    try {
      k.kernel = load(image);
      k.origin = "disk";
    } catch (const std::runtime_error&) {
      k.kernel = nullptr;  // a cached object that does not load: compiled afresh below
    }
  }
  if (!k.kernel) {
    image = compile_shared_object(k.compiler, source);
    try {
      k.kernel = load(image);
    } catch (const std::runtime_error& e) {
      throw DeviceError(kDevice, "", 0,
                        "the cpu kernel of model.kind = \"expression\" compiled by " + k.compiler +
                            " cannot be loaded: " + e.what());
    }
    k.origin = "compiled";
    if (!file.empty()) write_cache_file(file, kMagic, image);
  }
  memory_cache()[key] = k.kernel;
  return k;
}

void cpu_runtime_clear_memory_cache() {
  std::lock_guard<std::mutex> lock(cache_mutex);
  memory_cache().clear();
}

}  // namespace arnoldweb::detail
