// arnoldweb CLI: every subcommand lives in its own file (cmd_<name>.cpp) and
// registers itself here; main.cpp parses, runs the chosen action and maps
// errors to exit codes.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include <optional>

#include "arnoldweb/run.hpp"
#include "arnoldweb/output.hpp"
#include "arnoldweb/scene.hpp"

namespace arnoldweb::cli {

// What the chosen subcommand does once the command line is parsed; returns
// the exit code.
using Action = std::function<int()>;

// Options shared by the commands that take a scene.
struct SceneArgs {
  std::string scene;
  std::optional<std::string> device;  // absent: the scene's run.device
  std::optional<std::string> out;     // absent: the scene's output.dir
  std::vector<std::string> sets;
};
void add_scene_options(CLI::App* command, SceneArgs& args);
// Read the scene with --set, --out and --device applied (errors name the
// option the user typed).
Scene load_scene_args(const SceneArgs& args);
// --device as the scene reader reads run.device (trimmed, its form checked;
// an error names --device); absent stays absent.
std::optional<std::string> read_device_option(const std::optional<std::string>& device);

// What `check` and `run` both validate before anything is computed: the
// scene, every panel, and the output directory (made-writable probe, free
// space for the estimated outputs, the --force rules). One path, so the two
// commands agree.
struct PreparedJob {
  Job job;
  OutputOptions output;
  std::string out_dir;  // normalised
};
// Also refuses a job that does not fit the device's or this process's memory;
// where the device is not on this machine, `check` only warns (warning).
PreparedJob prepare_job(const SceneArgs& args, bool force, std::string* device_warning = nullptr);

// Runs a prepared job and writes its outputs (run and resume): checkpoints
// per run.checkpoint_every, continuing from `resume` when given; returns the
// exit code (128 + signal when stopped).
// `device_option`: --device as given (a list gives each MPI rank its entry);
// `opening`: the devices already being opened (run), else they are opened here.
class DeviceOpening;
int execute_job(const PreparedJob& prepared, bool quiet, const std::optional<FoundCheckpoint>& resume,
                const std::optional<std::string>& device_option, DeviceOpening* opening = nullptr);
// The checkpoint a resumed run of `out_dir` continues; CheckpointError if none.
FoundCheckpoint checkpoint_to_resume(const std::string& out_dir);
// prepare_job for a scene already read (resume reads it from a checkpoint).
PreparedJob prepare_scene_job(const Scene& scene, const std::string& scene_file, bool force,
                              std::string* device_warning = nullptr);

void add_resume_command(CLI::App& app, Action& action);
void add_continue_command(CLI::App& app, Action& action);
void add_devices_command(CLI::App& app, Action& action);
void add_methods_command(CLI::App& app, Action& action);
void add_models_command(CLI::App& app, Action& action);
void add_check_command(CLI::App& app, Action& action);
void add_run_command(CLI::App& app, Action& action);
void add_bench_command(CLI::App& app, Action& action);
void add_keys_command(CLI::App& app, Action& action);
void add_render_command(CLI::App& app, Action& action);
void add_compare_command(CLI::App& app, Action& action);
void add_accuracy_command(CLI::App& app, Action& action);
void add_view_command(CLI::App& app, Action& action);
void add_serve_command(CLI::App& app, Action& action);
void add_orbit_command(CLI::App& app, Action& action);

}  // namespace arnoldweb::cli
