// arnoldweb: command-line interface. `arnoldweb --help` lists the commands.
// Exit codes: 0 success, 1 unexpected error, 2 bad input (usage, scene),
// 3 output problem, 4 device problem, 130 interrupted (partial result written).
#include <iostream>
#include <memory>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/version.hpp"
#include "command.hpp"
#include "ranks.hpp"

int main(int argc, char** argv) {
  using namespace arnoldweb::cli;
  CLI::App app{"arnoldweb " ARNOLDWEB_VERSION
               " - maps the Arnold web of H = |P|^2/2 + cos x cos y (1 + cos 2z)\n"
               "with ensembles of symplectic trajectories on GPUs and CPUs.\n"
               "Exit codes: 0 ok, 1 unexpected error, 2 bad input, 3 output problem,\n"
               "4 device problem, 130 interrupted (partial result written)."};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(ARNOLDWEB_VERSION));

  Action action;
  add_devices_command(app, action);
  add_methods_command(app, action);
  add_models_command(app, action);
  add_check_command(app, action);
  add_run_command(app, action);
  add_orbit_command(app, action);
  add_resume_command(app, action);
  add_continue_command(app, action);
  add_bench_command(app, action);
  add_keys_command(app, action);
  add_render_command(app, action);
  add_compare_command(app, action);
  add_accuracy_command(app, action);
  add_view_command(app, action);
  add_serve_command(app, action);

  // an unknown command is named (CLI11 would only say that one is required)
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    std::string names;
    for (const CLI::App* sub : app.get_subcommands({})) {
      known |= sub->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      std::cerr << "arnoldweb: error: unknown command '" << argv[1] << "' (commands: " << names
                << "; arnoldweb --help)\n";
      return 2;
    }
  }
  // under mpirun/srun with the MPI build: MPI_Init (ranks.hpp; docs/cluster.md)
  std::unique_ptr<arnoldweb::Cluster> ranks;
  try {
    ranks = arnoldweb::start_cluster(&argc, &argv);
  } catch (const arnoldweb::Error& e) {
    std::cerr << "arnoldweb: error: " << e.what() << "\n";
    return e.exit_code();
  }
  set_cluster(ranks.get());
  // with several ranks an error on any rank ends them all (no rank waits forever)
  auto fail = [&](int code, const std::string& text) {
    std::cerr << "arnoldweb: " << text << "\n";
    if (ranks) {
      std::cerr.flush();
      ranks->abort(code);
    }
    return code;
  };
  const std::string who = ranks ? "rank " + std::to_string(ranks->rank()) + " of " + std::to_string(ranks->size()) + ": " : "";
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  try {
    return action ? action() : 2;
  } catch (const arnoldweb::Error& e) {
    return fail(e.exit_code(), who + "error: " + e.what());
  } catch (const std::exception& e) {
    return fail(1, who + "unexpected error: " + e.what());
  }
}
