// arnoldweb: command-line interface.
//   arnoldweb devices | methods | check SCENE | run SCENE [options]
// Exit codes: 0 success, 1 unexpected error, 2 bad input (usage, scene),
// 3 output problem, 4 device problem, 130 interrupted (partial result written).
#include <CLI/CLI.hpp>

#include <iostream>

#include "arnoldweb/arnoldweb.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace arnoldweb::cli;
  CLI::App app{"arnoldweb " ARNOLDWEB_VERSION
               " - maps the Arnold web of H = |P|^2/2 + cos x cos y (1 + cos 2z)\n"
               "with ensembles of symplectic trajectories on GPUs and CPUs.\n"
               "Exit codes: 0 ok, 1 unexpected error, 2 bad input, 3 output problem,\n"
               "4 device problem, 130 interrupted (partial result written)."};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(ARNOLDWEB_VERSION));

  bool json = false;
  auto* devices = app.add_subcommand("devices", "List the devices: id, name, vendor, fp64, compute units");
  devices->add_flag("--json", json, "Print JSON");

  app.add_subcommand("methods", "List the integrators: order, force evaluations per step, stability");

  RunArgs args;
  auto add_scene_options = [&](CLI::App* c) {
    c->add_option("scene", args.scene, "Scene file (TOML)")->required();
    c->add_option("--device,-d", args.device, "Device id (cpu, opencl:N, cuda:N, auto)");
    c->add_option("--set,-s", args.sets, "Override a scene key: --set integrator.step=0.005")
        ->allow_extra_args(false);
    c->add_option("--out,-o", args.out, "Output directory (overrides output.dir)");
  };
  auto* check = app.add_subcommand("check", "Validate a scene and print the plan");
  add_scene_options(check);
  auto* run = app.add_subcommand("run", "Run a scene and write its outputs");
  add_scene_options(run);
  run->add_flag("--force,-f", args.force, "Replace an existing output directory");
  run->add_flag("--quiet,-q", args.quiet, "Print nothing but errors");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  try {
    if (*devices) return cmd_devices(json);
    if (app.got_subcommand("methods")) return cmd_methods();
    if (*check) return cmd_check(args);
    if (*run) return cmd_run(args);
  } catch (const arnoldweb::Error& e) {
    std::cerr << "arnoldweb: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "arnoldweb: unexpected error: " << e.what() << "\n";
    return 1;
  }
  return 1;
}
