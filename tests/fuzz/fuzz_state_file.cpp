// libFuzzer target for state files (ensemble.file; docs/outputs.md, "State
// files"), read by read_state_file through the one HDF5 reader
// (lib/src/output/h5_reader.hpp; docs/reliability.md, "Reading HDF5 files").
//
// Structure-aware: an input is not the bytes of an HDF5 file but a
// description of one, which the harness writes with the HDF5 C API and then
// reads as `arnoldweb check` does. Raw HDF5 bytes mostly reach defects of
// HDF5 1.10.8's own parser on damaged metadata (a null read in its local
// heaps within seconds: tests/fuzz/hdf5-defects/), which arnoldweb cannot
// mend; a description reaches what arnoldweb decides: which group, which
// datasets, how each is linked (hard, soft, external), stored (contiguous,
// chunked, deflated, compact, partly written, external storage, virtual),
// typed (float64/32/16, big-endian, int64/32, uint64, uint8) and shaped, the
// values (every bit pattern, NaN and huge windings included), the units
// attribute (h5py's variable-length UTF-8, fixed ASCII, a number) and the
// time. External links, external storage and virtual datasets name fifo.h5,
// a FIFO beside the file: any attempt to read it blocks, which libFuzzer
// reports as a timeout.
//
// The description, byte by byte (missing bytes read as 0):
//   group   bit 0: the datasets go into /final (else the root)
//   then for momentum, position_turns, position, winding, status:
//     flags  bit 0 present; bits 1-2 link (0 hard, 1 soft from /data, 2
//            external); bits 3-5 storage (0 contiguous, 1 chunked, 2 chunked
//            with shuffle and deflate, 3 compact, 4 chunked with its first
//            chunk only, 5 external storage, 6 virtual, 7 never written)
//     type   0 f64, 1 f32, 2 f16, 3 f64 big-endian, 4 i64, 5 i32, 6 u64, 7 u8
//     rows   0-39; columns 0-4 (0: rank 1)
//     values 8 bytes each, as a double (float types) or an integer
//   units   0 none, 1 h5py's string, 2 fixed ASCII, 3 a number; then which
//           of "radians", "turns", "degrees", "", "radians ", "Turns"
//   time    bit 0: present, then 8 bytes as a double
//
// Expected outcomes: the states, or an arnoldweb::Error with a message.
// Findings: any other exception, states of inconsistent sizes, a crash, a
// sanitizer report, a hang, an HDF5 object left open.
#include <hdf5.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>
#include <typeinfo>
#include <vector>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/states.hpp"

namespace {

namespace fs = std::filesystem;

std::string g_dir;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "\nFUZZ FINDING in read_state_file: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

// The description, read from the front; 0 once it is used up.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t u8() { return at_ < size_ ? data_[at_++] : 0; }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int k = 0; k < 8; ++k) v |= std::uint64_t{u8()} << (8 * k);
    return v;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_, at_ = 0;
};

hid_t file_type(int kind) {
  switch (kind) {
    case 0: return H5Tcopy(H5T_IEEE_F64LE);
    case 1: return H5Tcopy(H5T_IEEE_F32LE);
    case 2: {
      const hid_t t = H5Tcopy(H5T_IEEE_F32LE);
      H5Tset_fields(t, 15, 10, 5, 0, 10);
      H5Tset_size(t, 2);
      H5Tset_ebias(t, 15);
      return t;
    }
    case 3: return H5Tcopy(H5T_IEEE_F64BE);
    case 4: return H5Tcopy(H5T_STD_I64LE);
    case 5: return H5Tcopy(H5T_STD_I32LE);
    case 6: return H5Tcopy(H5T_STD_U64LE);
    default: return H5Tcopy(H5T_STD_U8LE);
  }
}

