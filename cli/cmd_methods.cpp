// arnoldweb methods: the integrators, their order, cost and stability limit.
#include <cstdio>

#include "arnoldweb/methods.hpp"
#include "command.hpp"

namespace arnoldweb::cli {

void add_methods_command(CLI::App& app, Action& action) {
  auto* c = app.add_subcommand("methods", "List the integrators: order, force evaluations per step, stability limit");
  c->callback([&action] {
    action = [] {
      std::printf("%-14s %5s %12s %10s  %s\n", "method", "order", "forces/step", "stability", "name");
      for (const auto& m : methods())
        std::printf("%-14s %5d %12d %10.3f  %s\n", m.name.c_str(), m.order, m.stages, m.stability,
                    m.title.c_str());
      std::printf("stability: linear stability limit h*omega on a harmonic oscillator (docs/methods.md)\n");
      return 0;
    };
  });
}

}  // namespace arnoldweb::cli
