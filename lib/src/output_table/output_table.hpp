// arnoldweb: THE OUTPUT TABLE of per-trajectory outputs. One row per output
// that a kernel writes for every trajectory (its state, its indicators, ...):
// its name, its slot in the trajectory's records (AW_OUT_*, declared in its
// effect header lib/device/effects/aw_fx_<name>.h), the feature bit that asks for it, its columns of reals and of
// integers, how chunks fold (concatenated in trajectory order: every row) and
// how it is written (file, group, datasets). Everything downstream loops over
// the rows: the planner lays the columns out (lay_out_records), the backends
// allocate and read back two record arenas whatever the outputs, the reduction
// and the MPI messages carry those arenas, Result splits them into one Records
// per row, and the writers, the digests in summary.json and Python follow.
//
// A row also declares the scene keys that ask for it (switches, and table keys
// with their sub-keys, checks, parameters and data: the scene layer's key
// table takes them from here, the planner's features, checks and parameters
// follow them), per dataset the picture a grid scene draws of it, and the
// pictures drawn of its records (rows of the pictures plugin's picture table).
// This table sits below the scene (docs/design.md, "Layers") so that the
// scene's keys can come from it.
//
// Adding a per-trajectory output: its effect header (its bit, slot, sizes and
// parameters declared there, and the hook that writes aw_record_r/aw_record_i(out,
// ip, slot, rec)), a row here, and its picture (function and registered row) if
// it draws one (docs/design.md, "A per-trajectory output").
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "params/kernel_params.hpp"