void write_dataset(hid_t file, const std::string& group, const char* name, Bytes& in) {
  const std::uint8_t flags = in.u8();
  if (!(flags & 1)) return;
  const int link = (flags >> 1) & 3, storage = (flags >> 3) & 7, kind = in.u8() % 8;
  const hsize_t rows = in.u8() % 40, columns = in.u8() % 5;
  const std::string at = group + name, fifo = g_dir + "/fifo.h5";
  if (link == 2) {
    H5Lcreate_external(fifo.c_str(), "/momentum", file, at.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    return;
  }
  const std::string where = link == 1 ? std::string("/data/") + name : at;
  std::vector<hsize_t> dims = {rows};
  if (columns) dims.push_back(columns);
  const hsize_t n = rows * std::max<hsize_t>(columns, 1);
  std::vector<std::uint64_t> values(n);
  for (auto& v : values) v = in.u64();
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  const hid_t type = file_type(kind);
  std::vector<hsize_t> chunk = dims;
  chunk[0] = std::max<hsize_t>(1, (rows + 1) / 2);
  if ((storage == 1 || storage == 2 || storage == 4) && rows > 0) H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data());
  if (storage == 2 && rows > 0) H5Pset_shuffle(dcpl), H5Pset_deflate(dcpl, 1);
  if (storage == 3) H5Pset_layout(dcpl, H5D_COMPACT);
  if (storage == 5) H5Pset_external(dcpl, fifo.c_str(), 0, n * H5Tget_size(type));
  if (storage == 6) H5Pset_virtual(dcpl, space, fifo.c_str(), "/momentum", space);
  const hid_t d = H5Dcreate2(file, where.c_str(), type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  const bool real = kind <= 3;
  const hid_t memory = real ? H5T_NATIVE_DOUBLE : H5T_NATIVE_UINT64;
  if (d >= 0 && n > 0 && storage <= 3) {
    H5Dwrite(d, memory, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  } else if (d >= 0 && n > 0 && storage == 4) {  // the first chunk only
    const hid_t part = H5Scopy(space);
    std::vector<hsize_t> start(dims.size(), 0);
    H5Sselect_hyperslab(part, H5S_SELECT_SET, start.data(), nullptr, chunk.data(), nullptr);
    const hid_t in_memory = H5Screate_simple(static_cast<int>(chunk.size()), chunk.data(), nullptr);
    H5Dwrite(d, memory, in_memory, part, H5P_DEFAULT, values.data());
    H5Sclose(in_memory);
    H5Sclose(part);
  }
  if (d >= 0) H5Dclose(d);
  if (link == 1 && d >= 0) H5Lcreate_soft(where.c_str(), file, at.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  H5Tclose(type);
  H5Pclose(dcpl);
  H5Sclose(space);
}

void write_units(hid_t file, const std::string& group, Bytes& in) {
  static const char* const kUnits[] = {"radians", "turns", "degrees", "", "radians ", "Turns"};
  const int mode = in.u8() % 4;
  const char* value = kUnits[in.u8() % 6];
  const std::string object = group + "position";
  if (mode == 0 || H5Lexists(file, object.c_str(), H5P_DEFAULT) <= 0 ||
      H5Oexists_by_name(file, object.c_str(), H5P_DEFAULT) <= 0)
    return;
  const hid_t space = H5Screate(H5S_SCALAR);
  hid_t type = mode == 3 ? H5Tcopy(H5T_IEEE_F64LE) : H5Tcopy(H5T_C_S1);
  if (mode == 1) H5Tset_size(type, H5T_VARIABLE), H5Tset_cset(type, H5T_CSET_UTF8);
  if (mode == 2) H5Tset_size(type, std::max<std::size_t>(1, std::strlen(value)));
  const hid_t a = H5Acreate_by_name(file, object.c_str(), "units", type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const double number = 1.0;
  if (a >= 0) {
    if (mode == 1) H5Awrite(a, type, &value);
    if (mode == 2) H5Awrite(a, type, value);
    if (mode == 3) H5Awrite(a, H5T_NATIVE_DOUBLE, &number);
    H5Aclose(a);
  }
  H5Tclose(type);
  H5Sclose(space);
}

// The description as an HDF5 file at `path`.
void write_file(const std::string& path, Bytes& in) {
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0) finding("the harness cannot create " + path);
  const bool final = in.u8() & 1;
  const std::string group = final ? "/final/" : "/";
  if (final) H5Gclose(H5Gcreate2(file, "/final", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  H5Gclose(H5Gcreate2(file, "/data", lcpl, H5P_DEFAULT, H5P_DEFAULT));
  H5Pclose(lcpl);
  for (const char* name : {"momentum", "position_turns", "position", "winding", "status"})
    write_dataset(file, group, name, in);
  write_units(file, group, in);
  if (in.u8() & 1) {
    const std::uint64_t bits = in.u64();
    double time = 0;
    std::memcpy(&time, &bits, sizeof time);
    const hid_t space = H5Screate(H5S_SCALAR);
    const std::string object = final ? "/final" : "/";
    const hid_t a = H5Acreate_by_name(file, object.c_str(), "time", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT,
                                      H5P_DEFAULT);
    if (a >= 0) H5Awrite(a, H5T_NATIVE_DOUBLE, &time), H5Aclose(a);
    H5Sclose(space);
  }
  H5Fclose(file);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // the harness's own failed calls are quiet
  std::string templ = (fs::temp_directory_path() / "arnoldweb-fuzz-states-XXXXXX").string();
  if (!mkdtemp(templ.data())) finding("the harness cannot make a temporary directory");
  g_dir = templ;
  if (::mkfifo((g_dir + "/fifo.h5").c_str(), 0600) != 0) finding("the harness cannot make its FIFO");
  std::atexit([] {
    std::error_code ec;
    fs::remove_all(g_dir, ec);
  });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = g_dir + "/states.h5";
  Bytes in(data, size);
  write_file(path, in);
  if (const ssize_t open = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL); open != 0)
    finding("the harness left " + std::to_string(open) + " HDF5 object(s) open");
  try {
    const arnoldweb::StateSet s = arnoldweb::read_state_file(path);
    if (s.count == 0 || s.momentum.size() != 3 * s.count || s.position_turns.size() != 3 * s.count ||
        s.winding.size() != 3 * s.count || s.status.size() != s.count)
      finding("states of inconsistent sizes were returned");
  } catch (const arnoldweb::Error& e) {
    if (std::string(e.what()).empty()) finding("an arnoldweb::Error without a message");
  } catch (const std::exception& e) {
    finding(std::string("unexpected exception ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    finding("unexpected exception of a type not derived from std::exception");
  }
  // every HDF5 object the reader opened is closed again, on every path
  if (const ssize_t open = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL); open != 0)
    finding(std::to_string(open) + " HDF5 object(s) left open");
  return 0;
}
