// HDF5 files written by tests with the HDF5 C API: good ones and crafted
// ones (what h5py writes by default, links and storage that lead out of the
// file, datasets that declare more than they store) for the readers' tests
// (tests/states, tests/output, tests/reliability); read_doubles reads a
// dataset a run wrote back with its dimensions.
#pragma once

#include <doctest/doctest.h>
#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace awtest {

// A double dataset of an HDF5 file and its dimensions.
inline std::vector<double> read_doubles(const std::string& file, const char* name, std::vector<hsize_t>* dims) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(f >= 0);
  hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
  REQUIRE(d >= 0);
  hid_t space = H5Dget_space(d);
  const int rank = H5Sget_simple_extent_ndims(space);
  dims->assign(static_cast<std::size_t>(rank), 0);
  H5Sget_simple_extent_dims(space, dims->data(), nullptr);
  hsize_t n = 1;
  for (hsize_t x : *dims) n *= x;
  std::vector<double> v(n);
  CHECK(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  return v;
}

class H5TestFile {
 public:
  explicit H5TestFile(const std::string& path) {
    file_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    REQUIRE(file_ >= 0);
  }
  ~H5TestFile() { close(); }
  H5TestFile(const H5TestFile&) = delete;
  H5TestFile& operator=(const H5TestFile&) = delete;
  void close() {
    if (file_ >= 0) H5Fclose(file_);
    file_ = -1;
  }
  hid_t id() const { return file_; }

  void group(const std::string& name) {
    H5Gclose(H5Gcreate2(file_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  }
  // A dataset of `dims` and file type `type`, written from `v` (doubles, int64 or uint64)
  // unless it is empty; `dcpl` its creation properties.
  template <class T>
  void dataset(const std::string& name, const std::vector<T>& v, std::vector<hsize_t> dims, hid_t type,
               hid_t dcpl = H5P_DEFAULT) {
    const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
    const hid_t d = H5Dcreate2(file_, name.c_str(), type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    REQUIRE(d >= 0);
    const hid_t memory = std::is_same<T, double>::value          ? H5T_NATIVE_DOUBLE
                         : std::is_same<T, std::uint64_t>::value ? H5T_NATIVE_UINT64
                                                                 : H5T_NATIVE_INT64;
    if (!v.empty()) REQUIRE(H5Dwrite(d, memory, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
    H5Dclose(d);
    H5Sclose(space);
  }
  void reals(const std::string& name, const std::vector<double>& v, hid_t type = H5T_IEEE_F64LE) {
    dataset(name, v, {v.size() / 3, 3}, type);
  }
  void ints(const std::string& name, const std::vector<std::int64_t>& v, bool rows_of_3 = true) {
    dataset(name, v, rows_of_3 ? std::vector<hsize_t>{v.size() / 3, 3} : std::vector<hsize_t>{v.size()},
            H5T_STD_I64LE);
  }
  // A fixed-length ASCII string attribute (what the C API writes simply).
  void text(const std::string& object, const char* name, const std::string& value) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, value.size());
    attribute(object, name, type, value.c_str());
    H5Tclose(type);
  }
  // A variable-length UTF-8 string attribute: what h5py writes for attrs['units'] = 'radians'.
  void h5py_text(const std::string& object, const char* name, const std::string& value) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    const char* p = value.c_str();
    attribute(object, name, type, &p);
    H5Tclose(type);
  }
  void number(const std::string& object, const char* name, double value) {
    const hid_t type = H5Tcopy(H5T_IEEE_F64LE);
    attribute(object, name, type, &value, H5T_NATIVE_DOUBLE);
    H5Tclose(type);
  }

  // Links and storage that lead out of the file, to `target` (e.g. a FIFO).
  void external_link(const std::string& name, const std::string& target, const std::string& object = "/momentum") {
    REQUIRE(H5Lcreate_external(target.c_str(), object.c_str(), file_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT) >= 0);
  }
  void external_storage(const std::string& name, hsize_t rows, const std::string& target) {
    const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    REQUIRE(H5Pset_external(dcpl, target.c_str(), 0, rows * 3 * 8) >= 0);
    dataset<double>(name, {}, {rows, 3}, H5T_IEEE_F64LE, dcpl);
    H5Pclose(dcpl);
  }
  // A virtual dataset of `rows` x 3 mapped onto `target`:/momentum; with
  // `unlimited`, a mapping whose extent HDF5 finds by opening the source
  // (when the dataset's shape is asked for).
  void virtual_dataset(const std::string& name, hsize_t rows, const std::string& target, bool unlimited) {
    hsize_t dims[2] = {rows, 3}, most[2] = {H5S_UNLIMITED, 3};
    const hid_t space = H5Screate_simple(2, dims, unlimited ? most : nullptr);
    const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    if (unlimited) {
      hsize_t start[2] = {0, 0}, stride[2] = {1, 1}, count[2] = {H5S_UNLIMITED, 1}, block[2] = {1, 3};
      REQUIRE(H5Sselect_hyperslab(space, H5S_SELECT_SET, start, stride, count, block) >= 0);
    }
    REQUIRE(H5Pset_virtual(dcpl, space, target.c_str(), "/momentum", space) >= 0);
    if (unlimited) H5Sselect_all(space);
    const hid_t d = H5Dcreate2(file_, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    REQUIRE(d >= 0);
    H5Dclose(d);
    H5Pclose(dcpl);
    H5Sclose(space);
  }
  // A chunked dataset of `rows` x 3 doubles of which nothing is written.
  void unwritten(const std::string& name, hsize_t rows) {
    const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    hsize_t chunk[2] = {std::min<hsize_t>(rows, 65536), 3};
    REQUIRE(H5Pset_chunk(dcpl, 2, chunk) >= 0);
    dataset<double>(name, {}, {rows, 3}, H5T_IEEE_F64LE, dcpl);
    H5Pclose(dcpl);
  }

 private:
  void attribute(const std::string& object, const char* name, hid_t type, const void* value,
                 hid_t memory = -1) {
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a =
        H5Acreate_by_name(file_, object.c_str(), name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    REQUIRE(a >= 0);
    REQUIRE(H5Awrite(a, memory >= 0 ? memory : type, value) >= 0);
    H5Aclose(a);
    H5Sclose(space);
  }

  hid_t file_ = -1;
};

}  // namespace awtest
