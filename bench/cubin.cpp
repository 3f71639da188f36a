// arnoldweb_cubin: the CUDA ensemble kernel as the cuda backend compiles it
// (NVRTC from the embedded sources, the backend's options, and
// ARNOLDWEB_NVRTC_OPTIONS), written to a file. Needs NVRTC only, no GPU: for
// reading the SASS of a configuration (bench/gpu/sass_count.py).
//
//   arnoldweb_cubin ARCH OUT.cubin DEFINES...     e.g. 90 k.cubin -DAW_FEATURES=3u -DAW_STAGES=7 ...
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

#include "arnoldweb/errors.hpp"
#include "backends/cuda/nvrtc_compiler.hpp"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: arnoldweb_cubin ARCH OUT.cubin DEFINES...  (as `arnoldweb check` prints them)\n";
    return 2;
  }
  std::string defines;
  for (int i = 3; i < argc; ++i) defines += std::string(i > 3 ? " " : "") + argv[i];
  try {
    const auto target = arnoldweb::detail::nvrtc_target(std::atoi(argv[1]), "arnoldweb_cubin");
    const auto img = arnoldweb::detail::nvrtc_compile_ensemble(defines, target, "arnoldweb_cubin");
    std::ofstream out(argv[2], std::ios::binary);
    out.write(img.data.data(), static_cast<std::streamsize>(img.data.size()));
    if (!out) {
      std::cerr << "arnoldweb_cubin: cannot write " << argv[2] << "\n";
      return 3;
    }
    std::cout << img.options << "\n";
  } catch (const arnoldweb::Error& e) {
    std::cerr << e.what() << "\n";
    return 4;
  }
  return 0;
}
