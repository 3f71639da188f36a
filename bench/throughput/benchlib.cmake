# The bench library behind `arnoldweb bench` and arnoldweb_bench (bench/):
# included from cli/CMakeLists.txt so that the CLI has the command whether or
# not ARNOLDWEB_BENCH builds the bench programs. The naive CUDA baseline is a
# shared library built in bench/CMakeLists.txt where nvcc is found, loaded at
# run time.
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(CLI11 REQUIRED)
set(_aw_bench_dir ${PROJECT_SOURCE_DIR}/bench)
add_library(arnoldweb_benchlib STATIC
  ${_aw_bench_dir}/throughput/bench.cpp
  ${_aw_bench_dir}/throughput/naive_cuda_loader.cpp
  ${_aw_bench_dir}/baselines/naive_openmp.cpp)
target_include_directories(arnoldweb_benchlib PUBLIC ${_aw_bench_dir}/throughput ${_aw_bench_dir}/baselines)
target_link_libraries(arnoldweb_benchlib PUBLIC arnoldweb::arnoldweb CLI11::CLI11 PRIVATE OpenMP::OpenMP_CXX
                      nlohmann_json::nlohmann_json ${CMAKE_DL_LIBS})
target_compile_definitions(arnoldweb_benchlib PRIVATE
  ARNOLDWEB_BINARY_DIR="${PROJECT_BINARY_DIR}"
  ARNOLDWEB_BENCH_PLOT_SCRIPT="${_aw_bench_dir}/throughput/plot_bench.py")
# The baseline is "the obvious way": plain -O3 scalar code for the same CPU
# as the cpu backend (-march), libm sin/cos, no fast-math.
if(ARNOLDWEB_CPU_ARCH)
  set_source_files_properties(${_aw_bench_dir}/baselines/naive_openmp.cpp PROPERTIES
    COMPILE_OPTIONS "-march=${ARNOLDWEB_CPU_ARCH};-O3")
endif()
target_compile_options(arnoldweb_benchlib PRIVATE -Wall -Wextra)
target_sources(arnoldweb-cli PRIVATE ${PROJECT_SOURCE_DIR}/cli/cmd_bench.cpp)
target_link_libraries(arnoldweb-cli PRIVATE arnoldweb_benchlib)
