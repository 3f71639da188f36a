// arnoldweb: writing results. Every file is written under a temporary name and
// renamed into place, so a failed write (full disk) leaves no partial file.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"
#include "arnoldweb/run.hpp"

namespace arnoldweb {

struct Job;
struct JobResult;

// How an output directory may be used.
struct OutputOptions {
  // Replace an existing directory, but only one that a run of arnoldweb wrote
  // (its summary.json lists every file in it and nothing else is inside).
  bool force = false;
  // The scene's file: a directory holding it is never replaced.
  std::string scene_file;
  // Refuse before computing when the file system has less free than this.
  std::uint64_t expected_bytes = 0;
  // The staging directory this run made earlier for its checkpoints
  // (CheckpointStore::staging()): the outputs are written into it and it is
  // moved into place, its checkpoint removed (consumed). "" : a new one.
  std::string staging;
};

// Checkpoints beside an output directory: staging directories
// <dir>.partial-PID that hold a checkpoint (written by a run that was stopped
// or killed). Nothing removes them but a resumed run that completes.
struct FoundCheckpoint {
  std::string staging_dir;  // <dir>.partial-PID
  std::string file;         // its checkpoint
  long pid = 0;
  bool running = false;  // that process is still alive (then it is not resumable)
};
std::vector<FoundCheckpoint> find_checkpoints(const std::string& dir);

// Where a run's checkpoints go: <dir>.partial-PID, made (with the staging
// marker) at the first save, each checkpoint written atomically. Pass
// staging() as OutputOptions::staging to write_job.
class CheckpointStore final : public CheckpointSink {
 public:
  CheckpointStore(std::string dir, OutputOptions options);
  // Takes over a checkpoint found beside the directory (renaming its staging
  // directory to this process's) and returns its image. Throws OutputError
  // (a running process's, unreadable) .
  std::string adopt(const FoundCheckpoint& found);
  void save(const std::string& image) override;
  const std::string& staging() const { return staging_; }
  std::string file() const;

