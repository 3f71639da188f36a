# The cpu backend's kernels: the device core compiled ahead of time as C++,
# one translation unit per (model, precision, math, instruction set), generated
# here from lib/src/backends/cpu/cpu_kernel_variant.cpp.in, plus the tables
# that find them (cpu_kernel_table.cpp, read by backends/cpu/cpu_isa.cpp). The
# models are read from the generated models/aw_models.h (its
# "#define AW_MODEL_<NAME> <id>" lines), so a new model needs no change here.
#
#   arnoldweb_cpu_kernels(<out-var> <models-header> <output-dir>)
#
# Instruction sets (ARNOLDWEB_CPU_ISAS): every kernel is compiled once per
# -march of the list, and the best one the CPU supports is chosen when the
# kernel is picked (__builtin_cpu_supports; ARNOLDWEB_CPU_ISA=<name> in the
# environment forces one). The default on x86-64 is the baseline x86-64
# (SSE2), x86-64-v3 (AVX2, FMA) and x86-64-v4 (AVX-512): the library runs on
# any x86-64 CPU, so one build serves the CLI, the wheel and any machine. The
# bits do not depend on the set (FP contraction is off, fma is explicit and
# correctly rounded everywhere; the test cpu_isa.parity compares them). An
# empty list builds one set, -march=${ARNOLDWEB_CPU_ARCH} (e.g. native), as
# builds did before.
#
# Lanes (trajectories per vector): one vector register of the instruction
# set. Wider vectors than the registers are split by GCC into halves with many
# scalar moves and inserts: on a 2-core AVX2 EPYC (znver3) 8 double lanes made
# the kernel ~4x the instructions of 4 lanes and the cpu backend 5x slower than
# PoCL (docs/performance.md, "AVX2"); on AVX-512, 16 double lanes ran 6x slower
# than 8. "auto" picks 8/16 (double/float) where the set has AVX-512F, 4/8
# where it has AVX, and 2/4 (SSE2) otherwise. The bits do not depend on the lanes.
if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  set(aw_default_isas "x86-64;x86-64-v3;x86-64-v4")
else()
  set(aw_default_isas "")
endif()
set(ARNOLDWEB_CPU_ISAS "${aw_default_isas}" CACHE STRING
    "-march= sets the cpu backend's kernels are compiled for, chosen at run time (empty: one set, ARNOLDWEB_CPU_ARCH; host: x86-64 and the best level this machine runs)")

# "host" (scripts/bootstrap.sh's choice for a build that runs where it is
# built): the baseline x86-64 and the highest of x86-64-v3/v4 this machine
# runs, i.e. the sets its tests can run and compare (ctest cpu.isa). A set the
# machine cannot run is never run here: a third of the build time of the
# cpu kernels saved on 2 cores (24 instead of 36 variants on AVX-512 or AVX2).
# The wheel, packages and installs keep the default list and run anywhere.
# The features of each level that __builtin_cpu_supports knows in GCC and
# clang alike (clang before 19 has no "x86-64-v3" there), and the C expression
# that checks them at run time.
set(aw_isa_features_v2 "sse3;ssse3;sse4.1;sse4.2;popcnt")
set(aw_isa_features_v3 "${aw_isa_features_v2};avx;avx2;bmi;bmi2;fma")
set(aw_isa_features_v4 "${aw_isa_features_v3};avx512f;avx512bw;avx512cd;avx512dq;avx512vl")
function(aw_isa_check level out_var)
  set(features ${aw_isa_features_v${level}})
  list(TRANSFORM features PREPEND "__builtin_cpu_supports(\"")
  list(TRANSFORM features APPEND "\")")
  list(JOIN features " && " check)
  set(${out_var} "${check}" PARENT_SCOPE)
