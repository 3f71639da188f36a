#include "run_fields.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"

namespace arnoldweb::explorer {
namespace {

constexpr std::uint64_t kMaxValues = 1u << 22;  // a field larger than this is left out of the page

// An HDF5 file opened from bytes in memory (the core driver: nothing touches the disk).
class MemoryFile {
 public:
  MemoryFile(std::string bytes, const std::string& path) : bytes_(std::move(bytes)) {
    const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_fapl_core(fapl, 1 << 16, 0);
    H5Pset_file_image(fapl, bytes_.data(), bytes_.size());
    // the name only tells open images apart (HDF5 would hand back an open file of the same name)
    const std::string name = "explorer-image:" + path;
    H5E_BEGIN_TRY { file_ = H5Fopen(name.c_str(), H5F_ACC_RDONLY, fapl); }
    H5E_END_TRY;
    H5Pclose(fapl);
    if (file_ < 0) throw SavedRunError(path, "is not an HDF5 file HDF5 can open");
  }
  ~MemoryFile() {
    if (file_ >= 0) H5Fclose(file_);
  }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;

  // The real dataset `name` (in `group`, "" : the root) and its shape; false if absent or not real.
  bool read(const std::string& group, const std::string& name, std::vector<double>& values,
            std::vector<hsize_t>& dims) const {
    const std::string where = (group.empty() ? "/" : "/" + group + "/") + name;
    htri_t there;
    H5E_BEGIN_TRY { there = H5Lexists(file_, where.c_str(), H5P_DEFAULT) > 0 && H5Oexists_by_name(file_, where.c_str(), H5P_DEFAULT) > 0; }
    H5E_END_TRY;
    if (there <= 0) return false;
    const hid_t set = H5Dopen2(file_, where.c_str(), H5P_DEFAULT);
    if (set < 0) return false;
    const hid_t type = H5Dget_type(set), space = H5Dget_space(set);
    const bool real = H5Tget_class(type) == H5T_FLOAT;
    const int rank = H5Sget_simple_extent_ndims(space);
    bool ok = real && rank >= 1 && rank <= 3;
    if (ok) {
      dims.assign(static_cast<std::size_t>(rank), 0);
      H5Sget_simple_extent_dims(space, dims.data(), nullptr);
      hsize_t n = 1;
      for (hsize_t d : dims) n *= d;
      ok = n <= 3 * kMaxValues;
      if (ok) {
        values.resize(n);
        ok = H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0;
      }
    }
    H5Sclose(space);
    H5Tclose(type);
    H5Dclose(set);
    return ok;
  }

 private:
  std::string bytes_;
  hid_t file_ = -1;
};

nlohmann::json numbers(const std::vector<double>& v, std::size_t first = 0, std::size_t stride = 1) {
  nlohmann::json a = nlohmann::json::array();
  for (std::size_t i = first; i < v.size(); i += stride)
    if (std::isfinite(v[i])) a.push_back(v[i]);
    else a.push_back(nullptr);
  return a;
}

nlohmann::json grid_of(const Scene& s, const std::vector<hsize_t>& dims) {
  nlohmann::json g = {{"grid", s.grid_kind}};
  g["shape"] = dims;
  if (s.grid_kind == "healpix") {
    g["nside"] = s.grid_nside;
  } else if (s.grid_kind == "lonlat") {
    g["x"] = s.box_lon;
    g["y"] = s.box_lat;
    g["labels"] = {"longitude of P (deg)", "latitude of P (deg)"};
  } else {
    g["x"] = s.grid_range1;
    g["y"] = s.grid_range2;
    const char* p[] = {"p_x", "p_y", "p_z"};
    g["labels"] = {p[static_cast<int>(s.grid_axes[0]) % 3], p[static_cast<int>(s.grid_axes[1]) % 3]};
  }
  return g;
}

}  // namespace

nlohmann::json read_run_fields(const std::string& dir, const nlohmann::json& summary, const Scene& scene) {
  nlohmann::json out = nlohmann::json::object();
  const auto files = summary.value("files", nlohmann::json::array());
  const auto listed = [&](const std::string& f) {
    return std::find(files.begin(), files.end(), f) != files.end();
  };
  const std::uint64_t n = summary.value("completed", std::uint64_t{0});
  if (!n) return out;
  std::string open_name;
  std::unique_ptr<MemoryFile> file;
  for (const OutputLocation& row : output_locations()) {
    if (row.file.empty() || !row.per_trajectory || !listed(row.file)) continue;  // fields over the trajectories
    if (open_name != row.file) {
      file.reset();
      file = std::make_unique<MemoryFile>(read_saved_file(dir, row.file), dir + "/" + row.file);
      open_name = row.file;
    }
    for (const std::string& name : row.datasets) {
      std::vector<double> v;
      std::vector<hsize_t> dims;
      if (!file->read(row.group, name, v, dims)) continue;
      if (name == "nu_first" && v.size() == 3 * n) {  // the frequency map: nu_x against nu_y
        out["frequencies"] = {{"nu1", numbers(v, 0, 3)}, {"nu2", numbers(v, 1, 3)}};
      } else if (scene.initial == "grid" && v.size() == n && n <= kMaxValues && row.group.empty()) {
        nlohmann::json f = grid_of(scene, dims);
        f["output"] = row.output;
        f["values"] = numbers(v);
        out[name] = std::move(f);
      }
    }
  }
  return out;
}

}  // namespace arnoldweb::explorer
