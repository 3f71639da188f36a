// arnoldweb: which compiled instruction set the cpu backend runs. Every cpu
// kernel is compiled for each set of ARNOLDWEB_CPU_ISAS (by default x86-64,
// x86-64-v3 and x86-64-v4; cmake/ArnoldwebCpuKernels.cmake), and the best set
// this CPU supports is chosen when a kernel is picked, unless the environment
// names one (ARNOLDWEB_CPU_ISA=x86-64-v3). The bits do not depend on the set.
#pragma once

#include <string>
#include <vector>

#include "backends/cpu/cpu_kernel.hpp"

namespace arnoldweb::detail {

// One instruction set of this build (generated table, best first).
struct CpuIsa {
  const char* name;        // the -march it was compiled with, e.g. "x86-64-v4"
  int lanes_double, lanes_float;
  bool (*supported)();     // whether this CPU runs it
};

// One kernel: (model, precision, math) compiled for the set isa (an index of cpu_isa_table()).
struct CpuKernelRow {
  int model;
  bool single, native;
  int isa;
  CpuKernel kernel;
};

// The generated tables (cpu_kernel_table.cpp).
const std::vector<CpuIsa>& cpu_isa_table();
const std::vector<CpuKernelRow>& cpu_kernel_table();

// The sets of this build that this CPU supports, best first.
std::vector<std::string> cpu_isas_supported();
// Every set of this build, best first.
std::vector<std::string> cpu_isas_built();

// The set the cpu backend runs: $ARNOLDWEB_CPU_ISA when set (a DeviceError
// names the sets when it is not one of this build's, or this CPU lacks it),
// else the best set this CPU supports.
const CpuIsa& cpu_isa_selected();

// The variant for (model, precision, math) in the set `isa`, or null if this build has none.
CpuKernel cpu_kernel_for(int model, bool single_precision, bool native_math, const CpuIsa& isa);

}  // namespace arnoldweb::detail
