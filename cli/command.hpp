// arnoldweb CLI: every subcommand lives in its own file (cmd_<name>.cpp) and
// registers itself here; main.cpp parses, runs the chosen action and maps
// errors to exit codes.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "arnoldweb/scene.hpp"

namespace arnoldweb::cli {

// What the chosen subcommand does once the command line is parsed; returns
// the exit code.
using Action = std::function<int()>;

// Options shared by the commands that take a scene.
struct SceneArgs {
  std::string scene;
  std::string device;  // empty: the scene's run.device
  std::string out;     // empty: the scene's output.dir
  std::vector<std::string> sets;
};
void add_scene_options(CLI::App* command, SceneArgs& args);
// Read the scene with --set, --out and --device applied.
Scene load_scene_args(const SceneArgs& args);

void add_devices_command(CLI::App& app, Action& action);
void add_methods_command(CLI::App& app, Action& action);
void add_check_command(CLI::App& app, Action& action);
void add_run_command(CLI::App& app, Action& action);
void add_bench_command(CLI::App& app, Action& action);
void add_keys_command(CLI::App& app, Action& action);
void add_render_command(CLI::App& app, Action& action);
void add_accuracy_command(CLI::App& app, Action& action);

}  // namespace arnoldweb::cli
