// arnoldweb: reading a state file (states.hpp; the schema: docs/outputs.md,
// "State files"). The group read is the root, or /final when the root has no
// momentum dataset (a states.h5 as arnoldweb wrote it). Datasets are read
// whole, converted by HDF5 to double (floating-point datasets) or int64
// (integer ones); the rules on their values are those of states/state_rules.hpp.
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/states.hpp"
#include "os/regular_file.hpp"
#include "output/hdf5_handle.hpp"
#include "states/state_rules.hpp"

namespace arnoldweb {
namespace {

class StateFile {
 public:
  explicit StateFile(const std::string& path) : path_(path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not prints
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) fail("", -1, "no such file (ensemble.file names an HDF5 file of states)");
    // a FIFO, a device or a file of /proc is refused before HDF5 opens it (and blocks)
    if (const std::string why = detail::plain_file_problem(path); !why.empty()) fail("", -1, why);
    if (H5Fis_hdf5(path.c_str()) <= 0) fail("", -1, "not an HDF5 file (docs/outputs.md, \"State files\")");
    file_.id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file_.id < 0) fail("", -1, "cannot open it as an HDF5 file");
    group_ = has("/momentum") ? "/" : has("/final/momentum") ? "/final/" : "";
    if (group_.empty())
      fail("", -1,
           "no momentum dataset: a state file has /momentum (N x 3) beside /position or /position_turns, or is a "
           "states.h5 with /final (docs/outputs.md, \"State files\")");
  }

  std::string group() const { return group_ == "/" ? "/" : "/final"; }
  std::string name(const std::string& leaf) const { return group_ + leaf; }
  bool has(const std::string& path) const {
    // each parent must exist before H5Lexists may be asked about a child
    std::size_t at = 1;
    for (;;) {
      const std::size_t slash = path.find('/', at);
      if (H5Lexists(file_.id, path.substr(0, slash).c_str(), H5P_DEFAULT) <= 0) return false;
      if (slash == std::string::npos) return true;
      at = slash + 1;
    }
  }

