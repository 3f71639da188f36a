// arnoldweb: a scene is one experiment, written in TOML (docs/scenes.md).
// load_scene() validates every key and value and throws SceneError naming the
// file, line, column and key of the first problem.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "arnoldweb/precision.hpp"

namespace arnoldweb {

// Where a key was written (for messages about values that are only found to be
// wrong later, e.g. by the planner). line 0: not in the file (a default, or
// a --set override: then set_index says which).
struct SourcePos {
  int line = 0;
  int column = 0;
  int set_index = 0;  // 1-based index into Scene::overrides if --set gave the value
};

// How integrator.step = "auto" was resolved (resolve_step, accuracy.hpp): the
// scene then holds the chosen method and step, so that the scene as run
// reproduces the run without a pilot, and this record says how they were chosen.
struct AutoStep {
  bool used = false;               // the scene asked for step = "auto"
  double tolerance = 0;            // integrator.tolerance: target max|dE|
  double safety = 0;               // the pilot's max|dE| x safety <= tolerance
  bool method_chosen = false;      // the pilot chose the method too (integrator.method not written)
  std::string method;              // the method chosen (or written)
  double step = 0;                 // the step chosen, in T
  double predicted_max = 0;        // pilot max|dE| predicted by the fit at that step
  double pilot_max = -1;           // measured at that method and step on the pilot ensemble
  double pilot_median = -1;
  std::uint64_t pilot_trajectories = 0;
  double pilot_duration = 0;       // in T
  std::string pilot_device;        // where the pilot ran
  double pilot_seconds = 0;
};

struct Scene {
  // [model]
  double energy = 15.0;  // E; effective perturbation 2/E
  // model.kind and the values of its parameters' keys as written (the models'
  // descriptors declare them: lib/src/physics/models/<name>.cpp; a key not
  // written takes its default): "model.epsilon" -> {0.01}, "model.harmonics"
  // -> the rows [kx, ky, kz, c, phi] one after the other, ...
  std::string model_kind = "seibert2011";
  std::map<std::string, std::vector<double>> model_values;
  // model.kind = "expression" (docs/models.md, "Expression models"): V over x, y, z
  // and its named parameters (sorted by name, as TOML tables read)
  std::string model_potential;
  std::vector<std::pair<std::string, double>> model_parameters;

  // [ensemble]
  std::uint64_t trajectories = 100000;
  std::uint64_t seed = 1;
  std::string initial = "shell";
  std::uint64_t chunk = 0;  // trajectories per launch; 0 = chosen by the runner
  // Parameters of the non-uniform initial kinds (directions as longitude and
  // latitude of the momentum in degrees: P ~ (cos lat cos lon, cos lat sin lon, sin lat)).
  std::array<double, 2> cap_center = {45.0, 0.0};  // ensemble.cap.center
  double cap_radius = 5.0;                          // ensemble.cap.radius, degrees
  std::array<double, 2> box_lon = {40.0, 50.0};    // ensemble.box.lon, degrees
  std::array<double, 2> box_lat = {-5.0, 5.0};     // ensemble.box.lat, degrees
  std::array<double, 2> gaussian_mean = {0.0, 0.0};     // ensemble.gaussian.mean (p_x, p_y)
  std::array<double, 2> gaussian_sigma = {0.01, 0.01};  // ensemble.gaussian.sigma
  // ensemble.file: the HDF5 file of the states for ensemble.initial = "file"
  // (states.hpp; relative to the current directory); "" when none
  std::string initial_file;

  // [integrator]
  std::string method = "yoshida6a";
  double step = 0.01;         // in units of T = 2 pi; ignored when step_auto
  bool step_auto = false;     // integrator.step = "auto"
  double tolerance = 1e-8;    // target max |dE| for "auto"
  Precision precision = Precision::Double;
  MathMode math = MathMode::Portable;
  bool allow_unsafe_step = false;  // override of the step-size guard

  // [run]
  double average = 50.0;   // averaging window dt, in T
  double duration = 50.0;  // propagation time t_p, in T
  double slice = 0.0;      // run.slice: time slices of long trajectories, in T (0: none)
  std::string device = "auto";
  // run.checkpoint_every: wall-clock seconds between checkpoints; 0: "off";
  // -1: "auto" (on, every 10 min, for runs estimated above an hour)
  double checkpoint_every = -1;

  // [observe]
  bool velocity_map = true;
  int nside = 64;
  bool energy_error = true;
  double energy_every = 1.0;  // sample interval of |dE|, in T
  std::optional<double> max_energy_error;
  // The output table's switches set true (their keys, "observe.<name>"): each
  // row of lib/src/output_table/output_table.cpp declares its own; `arnoldweb
  // keys` lists them. No field here per output.
  std::set<std::string> switches;
  bool observes(const std::string& key) const { return switches.count(key) > 0; }
  // The values of the output table's table keys and direction keys as written (a dotted sub-key,
  // "observe.trajectories.ids" -> its numbers; a sub-key not written takes its
  // row's default): each row declares its own (KeyTable). No field here per output.
  std::map<std::string, std::vector<double>> output_values;
  // A sub-key's values: as written, else its row's default (none: not set, or no such key);
  // a table key's: {1} when switched on, none when off; a direction key's: as written, else its default.
  std::vector<double> output_value(const std::string& key) const;
  bool initial_states = false;
  bool final_states = false;
  // observe.zoom: an R x R histogram of a square region in gnomonic projection
  bool zoom = false;
  std::array<double, 2> zoom_center = {45.0, 0.0};  // lon, lat in degrees
  double zoom_width = 10.0;                          // full width, degrees
  int zoom_resolution = 512;
  // observe.confine: only trajectories whose momentum stays in this square count
  bool confine = false;
  std::array<double, 2> confine_center = {45.0, 0.0};
  double confine_width = 10.0;
  // observe.frames: one map per span [t_k, t_k+1) of window start times, in T
  std::vector<double> frame_times;

