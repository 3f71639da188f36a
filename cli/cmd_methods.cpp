// arnoldweb methods: the integrators, their order, cost and stability limit.
#include <cstdio>

#include "arnoldweb/methods.hpp"
#include "command.hpp"

namespace arnoldweb::cli {

void add_methods_command(CLI::App& app, Action& action) {
  auto* c = app.add_subcommand("methods", "List the integrators: order, force evaluations per step, stability limit");
  c->callback([&action] {
    action = [] {
      std::printf("%-14s %5s %-10s %12s %10s  %s\n", "method", "order", "eps order", "forces/step", "stability",
                  "name");
      for (const auto& m : methods())
        std::printf("%-14s %5d %-10s %12d %10.3f  %s\n", m.name.c_str(), m.order,
                    (eps_order_string(m) + (m.rkn ? " rkn" : "")).c_str(), m.stages, m.stability,
                    (m.title + (m.force_gradient() ? " [+grad]" : "")).c_str());
      std::printf("order: in h at eps = O(1); eps order (p,q,r): error O(eps h^p + eps^2 h^q + eps^3 h^r) for\n"
                  "H = |P|^2/2 + eps V, eps_eff = 2/E (the last entry for every higher power of eps); rkn: the\n"
                  "orders need V to depend on X only, as here; [+grad]: force-gradient kicks (the gradient of\n"
                  "|grad V|^2 from the force's own sin/cos, no extra force evaluation)\n"
                  "stability: linear stability limit h*omega on a harmonic oscillator (docs/methods.md)\n");
      return 0;
    };
  });
}

}  // namespace arnoldweb::cli