namespace arnoldweb::detail {

// Columns per trajectory of a row: a number, or one the plan decides (from its
// integer parameters: e.g. one action vector per sample time).
using Width = std::function<int(const IntParams& ip)>;
// The shape of a picked row's records (RecordOutput::picked), from the plan.
using Shape = std::function<std::vector<std::uint64_t>(const IntParams& ip)>;
inline Width fixed(int n) {
  return [n](const IntParams&) { return n; };
}

// One HDF5 dataset made of some of a row's columns.
struct RecordDataset {
  std::string name;           // within the row's group
  bool integers = false;      // columns of the integer record (else of the real record)
  int first = 0, count = 1;   // its columns: [first, first + count); count 1 gives a 1-d dataset; -1: to the row's end
  std::string meaning;        // its "meaning" attribute ("": none)
  std::uint32_t feature = 0;  // written only when the kernel has this bit as well (0: always)
  // 2 pi (winding + turns): real columns [first, first + count) with integer
  // columns [0, count) (an unwrapped position in radians)
  bool unwrapped = false;
  bool log10 = false;  // the decimal logarithm of the values (0: -inf)
  int group = 0;       // > 1: the columns grouped by this many (a dataset of shape (n, columns / group, group))
  // Over a grid of initial conditions (ensemble.initial = "grid"): the picture
  // file that draws this dataset (a 1-d one) and its colour bar's label ("": none).
  std::string picture = {}, picture_label = {};
};

// A boolean scene key that asks for a row (or some of its datasets): set true,
// it adds its effect's bit and the bits that effect needs to the kernel's
// features (lib/src/plan/effects.cpp; the effect is named after the key:
// "observe.<name>" is effect "<name>"). The scene keeps it in Scene::switches;
// the key table (lib/src/scene/keys.cpp) reads, writes and documents it from here.
struct OutputSwitch {
  std::string key;            // "observe.<name>"
  std::uint32_t bit = 0;      // its effect's AW_F_* bit
  std::uint32_t needs = 0;    // AW_F_* bits of the effects it needs as well
  std::string meaning;        // `arnoldweb keys`, docs/scenes.md
  std::string effect() const { return key.substr(key.find('.') + 1); }
};

// The values of the output table's table keys as a scene keeps them
// (Scene::output_values): a dotted sub-key ("observe.trajectories.ids") -> its
// numbers (integers held exactly), for the sub-keys written only.
using KeyValues = std::map<std::string, std::vector<double>>;

// The allowed values of a direction (TableSubKey::Kind::Direction, DirectionKey):
// normalised by its length, whose square must neither overflow nor underflow.
constexpr const char* kDirectionRange = "largest absolute component from 1e-150 to 1e150";

// One sub-key of a table key (KeyTable): its value is a number or an array.
struct TableSubKey {
  // Direction: an array of 3 floats, a direction (the key table's read_direction)
  enum class Kind { Integer, Real, Integers, Direction };
  std::string name;  // after the table's key: "ids" is "observe.trajectories.ids"
  Kind kind = Kind::Real;
  std::string allowed;  // as the docs show it
  std::string must;     // completes "must be ..." in a reading error
  // what is accepted when read (a number: one value); a failure names the key and `must`
  std::function<bool(const std::vector<double>&)> ok;
  std::string meaning;
  // its value when not written; none: not set, and writing it switches the table on
  std::vector<double> default_value = {};
  // a sample interval, in T: the schedule's segment is the shortest of them (and of the
  // scene's own), and each is a whole number of segments (KeyPlan::strides)
  bool interval = false;
  // taken (in the table's value, as a sample interval) only where this sub-key's value is not 0 ("": always)
  std::string only_with = {};
};

// What a table key's checks and parameters take from the plan: the schedule,
// and the planner's exact ratio of durations (0: not a whole number >= 1) and
// its number formats for messages.
struct KeyPlan {
  std::uint64_t trajectories = 0;
  double duration = 0;    // run.duration, T
  double interval = 0;    // the shortest sample interval, T
  double start_time = 0;  // the run's first time, T (a state file's time)
  std::int64_t (*ratio)(double x, double unit) = nullptr;
  std::string (*number)(double v) = nullptr;
  std::string (*count)(std::uint64_t n) = nullptr;
  std::int64_t slices = 1;          // time slices per trajectory (run.slice) ...
  std::int64_t slice_segments = 0;  // ... and the segments of one
  double slice = 0;                 // run.slice, T
  // segments between two samples of each sample interval (TableSubKey::interval), by
  // dotted sub-key ("observe.<name>.every"); 1 where it is not taken
  std::map<std::string, std::int64_t> strides = {};
  std::int64_t segments = 0;  // segments of the whole run (run.duration / interval)
  std::int64_t stride(const std::string& key) const {
    const auto it = strides.find(key);
    return it == strides.end() ? 1 : it->second;
  }
};

// A key's value refused together with the plan: the key named, and why.
struct KeyProblem {
  std::string key;  // "": none
  std::string message;
};

// A dataset or attribute a table key writes into its row's group, from its values
// and the plan (the picked trajectories' ids and sample times).
struct KeyData {
  std::string name;
  bool dataset = false;  // a dataset (with `meaning`), else a scalar attribute of reals[0] (of ints[0] if any)
  std::vector<double> reals = {};
  std::vector<std::int64_t> ints = {};  // an integer dataset or attribute when not empty
  std::string meaning = {};
};

// A table-valued scene key that asks for a row: `key = { sub = ..., ... }` or
// false. The scene keeps its sub-keys' values in Scene::output_values (no field
// per output); the key table (lib/src/scene/keys.cpp) reads, writes and
// documents them from here, the effect table names its effect after the key,
// the planner checks them against the schedule (`check`) and fills the
// kernels' parameters (`fill`), the writer adds `data` to the row's group,
// `continue` may set it, and the accuracy pilot turns it off.
struct KeyTable {
  using Values = KeyValues;
  std::string key;          // "observe.<name>"
  std::uint32_t bit = 0;    // its effect's AW_F_* bit
  std::uint32_t needs = 0;  // AW_F_* bits of the effects it needs as well
  std::string allowed, must, meaning;  // of the table key itself, as for a sub-key
  std::vector<TableSubKey> keys;
  std::function<KeyProblem(const KeyTable& t, const Values& v, const KeyPlan& p)> check = nullptr;
  // always called (off too: a parameter's neutral value)
  std::function<void(const KeyTable& t, const Values& v, const KeyPlan& p, IntParams& ip)> fill = nullptr;
  std::function<std::vector<KeyData>(const KeyTable& t, const Values& v, const KeyPlan& p, const IntParams& ip)> data =
      nullptr;
  // true (or a table) switches it on with every sub-key at its default: kept as the
  // key's own entry in Scene::output_values; else only a sub-key without a default does
  bool true_switches_on = false;
  // the kernels' real parameters, when switched on
  std::function<void(const KeyTable& t, const Values& v, const KeyPlan& p, RealParams& rp)> fill_reals = nullptr;

