// arnoldweb bench: throughput against N on every device with the plain
// baselines timed in the same process, the cost of each effect, GPU memory
// of large runs (arnoldweb/bench.hpp, built in bench/; docs/performance.md).
#include <iostream>

#include "arnoldweb/bench.hpp"
#include "command.hpp"

namespace arnoldweb::cli {

void add_bench_command(CLI::App& app, Action& action) {
  auto opts = std::make_shared<bench::Options>();
  auto* c = app.add_subcommand(
      "bench", "Throughput (trajectory-steps/s) against N on every device, with naive OpenMP/CUDA baselines");
  bench::add_options(c, *opts);
  c->callback([&action, opts, c] {
    std::string command = "arnoldweb bench";
    for (const auto* opt : c->get_options()) {
      if (opt->count() == 0 || opt->get_name() == "--help") continue;
      command += " " + opt->get_name();
      std::string values;
      for (const auto& v : opt->results()) values += (values.empty() ? "" : ",") + v;
      if (opt->get_expected_min() > 0) command += " " + values;
    }
    action = [opts, command] { return bench::run(*opts, command, std::cout); };
  });
}

}  // namespace arnoldweb::cli