  // A dataset of `columns` values per row (rank 2) or one (columns 0: rank 1), of `type_class`.
  template <class T>
  std::vector<T> rows(const std::string& leaf, int columns, H5T_class_t type_class, hid_t memory_type,
                      std::uint64_t& count) {
    const std::string n = name(leaf);
    const H5Handle d{H5Dopen2(file_.id, n.c_str(), H5P_DEFAULT), H5Dclose};
    if (d.id < 0) fail(n, -1, "cannot open it as a dataset");
    const H5Handle type{H5Dget_type(d.id), H5Tclose};
    if (H5Tget_class(type.id) != type_class)
      fail(n, -1, type_class == H5T_FLOAT ? "must hold floating-point numbers (float64 or float32)"
                                          : "must hold integers (int64 or another integer type)");
    // a damaged type of gigabytes per value would have the conversion allocate that much
    if (H5Tget_size(type.id) == 0 || H5Tget_size(type.id) > 8)
      fail(n, -1, "stores values of " + std::to_string(H5Tget_size(type.id)) + " bytes; at most 8 (a damaged file?)");
    const H5Handle space{H5Dget_space(d.id), H5Sclose};
    const int rank = H5Sget_simple_extent_ndims(space.id);
    hsize_t dims[2] = {0, 0};
    if (rank >= 1 && rank <= 2) H5Sget_simple_extent_dims(space.id, dims, nullptr);
    const bool ok = columns ? rank == 2 && dims[1] == static_cast<hsize_t>(columns) : rank == 1;
    if (!ok)
      fail(n, -1, "has the shape " + shape(rank, dims) + "; it must be " + (columns ? "(N, 3)" : "(N,)") +
                      ", one row per state");
    count = dims[0];
    if (count == 0) fail(n, -1, "holds no states (N = 0)");
    if (count > kMaxStateRows) fail(n, -1, "holds " + std::to_string(count) + " states, more than ensemble.trajectories allows (1e13)");
    std::vector<T> v;
    try {
      v.resize(static_cast<std::size_t>(count) * static_cast<std::size_t>(columns ? columns : 1));
    } catch (const std::bad_alloc&) {
      fail(n, -1, "does not fit this process's memory");
    }
    if (H5Dread(d.id, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
      fail(n, -1, "cannot be read (a damaged file, or values that do not convert)");
    return v;
  }

  // An attribute of the group or of a dataset (where = "" for the group).
  bool has_attribute(const std::string& where, const char* attr) const {
    const std::string object = where.empty() ? group() : name(where);
    return H5Aexists_by_name(file_.id, object.c_str(), attr, H5P_DEFAULT) > 0;
  }
  std::string text_attribute(const std::string& where, const char* attr) {
    const std::string object = name(where);
    const H5Handle a{H5Aopen_by_name(file_.id, object.c_str(), attr, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
    const H5Handle type{a.id < 0 ? -1 : H5Aget_type(a.id), H5Tclose};
    if (a.id < 0 || H5Tget_class(type.id) != H5T_STRING) fail(object, -1, std::string("the attribute ") + attr + " must be a string");
    if (H5Tis_variable_str(type.id) > 0) {
      const H5Handle mem{H5Tcopy(H5T_C_S1), H5Tclose};
      H5Tset_size(mem.id, H5T_VARIABLE);
      char* text = nullptr;
      if (H5Aread(a.id, mem.id, &text) < 0 || !text) fail(object, -1, std::string("cannot read the attribute ") + attr);
      const std::string s = text;
      H5free_memory(text);
      return s;
    }
    const std::size_t size = H5Tget_size(type.id);
    if (size > (1u << 20)) fail(object, -1, std::string("the attribute ") + attr + " is longer than 1 MiB (a damaged file?)");
    std::string s(size, '\0');
    if (H5Aread(a.id, type.id, s.data()) < 0) fail(object, -1, std::string("cannot read the attribute ") + attr);
    s.resize(std::strlen(s.c_str()));
    return s;
  }
  double real_attribute(const char* attr) {
    const H5Handle a{H5Aopen_by_name(file_.id, group().c_str(), attr, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
    const H5Handle type{a.id < 0 ? -1 : H5Aget_type(a.id), H5Tclose};
    const H5Handle space{a.id < 0 ? -1 : H5Aget_space(a.id), H5Sclose};
    double v = 0;
    if (a.id < 0 || (H5Tget_class(type.id) != H5T_FLOAT && H5Tget_class(type.id) != H5T_INTEGER) ||
        H5Tget_size(type.id) == 0 || H5Tget_size(type.id) > 8 ||
        H5Sget_simple_extent_npoints(space.id) != 1 || H5Aread(a.id, H5T_NATIVE_DOUBLE, &v) < 0)
      fail(group(), -1, std::string("the attribute ") + attr + " must be one number");
    return v;
  }

  [[noreturn]] void fail(const std::string& dataset, std::int64_t row, const std::string& message) const {
    throw StateError(path_, dataset, row, message);
  }

 private:
  static std::string shape(int rank, const hsize_t* dims) {
    if (rank < 1 || rank > 2) return "of rank " + std::to_string(rank);
    return "(" + std::to_string(dims[0]) + (rank == 2 ? ", " + std::to_string(dims[1]) : std::string(",")) + ")";
  }
  static constexpr std::uint64_t kMaxStateRows = 10'000'000'000'000ull;

  std::string path_;
  H5Handle file_{-1, H5Fclose};
  std::string group_;
};

}  // namespace

StateSet read_state_file(const std::string& path) {
  StateFile f(path);
  StateSet s;
  s.group = f.group();
  s.source = s.group == "/" ? path : path + ":" + s.group;
  detail::StateRows rows(path);
  std::uint64_t n = 0;
  s.momentum = f.rows<double>("momentum", 3, H5T_FLOAT, H5T_NATIVE_DOUBLE, n);
  s.count = n;
  auto same_count = [&](const std::string& leaf, std::uint64_t m) {
    if (m != n)
      f.fail(f.name(leaf), -1,
             "has " + std::to_string(m) + " rows and " + f.name("momentum") + " " + std::to_string(n) + ": one row per state in each");
  };
  if (f.has(f.name("status"))) {
    s.status = f.rows<std::int64_t>("status", 0, H5T_INTEGER, H5T_NATIVE_INT64, n);
    same_count("status", n);
    rows.check_status(s, f.name("status"));
  } else {
    s.status.assign(s.count, 0);
  }
  std::vector<std::int64_t> winding;
  std::string winding_name;
  if (f.has(f.name("winding"))) {
    std::uint64_t m = 0;
    winding = f.rows<std::int64_t>("winding", 3, H5T_INTEGER, H5T_NATIVE_INT64, m);
    same_count("winding", m);
    winding_name = f.name("winding");
  }
  std::uint64_t m = 0;
  if (f.has(f.name("position_turns"))) {
    const auto u = f.rows<double>("position_turns", 3, H5T_FLOAT, H5T_NATIVE_DOUBLE, m);
    same_count("position_turns", m);
    rows.set_positions(s, u, PositionUnits::Turns, winding_name.empty() ? nullptr : &winding, f.name("position_turns"),
                       winding_name);
  } else if (f.has(f.name("position"))) {
    if (!f.has_attribute("position", "units"))
      f.fail(f.name("position"), -1,
             "needs the attribute units = \"radians\" or \"turns\" (or give position_turns, in turns)");
    const std::string units = f.text_attribute("position", "units");
    if (units != "radians" && units != "turns")
      f.fail(f.name("position"), -1, "the attribute units is \"" + units + "\"; it must be \"radians\" or \"turns\"");
    const auto x = f.rows<double>("position", 3, H5T_FLOAT, H5T_NATIVE_DOUBLE, m);
    same_count("position", m);
    rows.set_positions(s, x, units == "turns" ? PositionUnits::Turns : PositionUnits::Radians,
                       winding_name.empty() ? nullptr : &winding, f.name("position"), winding_name);
  } else {
    f.fail(f.name("position"), -1, "missing: give position (N x 3, with the attribute units) or position_turns");
  }
  rows.check_momenta(s, f.name("momentum"));
  if (f.has_attribute("", "time")) {
    s.time = f.real_attribute("time");
    s.has_time = true;
    if (!std::isfinite(s.time) || s.time < 0)
      f.fail(f.group(), -1, "the attribute time is " + detail::show_number(s.time) + "; it must be a finite time >= 0 (in T)");
  }
  return s;
}

}  // namespace arnoldweb
