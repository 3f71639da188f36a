// arnoldweb_bench: the same as `arnoldweb bench` (bench/throughput/bench.hpp),
// as a stand-alone program for the GPU-machine script.
#include <CLI/CLI.hpp>
#include <iostream>

#include "arnoldweb/bench.hpp"

int main(int argc, char** argv) {
  CLI::App app{"arnoldweb_bench: throughput against N on every device, with the naive baselines"};
  arnoldweb::bench::Options o;
  arnoldweb::bench::add_options(&app, o);
  CLI11_PARSE(app, argc, argv);
  std::string command;
  for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
  try {
    return arnoldweb::bench::run(o, command, std::cout);
  } catch (const std::exception& e) {
    std::cerr << "arnoldweb_bench: error: " << e.what() << "\n";
    return 1;
  }
}
