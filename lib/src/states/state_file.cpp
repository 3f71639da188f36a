// arnoldweb: reading a state file (states.hpp; the schema: docs/outputs.md,
// "State files"). The group read is the root, or /final when the root has no
// momentum dataset (a states.h5 as arnoldweb wrote it). The file is opened
// by the one HDF5 reader (output/h5_reader.hpp: nothing outside the file is
// followed, every dataset's data is in the file), and a file that a run
// wrote is first checked against its summary.json, as `continue` checks it.
// Every dataset's shape and type are checked, and their row counts compared,
// before anything is allocated; then they are read whole, converted by HDF5
// to double (floating-point datasets) or int64 (integer ones); the rules on
// their values are those of states/state_rules.hpp.
#include <hdf5.h>

#include <cerrno>
#include <cmath>
#include <limits>
#include <optional>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/states.hpp"
#include "os/regular_file.hpp"
#include "output/h5_reader.hpp"
#include "output/saved_run.hpp"
#include "states/state_rules.hpp"

namespace arnoldweb {
namespace {

constexpr std::uint64_t kMaxStateRows = 10'000'000'000'000ull;  // ensemble.trajectories' limit

// A dataset of the schema: `columns` values per row (rank 2) or one (columns 0: rank 1).
struct Dataset {
  std::string name;
  int columns = 0;
  H5T_class_t type_class = H5T_FLOAT;
  std::optional<H5Handle> handle;
  std::uint64_t rows = 0;
  bool is_unsigned = false;  // an integer dataset of unsigned values
};

class StateFile {
 public:
  StateFile(const std::string& path, const detail::OpenPlainFile& plain)
      : path_(path), h5_(plain, path, [this](const std::string& object, const std::string& message) {
          fail(object, -1, message);
        }) {
    group_ = h5_.has("/momentum") ? "/" : h5_.has("/final/momentum") ? "/final/" : "";
    if (group_.empty())
      fail("", -1,
           "no momentum dataset: a state file has /momentum (N x 3) beside /position or /position_turns, or is a "
           "states.h5 with /final (docs/outputs.md, \"State files\")");
  }

  std::string group() const { return group_ == "/" ? "/" : "/final"; }
  std::string name(const std::string& leaf) const { return group_ + leaf; }
  bool has(const std::string& leaf) const { return h5_.has(name(leaf)); }

  // Opens `leaf` and checks its type and shape; reads nothing.
  Dataset open(const std::string& leaf, int columns, H5T_class_t type_class) const {
    Dataset d;
    d.name = name(leaf);
    d.columns = columns;
    d.type_class = type_class;
    d.handle.emplace(h5_.dataset(d.name));
    const H5Handle type{H5Dget_type(d.handle->id), H5Tclose};
    if (type.id < 0 || H5Tget_class(type.id) != type_class)
      fail(d.name, -1, type_class == H5T_FLOAT ? "must hold floating-point numbers (float64 or float32)"
                                               : "must hold integers (int64 or another integer type)");
    const std::size_t bytes = H5Tget_size(type.id);
    if (type_class == H5T_FLOAT && !ieee_float(type.id))
      fail(d.name, -1,
           "stores floating-point numbers of " + std::to_string(bytes) + " bytes" + (bytes == 2 ? " (float16)" : "") +
               "; it must hold float64 or float32 (docs/outputs.md, \"State files\")");
    // a damaged type of gigabytes per value would have the conversion allocate that much
    if (type_class == H5T_INTEGER && (bytes == 0 || bytes > 8))
      fail(d.name, -1, "stores integers of " + std::to_string(bytes) + " bytes; at most 8 (a damaged file?)");
    d.is_unsigned = type_class == H5T_INTEGER && H5Tget_sign(type.id) == H5T_SGN_NONE;
    const std::vector<hsize_t> dims = h5_.dims(d.handle->id, d.name);
    const bool ok = columns ? dims.size() == 2 && dims[1] == static_cast<hsize_t>(columns) : dims.size() == 1;
    if (!ok)
      fail(d.name, -1, "has the shape " + detail::show_shape(dims) + "; it must be " + (columns ? "(N, 3)" : "(N,)") +
                           ", one row per state");
    d.rows = dims[0];
    if (d.rows == 0) fail(d.name, -1, "holds no states (N = 0)");
    if (d.rows > kMaxStateRows)
      fail(d.name, -1, "holds " + std::to_string(d.rows) + " states, more than ensemble.trajectories allows (1e13)");
    return d;
  }

