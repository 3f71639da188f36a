// arnoldweb: checkpoints of a job. A checkpoint holds the program version,
// the job's identity (a hash of every part's scene as run, without the keys
// that do not change results: run.device, output.dir, run.checkpoint_every),
// the scene's source (file name, text, --set overrides: what `resume` plans
// again), and the partial reduction of every part begun: which trajectories
// are done, counters, histograms, energy statistics, state records. The
// image ends with an XXH64 of everything before it. Checkpoints are written
// by run_job (run.hpp: Checkpointing) and kept by the output directory's
// staging rules (output.hpp: find_checkpoints).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace arnoldweb {

struct Job;

// Hex digest of the job's scenes as run (the identity a checkpoint must match).
std::string job_identity(const Job& job);

struct CheckpointInfo {
  std::string version;   // ARNOLDWEB_VERSION of the writer
  std::string identity;  // job_identity of the job it belongs to
  std::string scene_file, scene_text;
  std::vector<std::string> overrides, override_labels;
  std::uint64_t parts = 0, parts_begun = 0;
  std::uint64_t completed = 0, trajectories = 0;  // over every part
};

// Reads the header of a checkpoint image and checks its integrity; throws
// CheckpointError naming `path` (damaged, truncated, not a checkpoint).
CheckpointInfo read_checkpoint_info(const std::string& image, const std::string& path);

// The bytes of the checkpoint file `path`, read as a plain file without
// blocking (a FIFO or a device in its place is refused, not waited on);
// CheckpointError naming it otherwise.
std::string read_checkpoint_file(const std::string& path);

}  // namespace arnoldweb
