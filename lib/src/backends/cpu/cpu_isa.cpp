// arnoldweb: the run-time choice of the cpu kernels' instruction set (cpu_isa.hpp).
#include "backends/cpu/cpu_isa.hpp"

#include <cstdlib>
#include <cstring>

#include "arnoldweb/errors.hpp"

namespace arnoldweb::detail {
namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "none" : s;
}

}  // namespace

std::vector<std::string> cpu_isas_supported() {
  std::vector<std::string> names;
  for (const CpuIsa& isa : cpu_isa_table())
    if (isa.supported()) names.emplace_back(isa.name);
  return names;
}

std::vector<std::string> cpu_isas_built() {
  std::vector<std::string> names;
  for (const CpuIsa& isa : cpu_isa_table()) names.emplace_back(isa.name);
  return names;
}

const CpuIsa& cpu_isa_selected() {
  const char* forced = std::getenv("ARNOLDWEB_CPU_ISA");
  for (const CpuIsa& isa : cpu_isa_table()) {
    if (forced && *forced) {
      if (std::strcmp(forced, isa.name) != 0) continue;
      if (!isa.supported())
        throw DeviceError("cpu", "", 0,
                          std::string("ARNOLDWEB_CPU_ISA=") + forced + ": this CPU does not support it (it supports " +
                              joined(cpu_isas_supported()) + ")");
      return isa;
    }
    if (isa.supported()) return isa;
  }
  if (forced && *forced)
    throw DeviceError("cpu", "", 0,
                      std::string("ARNOLDWEB_CPU_ISA=") + forced + ": this build's cpu kernels are compiled for " +
                          joined(cpu_isas_built()));
  throw DeviceError("cpu", "", 0,
                    "this CPU supports none of the instruction sets the cpu kernels were compiled for (" +
                        joined(cpu_isas_built()) + ")");
}

CpuKernel cpu_kernel_for(int model, bool single_precision, bool native_math, const CpuIsa& isa) {
  const auto& isas = cpu_isa_table();
  for (const CpuKernelRow& r : cpu_kernel_table())
    if (r.model == model && r.single == single_precision && r.native == native_math && &isas.at(r.isa) == &isa)
      return r.kernel;
  return nullptr;
}

CpuKernel cpu_kernel(int model, bool single_precision, bool native_math) {
  return cpu_kernel_for(model, single_precision, native_math, cpu_isa_selected());
}

}  // namespace arnoldweb::detail