  std::vector<double> reals(const Dataset& d) const {
    std::vector<double> v = allocate<double>(d);
    if (H5Dread(d.handle->id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
      fail(d.name, -1, "cannot be read (a damaged file?)");
    return v;
  }

  // Integers as int64; unsigned ones above its range are refused by row, not clipped.
  std::vector<std::int64_t> integers(const Dataset& d) const {
    if (!d.is_unsigned) {
      std::vector<std::int64_t> v = allocate<std::int64_t>(d);
      if (H5Dread(d.handle->id, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
        fail(d.name, -1, "cannot be read (a damaged file?)");
      return v;
    }
    std::vector<std::uint64_t> u = allocate<std::uint64_t>(d);
    if (H5Dread(d.handle->id, H5T_NATIVE_UINT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, u.data()) < 0)
      fail(d.name, -1, "cannot be read (a damaged file?)");
    const std::size_t per_row = d.columns ? static_cast<std::size_t>(d.columns) : 1;
    for (std::size_t i = 0; i < u.size(); ++i)
      if (u[i] > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
        fail(d.name, static_cast<std::int64_t>(i / per_row),
             "the value " + std::to_string(u[i]) + " is out of range (a signed 64-bit integer at most)");
    return std::vector<std::int64_t>(u.begin(), u.end());
  }

  // The row counts of all datasets read are the same: momentum's.
  void same_rows(const Dataset& d, const Dataset& momentum) const {
    if (d.rows != momentum.rows)
      fail(d.name, -1,
           "has " + std::to_string(d.rows) + " rows and " + momentum.name + " " + std::to_string(momentum.rows) +
               ": one row per state in each");
  }

  bool has_group_attribute(const char* attr) const { return h5_.has_attribute(group(), attr); }
  double group_number(const char* attr) const { return h5_.number_attribute(group(), attr); }
  bool has_attribute(const Dataset& d, const char* attr) const { return h5_.has_attribute(d.name, attr); }
  std::string text_attribute(const Dataset& d, const char* attr) const { return h5_.text_attribute(d.name, attr); }

  [[noreturn]] void fail(const std::string& dataset, std::int64_t row, const std::string& message) const {
    throw StateError(path_, dataset, row, message);
  }

 private:
  static bool ieee_float(hid_t type) {
    for (hid_t t : {H5T_IEEE_F64LE, H5T_IEEE_F64BE, H5T_IEEE_F32LE, H5T_IEEE_F32BE})
      if (H5Tequal(type, t) > 0) return true;
    return false;
  }
  template <class T>
  std::vector<T> allocate(const Dataset& d) const {
    try {
      return std::vector<T>(static_cast<std::size_t>(d.rows) * static_cast<std::size_t>(d.columns ? d.columns : 1));
    } catch (const std::bad_alloc&) {
      fail(d.name, -1, "does not fit this process's memory");
    }
  }

  std::string path_;
  detail::H5File h5_;
  std::string group_;
};

// The file, open and plain (StateError otherwise), checked against the
// summary.json of the run that wrote it, if one did.
void check_file(const std::string& path, const detail::OpenPlainFile& plain) {
  if (plain.error() == ENOENT) throw StateError(path, "", -1, "no such file (ensemble.file names an HDF5 file of states)");
  // a FIFO, a device or a file of /proc is refused before HDF5 opens it (and blocks)
  if (!plain.why().empty()) throw StateError(path, "", -1, plain.why());
  detail::check_run_file(path, plain);  // a run's file that was changed says so, whatever it holds now
  if (H5Fis_hdf5(plain.name().c_str()) <= 0)
    throw StateError(path, "", -1, "not an HDF5 file (docs/outputs.md, \"State files\")");
}

// The states of the open, checked file (read_state_file reads them in a child, then here).
StateSet read_states(const std::string& path, const detail::OpenPlainFile& plain) {
  const StateFile f(path, plain);
  StateSet s;
  s.group = f.group();
  s.source = s.group == "/" ? path : path + ":" + s.group;
  // every dataset's type and shape, and their rows compared, before anything is read
  const Dataset momentum = f.open("momentum", 3, H5T_FLOAT);
  std::optional<Dataset> status, winding, position;
  if (f.has("status")) status.emplace(f.open("status", 0, H5T_INTEGER));
  if (f.has("winding")) winding.emplace(f.open("winding", 3, H5T_INTEGER));
  const bool turns = f.has("position_turns");
  if (turns)
    position.emplace(f.open("position_turns", 3, H5T_FLOAT));
  else if (f.has("position"))
    position.emplace(f.open("position", 3, H5T_FLOAT));
  else
    f.fail(f.name("position"), -1, "missing: give position (N x 3, with the attribute units) or position_turns");
  for (const std::optional<Dataset>* d : {&status, &winding, &position})
    if (*d) f.same_rows(**d, momentum);
  PositionUnits units = PositionUnits::Turns;
  if (!turns) {
    if (!f.has_attribute(*position, "units"))
      f.fail(position->name, -1, "needs the attribute units = \"radians\" or \"turns\" (or give position_turns, in turns)");
    const std::string u = f.text_attribute(*position, "units");
    if (u != "radians" && u != "turns")
      f.fail(position->name, -1, "the attribute units is \"" + u + "\"; it must be \"radians\" or \"turns\"");
    units = u == "turns" ? PositionUnits::Turns : PositionUnits::Radians;
  }

  const detail::StateRows rows(path);
  s.count = momentum.rows;
  s.momentum = f.reals(momentum);
  if (status) {
    s.status = f.integers(*status);
    rows.check_status(s, status->name);
  } else {
    s.status.assign(s.count, 0);
  }
  const std::vector<std::int64_t> windings = winding ? f.integers(*winding) : std::vector<std::int64_t>();
  rows.set_positions(s, f.reals(*position), units, winding ? &windings : nullptr, position->name,
                     winding ? winding->name : std::string());
  rows.check_momenta(s, momentum.name);
  if (f.has_group_attribute("time")) {
    s.time = f.group_number("time");
    s.has_time = true;
    if (!std::isfinite(s.time) || s.time < 0)
      f.fail(f.group(), -1, "the attribute time is " + detail::show_number(s.time) + "; it must be a finite time >= 0 (in T)");
  }
  return s;
}

}  // namespace

StateSet read_state_file(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not prints
  const detail::OpenPlainFile plain(path);
  check_file(path, plain);
  // first in a child process (os/isolated.hpp): a defect of HDF5's parser ends the child
  const detail::H5Fail fail = [&](const std::string& object, const std::string& message) {
    throw StateError(path, object, -1, message);
  };
  return detail::read_in_child_first(plain.size(), fail, [&] { return read_states(path, plain); });
}

}  // namespace arnoldweb
