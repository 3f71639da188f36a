// arnoldweb: one HDF5 file built in memory (output.hpp's writers). Internal:
// the only header of the library that includes hdf5.h.
#pragma once

#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "arnoldweb/plan.hpp"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

// One HDF5 file being built in memory (the core driver, no backing store);
// any failing call throws OutputError naming the final path. finish() returns
// the file's bytes, which the caller writes with every write checked: HDF5
// itself never touches the disk, so a full disk cannot leave it in a broken
// state. Handles are closed in reverse order, quietly, on unwinding.
class H5Writer {
 public:
  explicit H5Writer(const std::string& path) : path_(path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not prints
    hid_t fapl = keep(check(H5Pcreate(H5P_FILE_ACCESS), "file access properties"));
    check(H5Pset_fapl_core(fapl, 1 << 20, 0), "the in-memory driver");
    file_ = check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), "create the file");
  }
  ~H5Writer() {
    for (auto it = open_.rbegin(); it != open_.rend(); ++it) close_any(*it);
    if (file_ >= 0) H5Fclose(file_);
  }
  H5Writer(const H5Writer&) = delete;
  H5Writer& operator=(const H5Writer&) = delete;

  hid_t root() const { return file_; }

  hid_t group(const char* name) { return keep(check(H5Gcreate2(file_, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), name)); }

  // A dataset of `dims`, chunked when large; integer datasets (statuses,
  // windings) also shuffled and deflated.
  hid_t dataset(hid_t where, const char* name, hid_t type, const std::vector<hsize_t>& dims, const void* data) {
    hid_t space = keep(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), name));
    hid_t props = keep(check(H5Pcreate(H5P_DATASET_CREATE), name));
    hsize_t total = 1;
    for (auto d : dims) total *= d;
    if (total >= 4096) {
      std::vector<hsize_t> chunk = dims;
      chunk[0] = std::min<hsize_t>(dims[0], std::max<hsize_t>(1, 65536 / std::max<hsize_t>(1, total / dims[0])));
      check(H5Pset_chunk(props, static_cast<int>(chunk.size()), chunk.data()), name);
      // Byte shuffle and deflate (level 1) for integers only: floating-point outputs hardly
      // compress (frequencies.h5 of 1.5e6 trajectories 84 -> 75 MB, diffusion.h5 of 1024 x
      // 10,001 actions 245 -> 199 MB) and zlib took 1.2-1.5 s of such a run's 3.3 s process on
      // the H200 machine, longer than the GPU's integration (docs/outputs.md).
      if (H5Tget_class(type) == H5T_INTEGER) {
        check(H5Pset_shuffle(props), name);
        check(H5Pset_deflate(props, 1), name);
      }
    }
    hid_t set = keep(check(H5Dcreate2(where, name, type, space, H5P_DEFAULT, props, H5P_DEFAULT), name));
    if (total) check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name);
    return set;
  }

  void attr(hid_t where, const char* name, const std::string& value) {
    hid_t type = keep(check(H5Tcopy(H5T_C_S1), name));
    check(H5Tset_size(type, std::max<std::size_t>(1, value.size())), name);
    check(H5Tset_strpad(type, H5T_STR_NULLTERM), name);
    hid_t space = keep(check(H5Screate(H5S_SCALAR), name));
    hid_t a = keep(check(H5Acreate2(where, name, type, space, H5P_DEFAULT, H5P_DEFAULT), name));
    check(H5Awrite(a, type, value.c_str()), name);
  }
  void attr(hid_t where, const char* name, double value) { scalar(where, name, H5T_NATIVE_DOUBLE, &value); }
  void attr(hid_t where, const char* name, std::int64_t value) { scalar(where, name, H5T_NATIVE_INT64, &value); }
  void attr(hid_t where, const char* name, const std::vector<double>& v) {
    const hsize_t n = v.size();
    hid_t space = keep(check(H5Screate_simple(1, &n, nullptr), name));
    hid_t a = keep(check(H5Acreate2(where, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT), name));
    check(H5Awrite(a, H5T_NATIVE_DOUBLE, v.data()), name);
  }

  // Closes every object and returns the complete file.
  std::string finish() {
    for (auto it = open_.rbegin(); it != open_.rend(); ++it) close_any(*it);
    open_.clear();
    check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush");
    const ssize_t size = check(H5Fget_file_image(file_, nullptr, 0), "the file image");
    std::string bytes(static_cast<std::size_t>(size), '\0');
    check(H5Fget_file_image(file_, bytes.data(), bytes.size()), "the file image");
    const herr_t rc = H5Fclose(file_);
    file_ = -1;
    if (rc < 0) throw OutputError(path_, "HDF5 could not complete the file");
    return bytes;
  }

 private:
  void scalar(hid_t where, const char* name, hid_t type, const void* v) {
    hid_t space = keep(check(H5Screate(H5S_SCALAR), name));
    hid_t a = keep(check(H5Acreate2(where, name, type, space, H5P_DEFAULT, H5P_DEFAULT), name));
    check(H5Awrite(a, type, v), name);
  }

  template <class T>
  T check(T rc, const char* what) {
    if (rc < 0) throw OutputError(path_, std::string("HDF5 failed to write ") + what + " (" + last_error() + ")");
    return rc;
  }

  static std::string last_error() {
    std::string msg;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD,
             [](unsigned n, const H5E_error2_t* e, void* out) -> herr_t {
               if (n == 0 && e->desc) *static_cast<std::string*>(out) = e->desc;
               return 0;
             },
             &msg);
    return msg.empty() ? "disk full or not writable?" : msg;
  }

  hid_t keep(hid_t h) {
    open_.push_back(h);
    return h;
  }

  static void close_any(hid_t h) {
    switch (H5Iget_type(h)) {
      case H5I_DATASET: H5Dclose(h); break;
      case H5I_DATASPACE: H5Sclose(h); break;
      case H5I_DATATYPE: H5Tclose(h); break;
      case H5I_ATTR: H5Aclose(h); break;
      case H5I_GROUP: H5Gclose(h); break;
      case H5I_GENPROP_LST: H5Pclose(h); break;
      default: break;
    }
  }

  std::string path_;
  hid_t file_ = -1;
  std::vector<hid_t> open_;
};

// The attributes every file of a run carries at its root: version, scene, energy, counts, device.
void run_attributes(H5Writer& h, hid_t where, const Plan& plan, const Result& r);

}  // namespace arnoldweb::detail
