// arnoldweb: THE OUTPUT TABLE of per-trajectory outputs. One row per output
// that a kernel writes for every trajectory (its state, its indicators, ...):
// its name, its slot in the trajectory's records (lib/device/aw_params.h:
// AW_OUT_*), the feature bit that asks for it, its columns of reals and of
// integers, how chunks fold (concatenated in trajectory order: every row) and
// how it is written (file, group, datasets). Everything downstream loops over
// the rows: the planner lays the columns out (lay_out_records), the backends
// allocate and read back two record arenas whatever the outputs, the reduction
// and the MPI messages carry those arenas, Result splits them into one Records
// per row, and the writers, the digests in summary.json and Python follow.
//
// Adding a per-trajectory output: a slot in aw_params.h, the device code that
// writes aw_record_r/aw_record_i(out, ip, slot, rec) (an effect header and its
// hook), and a row here (docs/design.md, "How to add an output").
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "params/kernel_params.hpp"

namespace arnoldweb::detail {

// One HDF5 dataset made of some of a row's columns.
struct RecordDataset {
  std::string name;           // within the row's group
  bool integers = false;      // columns of the integer record (else of the real record)
  int first = 0, count = 1;   // its columns: [first, first + count); count 1 gives a 1-d dataset
  std::string meaning;        // its "meaning" attribute ("": none)
  std::uint32_t feature = 0;  // written only when the kernel has this bit as well (0: always)
  // 2 pi (winding + turns): real columns [first, first + count) with integer
  // columns [0, count) (an unwrapped position in radians)
  bool unwrapped = false;
};

struct RecordOutput {
  std::string name;           // Result::records_of, summary.json "digests", Python
  int slot = 0;               // AW_OUT_* (aw_params.h)
  std::uint32_t feature = 0;  // the kernel writes it when its features have this bit
  int reals = 0, ints = 0;    // columns per trajectory
  std::string file;           // the output file it is written into ...
  std::string group;          // ... under this group ("": the file's root)
  // Its datasets take the grid's shape ([n2][n1]) when the initial states are a
  // lonlat or plane grid (ensemble.initial = "grid"), and its file describes the grid.
  bool grid_shaped = false;
  std::vector<RecordDataset> datasets;
  std::string meaning;        // one line, for docs and `arnoldweb outputs`
  // attributes of the file's root taken from the plan ("duration", "tangent_initial")
  std::vector<std::string> attributes = {};
  // Kept between launches only (checkpoints), never a result: no file.
  bool internal() const { return file.empty(); }
};

const std::vector<RecordOutput>& record_outputs();
// The row of a name, or nullptr.
const RecordOutput* find_record_output(const std::string& name);
// The rows a kernel with these features writes, in table order.
std::vector<const RecordOutput*> records_written(std::uint32_t features);
// Those of them that are results (not internal).
std::vector<const RecordOutput*> records_reported(std::uint32_t features);
// Lays those rows' columns out in the integer parameters (rec_reals, rec_ints,
// rec_col_r, rec_col_i): one row after the other, in table order.
void lay_out_records(std::uint32_t features, IntParams& ip);

}  // namespace arnoldweb::detail