  // Grids of initial conditions (ensemble.initial = "grid"; chaos indicators'
  // switches and their initial tangent vector, observe.tangent_initial, are
  // the indicators row's: Scene::switches and Scene::output_values).
  std::string grid_kind = "healpix";                // ensemble.grid.kind: healpix, lonlat, plane
  int grid_nside = 16;                              // ensemble.grid.nside (healpix)
  std::array<double, 2> grid_resolution = {64, 64}; // ensemble.grid.resolution (lonlat, plane)
  std::array<double, 2> grid_range1 = {-0.5, 1.5};  // ensemble.grid.range1 (plane: first momentum)
  std::array<double, 2> grid_range2 = {-0.5, 1.5};  // ensemble.grid.range2 (plane: second momentum)
  std::array<double, 2> grid_axes = {0, 1};         // ensemble.grid.axes (plane: which momenta, 0-based)
  double grid_fixed = 0.0;                          // ensemble.grid.fixed (plane: the third momentum)
  std::vector<double> grid_position = {0.0, 0.0, 0.0};  // ensemble.grid.position, radians


  // [output]
  std::string output_dir = "out";
  bool images = true;
  // output.formats: the map's files, "hdf5" (map.h5, always) and "fits" (map.fits)
  std::vector<std::string> formats{"hdf5"};
  bool writes_format(const std::string& f) const;

  // [[panel]]: further runs of the same scene with overrides, drawn as insets
  // of one figure (e.g. the zooms (b), (c) of the paper's Figure 2).
  struct Panel {
    std::string name;               // [a-z0-9_-]+, names the panel's output folder
    std::string title;
    std::vector<std::string> sets;  // --set style overrides applied to this scene
    std::vector<std::string> set_origins;  // where each was written: "file:line:col"
  };
  std::vector<Panel> panels;

  // Provenance
  AutoStep auto_step;                      // how "auto" was resolved (resolve_step), if it was
  std::string file;                        // path it was read from ("<string>" if none)
  std::string text;                        // the TOML text it was read from (panels re-read it)
  std::map<std::string, SourcePos> where;  // dotted key -> position in the file
  std::vector<std::string> overrides;      // --set key=value, in order
  // How each override was given, for messages ("--out res", "--device gpu");
  // "" (or missing): "--set key=value".
  std::vector<std::string> override_labels;

  // The scene as run, as TOML (every key, defaults included).
  std::string to_toml() const;
  // The same as JSON (the echo in summary.json): derived from to_toml().
  std::string to_json() const;
  // Position of a dotted key, for messages ({0, 0} for defaults).
  SourcePos pos(const std::string& key) const;
  // Where a key's value came from, for messages: "scene.toml:7:9",
  // "--set integrator.step=0.005" or "default".
  std::string origin(const std::string& key) const;
};

// Read and validate a scene file; apply `overrides` ("key=value", value in TOML
// syntax or a bare string) on top. Throws SceneError.
// `labels` (parallel to overrides, optional) say how each was given, for
// messages: e.g. "--out res" for the override "output.dir=res".
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {},
                 const std::vector<std::string>& labels = {});

// The same from text (file is the name used in messages).
Scene parse_scene(const std::string& text, const std::string& file,
                  const std::vector<std::string>& overrides = {},
                  const std::vector<std::string>& labels = {});

// The override that gives the string key `key` the text `value` as it is:
// written as a TOML string of its own, never read as TOML, so that `--out
// '"q" #'` is the directory named that and not q (--out, --device, what
// `continue` and `resume` add, a panel's directory). SceneError naming `label`
// (how the value was given, e.g. "--out <value>") for a value that is not
// UTF-8, which no scene (TOML text) can hold.
std::string string_override(const std::string& key, const std::string& value, const std::string& label);

// run.device (docs/cluster.md): "auto", "all", one device id or a list of ids
// separated by commas ("cuda:0,cuda:1"). The entries of a value as written: a
// list's ids in order, any other value on its own.
std::vector<std::string> device_entries(const std::string& device);
// Whether `id` is one device id: "cpu", "opencl:N" or "cuda:N" (N in decimal
// without a leading zero, as `arnoldweb devices` lists it).
bool is_device_id(const std::string& id);
// The first id that a list names twice, or "".
std::string repeated_device(const std::string& device);

// All keys a scene may contain, with their type and allowed values, for docs
// and `arnoldweb check`.
struct SceneKey {
  std::string key, type, allowed, default_value, meaning;
};
const std::vector<SceneKey>& scene_keys();
// The key table as Markdown: the list in docs/scenes.md, which is generated
// from it (`arnoldweb keys --markdown`; a test fails when the page is stale).
std::string scene_keys_markdown();

}  // namespace arnoldweb