endfunction()
function(aw_resolve_host_isas out_var)
  include(CheckCXXSourceRuns)
  set(CMAKE_REQUIRED_QUIET ON)
  foreach(level 4 3)
    aw_isa_check(${level} check)
    check_cxx_source_runs("int main() { __builtin_cpu_init(); return (${check}) ? 0 : 1; }"
                          ARNOLDWEB_HOST_RUNS_X86_64_V${level})
    if(ARNOLDWEB_HOST_RUNS_X86_64_V${level})
      set(${out_var} "x86-64;x86-64-v${level}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  set(${out_var} "x86-64" PARENT_SCOPE)
endfunction()
set(aw_cpu_isas "${ARNOLDWEB_CPU_ISAS}")
if(ARNOLDWEB_CPU_ISAS STREQUAL "host")
  if(NOT CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
    set(aw_cpu_isas "")
  else()
    aw_resolve_host_isas(aw_cpu_isas)
  endif()
  message(STATUS "arnoldweb: ARNOLDWEB_CPU_ISAS=host: ${aw_cpu_isas}")
endif()
set(ARNOLDWEB_CPU_LANES_DOUBLE auto CACHE STRING "Trajectories per vector in the cpu backend's double kernels (auto: one register of the ISA)")
set(ARNOLDWEB_CPU_LANES_FLOAT auto CACHE STRING "Trajectories per vector in the cpu backend's float kernels (auto: one register of the ISA)")

# aw_cpu_lanes(<-march or ""> <double-var> <float-var>): the lanes for one set.
function(aw_cpu_lanes march double_var float_var)
  include(CheckCXXSourceCompiles)
  set(CMAKE_REQUIRED_QUIET ON)
  if(march)
    set(CMAKE_REQUIRED_FLAGS "-march=${march}")
  endif()
  string(MAKE_C_IDENTIFIER "${march}" id)
  check_cxx_source_compiles("#ifndef __AVX512F__\n#error no AVX-512F\n#endif\nint main() { return 0; }"
                            ARNOLDWEB_CPU_HAS_AVX512_${id})
  check_cxx_source_compiles("#ifndef __AVX__\n#error no AVX\n#endif\nint main() { return 0; }"
                            ARNOLDWEB_CPU_HAS_AVX_${id})
  if(ARNOLDWEB_CPU_HAS_AVX512_${id})
    set(d 8)
    set(f 16)
  elseif(ARNOLDWEB_CPU_HAS_AVX_${id})
    set(d 4)
    set(f 8)
  else()
    set(d 2)
    set(f 4)
  endif()
  if(NOT ARNOLDWEB_CPU_LANES_DOUBLE STREQUAL "auto")
    set(d ${ARNOLDWEB_CPU_LANES_DOUBLE})
  endif()
  if(NOT ARNOLDWEB_CPU_LANES_FLOAT STREQUAL "auto")
    set(f ${ARNOLDWEB_CPU_LANES_FLOAT})
  endif()
  set(${double_var} ${d} PARENT_SCOPE)
  set(${float_var} ${f} PARENT_SCOPE)
endfunction()

# The options of every cpu kernel beyond the library's own (the device core's
# -ffp-contract=off -fno-fast-math, OpenMP, C++17), besides its -march.
set(ARNOLDWEB_CPU_KERNEL_OPTIONS -O3)

# arnoldweb_cpu_runtime_config(<header> <device-core-target>): the header that
# tells lib/src/backends/cpu/cpu_runtime_kernel.cpp how the variants compiled
# here were compiled, so that an expression model's kernel compiled at run time
# gets the same options: the compiler and the command-line options (C++17, the
# device core's, OpenMP's, ARNOLDWEB_CPU_KERNEL_OPTIONS, -DNDEBUG), plus those
# of a shared object with one visible symbol. The instruction set (-march) and
# the lanes are the set the cpu backend runs (backends/cpu/cpu_isa.hpp).
function(arnoldweb_cpu_runtime_config header core_target)
  get_target_property(core_options ${core_target} INTERFACE_COMPILE_OPTIONS)
  separate_arguments(openmp_options UNIX_COMMAND "${OpenMP_CXX_FLAGS}")
  set(options -std=c++17 ${ARNOLDWEB_CPU_KERNEL_OPTIONS} -DNDEBUG ${core_options} ${openmp_options}
              -fPIC -shared -fvisibility=hidden)
  set(quoted "")
  foreach(o IN LISTS options)
    string(APPEND quoted "\"${o}\", ")
  endforeach()
  file(CONFIGURE OUTPUT "${header}" CONTENT
"// arnoldweb: how the cpu kernel variants of this build were compiled
// (generated by cmake/ArnoldwebCpuKernels.cmake), for the expression-model
// kernels compiled at run time (cpu_runtime_kernel.cpp).
#pragma once
#define ARNOLDWEB_CPU_RUNTIME_CXX \"${CMAKE_CXX_COMPILER}\"
#define ARNOLDWEB_CPU_RUNTIME_OPTIONS ${quoted}
" @ONLY)
endfunction()
function(arnoldweb_cpu_kernels out_var models_header out_dir)
  file(STRINGS "${models_header}" model_lines REGEX "^#define AW_MODEL_[A-Z0-9_]+ [0-9]+")
  set(template "${PROJECT_SOURCE_DIR}/lib/src/backends/cpu/cpu_kernel_variant.cpp.in")
  # the sets, best first (the run-time choice takes the first one the CPU supports)
  set(isas ${aw_cpu_isas})
  list(REVERSE isas)
  if(NOT isas)
    set(isas "${ARNOLDWEB_CPU_ARCH}")
  endif()
  set(sources)
  set(declarations "")
  set(rows "")
  set(isa_rows "")
  set(isa_index 0)
  foreach(isa IN LISTS isas)
    if(aw_cpu_isas)
      if(isa STREQUAL "x86-64")
        set(check "true")
      elseif(isa MATCHES "^x86-64-v([234])$")
        aw_isa_check(${CMAKE_MATCH_1} check)
      else()
        message(FATAL_ERROR "ARNOLDWEB_CPU_ISAS: '${isa}' is not one of x86-64, x86-64-v2, x86-64-v3, x86-64-v4 "
                            "(a set the library can check for at run time); for one other set use "
                            "-DARNOLDWEB_CPU_ISAS= -DARNOLDWEB_CPU_ARCH=${isa}")
      endif()
      string(MAKE_C_IDENTIFIER "${isa}" isa_suffix)
      set(isa_suffix "_${isa_suffix}")
      set(isa_name "${isa}")
    else()
      set(check "true")  # one set, for the machine that builds (as before the sets)
      set(isa_suffix "")
      set(isa_name "${isa}")
      if(NOT isa_name)
        set(isa_name "default")
      endif()
    endif()
    aw_cpu_lanes("${isa}" lanes_double lanes_float)
    message(STATUS "arnoldweb: cpu kernels for ${isa_name}: ${lanes_double} double lanes, ${lanes_float} float lanes")
    string(APPEND isa_rows "      {\"${isa_name}\", ${lanes_double}, ${lanes_float}, [] { return ${check}; }},\n")
    foreach(line IN LISTS model_lines)
      string(REGEX REPLACE "^#define AW_MODEL_([A-Z0-9_]+) ([0-9]+).*" "\\1;\\2" parts "${line}")
      list(GET parts 0 model_upper)
      list(GET parts 1 MODEL_ID)
      string(TOLOWER "${model_upper}" model)
      set(MODEL_HEADER_DEFINE "#define AW_MODEL_HEADER \"models/aw_${model}.h\"  // this model's alone (aw_model.h)")
      foreach(precision double float)
        foreach(math portable native)
          set(VARIANT "${model}_${precision}_${math}${isa_suffix}")
          if(precision STREQUAL "float")
            set(PRECISION_DEFINE "#define AW_FLOAT 1")
            set(LANES ${lanes_float})
            set(single true)
          else()
            set(PRECISION_DEFINE "")
            set(LANES ${lanes_double})
            set(single false)
          endif()
          if(math STREQUAL "native")
            set(MATH_DEFINE "#define AW_NATIVE_MATH 1")
            set(native true)
          else()
            set(MATH_DEFINE "")
            set(native false)
          endif()
          set(file "${out_dir}/cpu_kernel_${VARIANT}.cpp")
          configure_file("${template}" "${file}" @ONLY)
          if(isa)
            set_source_files_properties("${file}" PROPERTIES COMPILE_OPTIONS "-march=${isa};${ARNOLDWEB_CPU_KERNEL_OPTIONS}")
          else()
            set_source_files_properties("${file}" PROPERTIES COMPILE_OPTIONS "${ARNOLDWEB_CPU_KERNEL_OPTIONS}")
          endif()
          list(APPEND sources "${file}")
          string(APPEND declarations "void cpu_chunk_${VARIANT}(const CpuChunk& c);\n")
          string(APPEND rows "      {${MODEL_ID}, ${single}, ${native}, ${isa_index}, cpu_chunk_${VARIANT}},\n")
        endforeach()
      endforeach()
    endforeach()
    math(EXPR isa_index "${isa_index} + 1")
  endforeach()
  file(CONFIGURE OUTPUT "${out_dir}/cpu_kernel_table.cpp" CONTENT
"// arnoldweb: the cpu kernel variants of this build and the instruction sets
// they were compiled for, best first (generated by
// cmake/ArnoldwebCpuKernels.cmake; backends/cpu/cpu_isa.cpp chooses).
#include \"backends/cpu/cpu_isa.hpp\"

namespace arnoldweb::detail {

${declarations}
const std::vector<CpuIsa>& cpu_isa_table() {
  static const std::vector<CpuIsa> isas = {
${isa_rows}  };
  return isas;
}

const std::vector<CpuKernelRow>& cpu_kernel_table() {
  static const std::vector<CpuKernelRow> rows = {
${rows}  };
  return rows;
}

}  // namespace arnoldweb::detail
" @ONLY)
  set(${out_var} ${sources} "${out_dir}/cpu_kernel_table.cpp" PARENT_SCOPE)
endfunction()