  std::string effect() const { return key.substr(key.find('.') + 1); }
  std::string sub(const std::string& name) const { return key + "." + name; }
  // on: switched on by true (true_switches_on), or a sub-key without a default is written
  bool on(const Values& v) const;
  // a sub-key is taken: it has no `only_with`, or that sub-key's value is not 0
  bool taken(const Values& v, const TableSubKey& k) const;
  // a sub-key's values: as written, else its default
  std::vector<double> value(const Values& v, const std::string& name) const;
  bool written(const Values& v, const std::string& name) const { return v.count(sub(name)) > 0; }
};

// A direction-valued scene key that parametrises a row's effect, neither a
// switch nor a table: `observe.tangent_initial = [6 floats]`, normalised by its
// length. The scene keeps it in Scene::output_values under its key when written
// (else `default_value` holds); the key table (lib/src/scene/keys.cpp) reads,
// writes and documents it from here (kDirectionRange), `continue` may set it,
// the planner fills the kernels' real parameters from its value (`fill_reals`,
// always: neutral where the row is off), and the writer makes it an attribute
// of the row's file named after the key's last part ("tangent_initial").
struct DirectionKey {
  std::string key;  // "observe.<name>"
  std::size_t count = 3;  // its components
  std::vector<double> default_value;
  std::string meaning;
  std::function<void(const std::vector<double>& v, RealParams& rp)> fill_reals = nullptr;
  std::string name() const { return key.substr(key.find('.') + 1); }
  // its value in a scene's output values: as written, else its default
  const std::vector<double>& value(const KeyValues& v) const;
};

struct RecordOutput {
  std::string name;           // Result::records_of, summary.json "digests", Python
  int slot = 0;               // AW_OUT_* (its effect header's declarations)
  std::uint32_t feature = 0;  // the kernel writes it when its features have this bit
  Width reals, ints;          // columns per trajectory
  std::string file;           // the output file it is written into ...
  std::string group;          // ... under this group ("": the file's root)
  // Its datasets take the grid's shape ([n2][n1]) when the initial states are a
  // lonlat or plane grid (ensemble.initial = "grid"), and its file describes the grid.
  bool grid_shaped = false;
  std::vector<RecordDataset> datasets;
  std::string meaning;        // one line, for docs and `arnoldweb outputs`
  // attributes of the file's root taken from the plan ("duration"; its direction keys follow)
  std::vector<std::string> attributes = {};
  std::vector<OutputSwitch> switches = {};  // the boolean keys that ask for it
  std::vector<KeyTable> tables = {};        // the table keys that ask for it
  // Picked (not per trajectory): records of a few chosen trajectories, `shape`
  // of them (e.g. picks x samples), `reals` and `ints` columns each, in the
  // histogram buffer after the maps (effects/aw_fx_trajectories.h, "Picked records"): their
  // memory is the picks', not the ensemble's, and they take no columns of the
  // trajectories' records. Their datasets have the records' shape.
  Shape picked = nullptr;
  // The pictures drawn of its records: names of rows of the pictures plugin's
  // picture table (lib/src/pictures/picture_table.hpp: rows registered beside their functions).
  std::vector<std::string> pictures = {};
  std::vector<DirectionKey> directions = {};  // the direction keys that parametrise it
  // Kept between launches only (checkpoints), never a result: no file.
  bool internal() const { return file.empty(); }
};

const std::vector<RecordOutput>& record_outputs();
// Every row's switches, in table order.
std::vector<const OutputSwitch*> output_switches();
// Every row's table keys, in table order.
std::vector<const KeyTable*> key_tables();
// Every row's direction keys, in table order; one by its key ("observe.<name>"), or nullptr.
std::vector<const DirectionKey*> direction_keys();
const DirectionKey* find_direction_key(const std::string& key);
// The AW_F_* bits the switches set true (their keys in `on`) and the table keys
// switched on (their values) ask for.
std::uint32_t switch_features(const std::set<std::string>& on, const KeyValues& values);
// The sample intervals of the table keys switched on (TableSubKey::interval),
// where taken, in table order: each dotted sub-key and its value in T.
std::vector<std::pair<std::string, double>> sample_intervals(const KeyValues& values);
// The row of a name, or nullptr.
const RecordOutput* find_record_output(const std::string& name);
// The rows a kernel with these features writes, in table order.
std::vector<const RecordOutput*> records_written(std::uint32_t features);
// Those of them that are results (not internal).
std::vector<const RecordOutput*> records_reported(std::uint32_t features);
// Lays those rows' columns out in the integer parameters (rec_reals, rec_ints,
// rec_col_r, rec_col_i, rec_width_r, rec_width_i): one row after the other, in
// table order. The widths may depend on the other integer parameters: fill them first.
void lay_out_records(std::uint32_t features, IntParams& ip);
// The picked rows' records (RecordOutput::picked) of a kernel with these
// features and their 32-bit words in the histogram buffer: they start at the
// even word at or after `hist_words` (ip.pick_base); returns the buffer's new
// size in words. (One picked row at a time: the device reads one ip.pick_base.)
std::uint64_t picked_records(const RecordOutput& row, const IntParams& ip);
std::uint64_t lay_out_picked(std::uint32_t features, std::uint64_t hist_words, IntParams& ip);

}  // namespace arnoldweb::detail