 private:
  std::string dir_, staging_;
  OutputOptions options_;
};

// Checks, before anything is computed, that `dir` can receive a job's
// outputs: the name is normalised (trailing slashes, "." and ".."); an existing
// directory is refused without force (OutputError, exit 3) and refused always
// (OutputRefused, exit 2) if arnoldweb did not write it or it is the current
// directory, a parent of it or of the scene file, / or $HOME; the place is
// made writable-checked with a probe that is created and removed; the free
// space is compared with options.expected_bytes. Staging directories left by
// dead processes beside it are removed. Returns the normalised name.
std::string check_output_dir(const std::string& dir, const OutputOptions& options);

// An upper estimate of the bytes a job writes (data and pictures).
std::uint64_t estimate_output_bytes(const Job& job);

// Writes a job's outputs into its main scene's output.dir: summary.json,
// map.h5, states.h5 (if states were asked for), pictures, panel-<name>/ for
// every panel that ran and figure.png. The files are produced in a staging
// directory beside it and moved into place at the end; summary.json, written
// last, lists every file ("files"). If a write fails (full disk), the
// directory in place is left as it was, what was written is kept under a name
// the error gives, and OutputError says which file failed and why. Returns
// the paths written.
std::vector<std::string> write_job(const Job& job, const JobResult& result, const OutputOptions& options);

// One run's outputs (a job of one part).
std::vector<std::string> write_outputs(const Plan& plan, const Result& result, const std::string& dir,
                                       const OutputOptions& options);

// A file of an output directory as its summary.json records it
// ("file_digests"): the size and the XXH3-128 digest of its bytes, taken by
// the atomic writer that put it in place and checked when the directory is
// read back (render, compare, resume, Python; docs/reliability.md).
struct FileDigest {
  std::uint64_t bytes = 0;
  std::string xxh3_128;  // 32 lowercase hex digits
};
using FileDigests = std::map<std::string, FileDigest>;  // by name relative to the directory

// The summary as JSON text; `files` lists the files of its directory and
// `digests` their sizes and digests ("file_digests", written when given).
std::string summary_json(const Plan& plan, const Result& result, const std::vector<std::string>& files = {},
                         const FileDigests* digests = nullptr);

// Individual writers (each atomic).
void write_text_file(const std::string& path, const std::string& text);
void write_map_hdf5(const std::string& path, const Plan& plan, const Result& result);
// map.fits: the velocity map as a HEALPix FITS binary table (RING, NSIDE), for
// healpy.read_map; written where output.formats asks for "fits".
void write_map_fits(const std::string& path, const Plan& plan, const Result& result);
// One dataset of a per-trajectory output as its file holds it (the output
// table's datasets; docs/outputs.md): e.g. output "final_states", dataset
// "momentum" of shape {n, 3}; "indicators"/"fli" of the grid's shape.
struct OutputDataset {
  std::string output, name, meaning;
  std::string file, group;             // where the writer puts it
  std::vector<std::uint64_t> shape;
  bool integers = false;               // values in `ints`, else in `reals`
  std::vector<double> reals;
  std::vector<std::int64_t> ints;
};
// Every dataset of the result's per-trajectory outputs, in the table's order.
std::vector<OutputDataset> output_datasets(const Plan& plan, const Result& result);

// The file `file` of the per-trajectory outputs (states.h5, indicators.h5, ...:
// the output table's rows that name it; docs/outputs.md), at `path`.
void write_records_hdf5(const std::string& path, const std::string& file, const Plan& plan, const Result& result);
// The files the result's per-trajectory outputs go into, in the table's order.
std::vector<std::string> record_files(const Result& result);
// Where each per-trajectory output can be in a run's directory (the output
// table's rows; a run writes the datasets its plan asked for): for readers of
// saved runs (arnoldweb.load).
struct OutputLocation {
  std::string output, file, group;    // e.g. "final_states", "states.h5", "final"
  std::vector<std::string> datasets;  // every dataset the row can write
  bool per_trajectory = true;         // a row per trajectory (else of picked ones: trajectories.h5)
};
std::vector<OutputLocation> output_locations();

struct RenderOptions {
  int width = 900;          // pixels
  double view_lon = 45;     // degrees: longitude of the view direction
  double view_lat = 30;     // degrees: latitude of the view direction
  std::string title;        // first line at the top
  std::string caption;      // small line at the bottom
  int resonance_order = 0;  // draw and label the circles m.P = 0 with max |m_i| <= this (0: none)
  // if not empty (and resonance_order > 0): draw these circles m.V = 0 instead, the harmonics of the
  // scene's model (docs/models.md)
  std::vector<std::array<int, 3>> resonances;
};
// Orthographic view of the sphere (like the paper's figures), with colour bar.
void render_sphere_png(const std::string& path, const std::vector<std::uint64_t>& map, int nside,
                       const RenderOptions& options);
// Mollweide full-sphere image, with colour bar.
void render_mollweide_png(const std::string& path, const std::vector<std::uint64_t>& map,
                          int nside, const RenderOptions& options);

// A figure of several runs of one scene: the main run's sphere with the zoom
// regions of its panels marked, and each panel's zoom beside it (the paper's
// Figures 2 and 3).
struct FigurePanel {
  std::string name, title;
  const Plan* plan = nullptr;
  const Result* result = nullptr;
};
void render_figure_png(const std::string& path, const Plan& plan, const Result& result,
                       const std::vector<FigurePanel>& panels, const RenderOptions& options);

// Writes figure.png for a run and its panels into `dir` (nothing if the build
// has no pictures or the scene none); returns the path written, or "".
std::string write_figure(const std::string& dir, const Plan& plan, const Result& result,
                         const std::vector<FigurePanel>& panels);

// The maps of an output directory written earlier, read back from its
// summary.json and map.h5 (docs/outputs.md).
struct SavedMaps {
  std::string summary_file, map_file;     // <dir>/summary.json, <dir>/map.h5
  std::uint64_t trajectories = 0, binned = 0;  // from summary.json
  std::optional<std::uint64_t> seed;     // the run's ensemble.seed (absent: not recorded)
  int nside = 0;                          // of map and frames (0: the run made no velocity map)
  std::vector<std::uint64_t> map;         // RING order, 12 nside^2 counts (all frames)
  std::vector<std::vector<std::uint64_t>> frames;  // one map per frame (observe.frames)
  int zoom_resolution = 0;                // R (0: no zoom)
  std::vector<std::uint64_t> zoom;        // R x R counts, row y then column x
  std::string note;                       // "" or a note for the user (an older directory: files unchecked)
};
// SavedRunError (exit 2) naming the directory or the file that is missing, not
// a plain file, damaged (its size or digest is not what summary.json records)
// or inconsistent (a map of another shape than summary.json declares;
// docs/reliability.md). A run with a zoom but no velocity map gives an empty
// map, one without either has no map.h5 (an error).
SavedMaps read_saved_maps(const std::string& dir);

// <dir>/summary.json, read and checked as every reader of saved runs does
// (a plain file, a JSON object of the form arnoldweb writes): its text.
// SavedRunError otherwise.
std::string read_saved_summary(const std::string& dir);

// The bytes of the file `name` of an output directory (e.g. "states.h5",
// "panel-a/summary.json"), read as every reader of saved runs reads them: a
// plain file with the size and digest its summary.json records (an older
// directory without digests: read unchecked). SavedRunError otherwise.
std::string read_saved_file(const std::string& dir, const std::string& name);

// The same for an HDF5 file of the directory (states.h5, indicators.h5,
// ...), whose bytes are then also checked by the HDF5 reader's policy
// (docs/reliability.md, "Reading HDF5 files": nothing that leads out of the
// file, every dataset's data in it), for readers such as h5py.
std::string read_saved_hdf5_file(const std::string& dir, const std::string& name);

// What continuing the finished run in `dir` adds to its scene
// (`arnoldweb continue`, Python's continue_run).
struct ContinueArgs {
  double duration = 0;                    // T more (--for)
  std::vector<std::string> sets;          // the caller's "key=value", keys of continue_keys() only
  std::vector<std::string> set_labels;    // how each was given ("" : "--set <text>")
  std::optional<std::string> out;         // output.dir
  bool out_beside = false;                // without `out`: output.dir = DIR-to-<end time> (the CLI)
  std::optional<std::string> device;      // run.device
};
// The keys a continuation may set (with everything under each): those that
// leave the trajectories as the run would have made them (docs/cluster.md,
// "Continuing a finished run").
const std::vector<std::string>& continue_keys();

// The run's scene as it ran (summary.json's scene_toml) and the overrides, in
// order, that start its trajectories from the final states, windings and time
// of its states.h5 and run them `args.duration` T more, then the caller's. Each
// value is passed as a TOML value of its own (a directory named '"q" #' is
// that directory), never spliced into TOML text. states.h5 is checked against
// the size and digest summary.json records when it is read (read_state_file).
// SavedRunError naming summary.json or states.h5 for a directory that is not
// a finished run or kept no final states; SceneError for a set of a key that
// changes the trajectories, or of run.duration (that is `duration`).
struct Continuation {
  std::string scene_toml;
  std::string source;     // <dir>/summary.json, the scene's name in messages
  double end_time = 0;    // when the run ended, in T
  std::vector<std::string> overrides, labels;  // labels: how each override was given
};
Continuation continuation_of(const std::string& dir, const ContinueArgs& args);

// Draws the pictures of an output directory written earlier (from its
// summary.json and map.h5; e.g. a GPU node's run, on a machine with cairo),
// its panels' and figure.png. Returns the paths written.
std::vector<std::string> render_saved(const std::string& dir);

}  // namespace arnoldweb
