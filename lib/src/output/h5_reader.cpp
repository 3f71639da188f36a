// arnoldweb: opening HDF5 files for reading under one policy (h5_reader.hpp).
#include "output/h5_reader.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace arnoldweb::detail {
namespace {

constexpr std::size_t kMaxLinks = 100000;            // arnoldweb's files hold a few dozen
constexpr std::size_t kMaxAttributeBytes = 1u << 20;  // a units string, a nside

constexpr int kMaxSoftLinks = 16;                    // hops from one name to its object

#if H5_VERSION_GE(1, 12, 0)
using LinkInfo = H5L_info2_t;
#define AW_H5LVISIT H5Lvisit2
#define AW_H5LGET_INFO H5Lget_info2
#else
using LinkInfo = H5L_info_t;
#define AW_H5LVISIT H5Lvisit
#define AW_H5LGET_INFO H5Lget_info
#endif

// External links are never followed (the walk refuses them first; this
// guards every name given to HDF5 as well).
herr_t refuse_external_link(const char*, const char*, const char*, const char*, unsigned*, hid_t, void*) { return -1; }

const char* const kWhy = " (docs/reliability.md, \"Reading HDF5 files\")";

// " to other.h5:/momentum" (where the external link `name` leads), or "".
std::string external_link_target(hid_t group, const char* name, std::size_t size) {
  std::vector<char> value(size + 1, '\0');
  const char* file = nullptr;
  const char* object = nullptr;
  unsigned flags = 0;
  if (size == 0 || size > (1u << 16) || H5Lget_val(group, name, value.data(), value.size(), H5P_DEFAULT) < 0 ||
      H5Lunpack_elink_val(value.data(), size, &flags, &file, &object) < 0 || !file || !object)
    return "";
  return std::string(" to ") + file + ":" + object;
}

std::string filter_name(hid_t dcpl, unsigned k, H5Z_filter_t& id) {
  unsigned flags = 0, config = 0;
  std::size_t n = 8;
  unsigned values[8];
  char name[64] = {0};
  id = H5Pget_filter2(dcpl, k, &flags, &n, values, sizeof name, name, &config);
  return name[0] ? std::string(name) : "id " + std::to_string(static_cast<long>(id));
}

// A count that may exceed 64 bits: "402653184", "3.4e+38".
std::string show_count(long double n) {
  if (n < 1.8e19L) return std::to_string(static_cast<unsigned long long>(n));
  char text[32];
  std::snprintf(text, sizeof text, "%.3Lg", n);
  return text;
}

// Why the dataset `d` may not be read, or "" (a file of `file_bytes`).
std::string dataset_problem(hid_t d, std::uint64_t file_bytes) {
  const H5Handle dcpl{H5Dget_create_plist(d), H5Pclose};
  if (dcpl.id < 0) return "has creation properties that cannot be read (a damaged file?)";
  const H5D_layout_t layout = H5Pget_layout(dcpl.id);
  if (layout == H5D_VIRTUAL)
    return std::string("is a virtual dataset: its data lives in other files, and arnoldweb reads only what is "
                       "stored in the file itself") + kWhy;
  if (const int n = H5Pget_external_count(dcpl.id); n != 0) {
    char name[256] = {0};
    off_t offset = 0;
    hsize_t size = 0;
    const bool named = n > 0 && H5Pget_external(dcpl.id, 0, sizeof name - 1, name, &offset, &size) >= 0;
    return std::string("stores its data in the external file") + (named ? std::string(" ") + name : std::string()) +
           ": arnoldweb reads only what is stored in the file itself" + kWhy;
  }
  if (layout != H5D_CONTIGUOUS && layout != H5D_CHUNKED && layout != H5D_COMPACT)
    return "has a storage layout this HDF5 cannot read (a damaged file?)";
  const int filters = H5Pget_nfilters(dcpl.id);
  if (filters < 0) return "has filters that cannot be read (a damaged file?)";
  for (int k = 0; k < filters; ++k) {
    H5Z_filter_t id = -1;
    const std::string name = filter_name(dcpl.id, static_cast<unsigned>(k), id);
    if (id != H5Z_FILTER_DEFLATE && id != H5Z_FILTER_SHUFFLE && id != H5Z_FILTER_FLETCHER32)
      return "is stored with the filter " + name +
             "; arnoldweb reads datasets stored plain or with gzip (deflate), shuffle and fletcher32, as h5py and "
             "arnoldweb write them" + kWhy;
  }
  const H5Handle space{H5Dget_space(d), H5Sclose};
  const H5Handle type{H5Dget_type(d), H5Tclose};
  const hssize_t points = space.id < 0 ? -1 : H5Sget_simple_extent_npoints(space.id);
  const std::size_t value_bytes = type.id < 0 ? 0 : H5Tget_size(type.id);
  if (points < 0 || value_bytes == 0) return "has a shape or a type that cannot be read (a damaged file?)";
  if (points == 0) return "";
  const long double declared = static_cast<long double>(points) * static_cast<long double>(value_bytes);
  const std::uint64_t stored = H5Dget_storage_size(d);
  const std::string sizes = "declares " + std::to_string(points) + " values (" + show_count(declared) +
                            " bytes) and stores " + std::to_string(stored) + " bytes";
  if (stored > file_bytes) return sizes + " in a file of " + std::to_string(file_bytes) + " bytes (a damaged file)";
  if (layout == H5D_CHUNKED) {
    const int rank = H5Sget_simple_extent_ndims(space.id);
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank > 0 ? rank : 0)), chunk(dims.size());
    if (rank <= 0 || H5Sget_simple_extent_dims(space.id, dims.data(), nullptr) < 0 ||
        H5Pget_chunk(dcpl.id, rank, chunk.data()) != rank)
      return "has a chunk shape that cannot be read (a damaged file?)";
    long double chunks = 1;
    for (int k = 0; k < rank; ++k) {
      if (chunk[k] == 0) return "has a chunk of size 0 (a damaged file)";
      chunks *= static_cast<long double>((dims[k] + chunk[k] - 1) / chunk[k]);
    }
#if H5_VERSION_GE(1, 10, 5)
    hsize_t written = 0;
    if (H5Dget_num_chunks(d, space.id, &written) < 0) return "has a chunk index that cannot be read (a damaged file?)";
    if (static_cast<long double>(written) < chunks)
      return sizes + " in " + std::to_string(written) + " of its " + show_count(chunks) +
             " chunks: the others were never written (HDF5 would give fill values in their place)";
#endif
  }
  const bool filtered = filters > 0;
  if (!filtered && static_cast<long double>(stored) < declared)
    return sizes + ": the rest was never written (HDF5 would give fill values in its place)";
  if (filtered && declared > static_cast<long double>(stored) * kMaxInflation)
    return sizes + ", compressed more than gzip can (" + std::to_string(kMaxInflation) + ":1; a damaged file)";
  return "";
}

struct Walk {
  std::uint64_t file_bytes = 0;
  hid_t lapl = -1;
  std::size_t links = 0;
  std::string object, problem;
};

// Why a link of `type` (not hard, not soft) may not be followed.
std::string link_leads_out(H5L_type_t type, hid_t group, const char* name, std::size_t value_size) {
  const std::string what = type == H5L_TYPE_EXTERNAL
                               ? "is an external link" + external_link_target(group, name, value_size)
                               : std::string("is a user-defined link");
  return what + ": arnoldweb reads only what is stored in the file itself" + kWhy;
}

herr_t visit_link(hid_t group, const char* name, const LinkInfo* info, void* data) {
  Walk& w = *static_cast<Walk*>(data);
  w.object = std::string("/") + name;
  if (++w.links > kMaxLinks) {
    w.object.clear();
    w.problem = "holds more than " + std::to_string(kMaxLinks) + " links; arnoldweb's files hold a few dozen";
    return 1;
  }
  switch (info->type) {
    case H5L_TYPE_HARD: {
      const H5Handle o{H5Oopen(group, name, w.lapl), H5Oclose};
      if (o.id < 0) {
        w.problem = "cannot be opened (a damaged file?)";
        return 1;
      }
      if (H5Iget_type(o.id) == H5I_DATASET) w.problem = dataset_problem(o.id, w.file_bytes);
      return w.problem.empty() ? 0 : 1;
    }
    case H5L_TYPE_SOFT:
      return 0;  // a path inside this file, where no link leads out (this walk)
    default:
      w.problem = link_leads_out(info->type, group, name, info->u.val_size);
      return 1;
  }
}

}  // namespace

std::string show_shape(const std::vector<hsize_t>& dims) {
  std::string s;
  for (hsize_t d : dims) s += (s.empty() ? "" : ", ") + std::to_string(d);
  return "(" + s + (dims.size() == 1 ? ",)" : ")");
}

H5File::H5File(const OpenPlainFile& file, const std::string& path, H5Fail fail)
    : path_(path), fail_(std::move(fail)), file_bytes_(file.size()) {
  if (!file.why().empty()) this->fail("", file.why());
  const int fd = file.fd();
  const std::uint64_t size = file_bytes_;
  guard_heaps([fd, size](std::uint64_t offset, std::size_t n) {
    std::string b(offset < size ? static_cast<std::size_t>(std::min<std::uint64_t>(n, size - offset)) : 0, '\0');
    std::size_t got = 0;
    while (got < b.size()) {
      const ssize_t r = ::pread(fd, b.data() + got, b.size() - got, static_cast<off_t>(offset + got));
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) break;
      got += static_cast<std::size_t>(r);
    }
    b.resize(got);
    return b;
  });
  const H5Handle fapl{H5Pcreate(H5P_FILE_ACCESS), H5Pclose};
  open(file.name(), fapl.id);
}

H5File::H5File(std::string& bytes, const std::string& path, H5Fail fail)
    : path_(path), fail_(std::move(fail)), file_bytes_(bytes.size()) {
  guard_heaps([&bytes](std::uint64_t offset, std::size_t n) {
    return offset < bytes.size() ? bytes.substr(static_cast<std::size_t>(offset), n) : std::string();
  });
  const H5Handle fapl{H5Pcreate(H5P_FILE_ACCESS), H5Pclose};
  if (fapl.id < 0 || H5Pset_fapl_core(fapl.id, 1 << 20, 0) < 0 ||
      H5Pset_file_image(fapl.id, bytes.data(), bytes.size()) < 0)
    this->fail("", "HDF5 could not take the file's bytes");
  // The core driver refuses an image whose name it can open on disk (and an
  // open could block on a FIFO): with a slash after the name of a file, the
  // open fails at once (ENOTDIR).
  open(path + "/", fapl.id);
}

void H5File::open(const std::string& name, hid_t fapl) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not prints
  lapl_.id = H5Pcreate(H5P_LINK_ACCESS);
  if (lapl_.id < 0 || H5Pset_elink_cb(lapl_.id, refuse_external_link, nullptr) < 0)
    fail("", "HDF5 could not make its link access properties");
  file_.id = fapl < 0 ? -1 : H5Fopen(name.c_str(), H5F_ACC_RDONLY, fapl);
  if (file_.id < 0) fail("", "cannot be opened as an HDF5 file (it is none, or a damaged one)");
}

void H5File::guard_heaps(const ReadAt& read) const {
  if (const std::string why = heap_problem(read, file_bytes_); !why.empty()) fail("", why);
}

void H5File::fail(const std::string& object, const std::string& message) const {
  fail_(object, message);
  throw std::logic_error("H5Fail returned");  // the callers' fail throws
}

void H5File::check_every_link() const {
  Walk w;
  w.file_bytes = file_bytes_;
  w.lapl = lapl_.id;
  const herr_t visited = AW_H5LVISIT(file_.id, H5_INDEX_NAME, H5_ITER_NATIVE, visit_link, &w);
  if (!w.problem.empty()) fail(w.object, w.problem);
  if (visited < 0) fail("", "its groups cannot be read (a damaged file?)");
}

std::string H5File::resolve(const std::string& path, int hops) const {
  if (hops > kMaxSoftLinks) fail(path, "is reached through more than " + std::to_string(kMaxSoftLinks) + " soft links");
  std::string at;  // the object reached so far, through hard links only ("": the root group)
  for (std::size_t start = 0; start <= path.size();) {
    const std::size_t slash = std::min(path.find('/', start), path.size());
    const std::string part = path.substr(start, slash - start);
    start = slash + 1;
    if (part.empty() || part == ".") continue;
    const std::string next = at + "/" + part;
    LinkInfo info{};
    // HDF5 follows no link here: every link on the way to `next` is a hard link already looked at
    if (H5Lexists(file_.id, next.c_str(), lapl_.id) <= 0 ||
        AW_H5LGET_INFO(file_.id, next.c_str(), &info, lapl_.id) < 0)
      return "";
    if (info.type == H5L_TYPE_HARD) {
      at = next;
    } else if (info.type == H5L_TYPE_SOFT) {
      std::vector<char> target(info.u.val_size + 1, '\0');
      if (info.u.val_size == 0 || info.u.val_size > (1u << 16) ||
          H5Lget_val(file_.id, next.c_str(), target.data(), target.size(), lapl_.id) < 0)
        return "";
      const std::string to(target.data());
      at = resolve(to[0] == '/' ? to : (at.empty() ? "/" : at) + "/" + to, hops + 1);
      if (at.empty()) return "";
      if (at == "/") at.clear();
    } else {
      fail(next, link_leads_out(info.type, file_.id, next.c_str(), info.u.val_size));
    }
  }
  return at.empty() ? "/" : at;
}

bool H5File::has(const std::string& path) const {
  const std::string at = resolve(path, 0);
  return !at.empty() && H5Oexists_by_name(file_.id, at.c_str(), lapl_.id) > 0;
}

H5Handle H5File::dataset(const std::string& path) const {
  const std::string at = resolve(path, 0);
  if (at.empty()) fail(path, "is missing");
  const H5Handle dapl{H5Pcreate(H5P_DATASET_ACCESS), H5Pclose};
  if (dapl.id < 0 || H5Pset_elink_cb(dapl.id, refuse_external_link, nullptr) < 0)
    fail(path, "cannot be opened (HDF5 could not make its access properties)");
  H5Handle d{H5Dopen2(file_.id, at.c_str(), dapl.id), H5Dclose};
  if (d.id < 0) fail(path, "cannot be opened as a dataset");
  // before its shape is asked for: a virtual dataset's shape can open its sources
  if (const std::string why = dataset_problem(d.id, file_bytes_); !why.empty()) fail(path, why);
  return d;
}

std::vector<hsize_t> H5File::dims(hid_t dataset, const std::string& path) const {
  const H5Handle space{H5Dget_space(dataset), H5Sclose};
  const int rank = space.id < 0 ? -1 : H5Sget_simple_extent_ndims(space.id);
  if (rank < 0 || rank > H5S_MAX_RANK) fail(path, "has a shape that cannot be read (a damaged file?)");
  std::vector<hsize_t> d(static_cast<std::size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space.id, d.data(), nullptr) < 0)
    fail(path, "has a shape that cannot be read (a damaged file?)");
  return d;
}

bool H5File::has_attribute(const std::string& object, const char* name) const {
  const std::string at = resolve(object, 0);
  return !at.empty() && H5Aexists_by_name(file_.id, at.c_str(), name, lapl_.id) > 0;
}

namespace {

// "a variable-length UTF-8 string", "an integer", ...
std::string describe(hid_t type) {
  switch (H5Tget_class(type)) {
    case H5T_STRING:
      return std::string(H5Tis_variable_str(type) > 0 ? "a variable-length " : "a fixed-length ") +
             (H5Tget_cset(type) == H5T_CSET_UTF8 ? "UTF-8" : "ASCII") + " string";
    case H5T_INTEGER: return "an integer";
    case H5T_FLOAT: return "a floating-point number";
    default: return "neither a string nor a number";
  }
}

}  // namespace

std::string H5File::text_attribute(const std::string& object, const char* name) const {
  const std::string what = std::string("the attribute ") + name;
  const H5Handle a{H5Aopen_by_name(file_.id, resolve(object, 0).c_str(), name, H5P_DEFAULT, lapl_.id), H5Aclose};
  if (a.id < 0) fail(object, what + " cannot be opened (a damaged file?)");
  const H5Handle type{H5Aget_type(a.id), H5Tclose};
  const H5Handle space{H5Aget_space(a.id), H5Sclose};
  if (type.id < 0 || space.id < 0) fail(object, what + " has a type that cannot be read (a damaged file?)");
  if (H5Tget_class(type.id) != H5T_STRING) fail(object, what + " must be a string; it is " + describe(type.id));
  if (H5Sget_simple_extent_npoints(space.id) != 1)
    fail(object, what + " must be one string; it holds " +
                     std::to_string(static_cast<long long>(H5Sget_simple_extent_npoints(space.id))) + " values");
  std::string s;
  if (H5Tis_variable_str(type.id) > 0) {
    // in memory: a C string of the file's character set (h5py writes UTF-8)
    const H5Handle memory{H5Tcopy(H5T_C_S1), H5Tclose};
    char* text = nullptr;
    if (memory.id < 0 || H5Tset_size(memory.id, H5T_VARIABLE) < 0 ||
        H5Tset_cset(memory.id, H5Tget_cset(type.id)) < 0 || H5Aread(a.id, memory.id, &text) < 0)
      fail(object, what + " (" + describe(type.id) + ") cannot be read (a damaged file?)");
    if (text) {
      s.assign(text, ::strnlen(text, kMaxAttributeBytes + 1));
      H5free_memory(text);
    }
  } else {
    const std::size_t size = H5Tget_size(type.id);
    if (size == 0 || size > kMaxAttributeBytes)
      fail(object, what + " is longer than 1 MiB (a damaged file?)");
    s.assign(size, '\0');
    if (H5Aread(a.id, type.id, s.data()) < 0)
      fail(object, what + " (" + describe(type.id) + ") cannot be read (a damaged file?)");
    s.resize(std::strlen(s.c_str()));
    if (H5Tget_strpad(type.id) == H5T_STR_SPACEPAD) s.erase(s.find_last_not_of(' ') + 1);
  }
  if (s.size() > kMaxAttributeBytes) fail(object, what + " is longer than 1 MiB (a damaged file?)");
  return s;
}

double H5File::number_attribute(const std::string& object, const char* name) const {
  const std::string what = std::string("the attribute ") + name;
  const H5Handle a{H5Aopen_by_name(file_.id, resolve(object, 0).c_str(), name, H5P_DEFAULT, lapl_.id), H5Aclose};
  const H5Handle type{a.id < 0 ? -1 : H5Aget_type(a.id), H5Tclose};
  const H5Handle space{a.id < 0 ? -1 : H5Aget_space(a.id), H5Sclose};
  if (type.id < 0 || space.id < 0) fail(object, what + " cannot be opened (a damaged file?)");
  const H5T_class_t c = H5Tget_class(type.id);
  if (c != H5T_FLOAT && c != H5T_INTEGER) fail(object, what + " must be a number; it is " + describe(type.id));
  if (const hssize_t n = H5Sget_simple_extent_npoints(space.id); n != 1)
    fail(object, what + " must be one number; it holds " + std::to_string(static_cast<long long>(n)));
  // a damaged type of gigabytes per value would have the conversion allocate that much
  if (H5Tget_size(type.id) == 0 || H5Tget_size(type.id) > 8)
    fail(object, what + " is a number of " + std::to_string(H5Tget_size(type.id)) + " bytes; at most 8");
  double v = 0;
  if (H5Aread(a.id, H5T_NATIVE_DOUBLE, &v) < 0) fail(object, what + " cannot be read (a damaged file?)");
  return v;
}

std::string hdf5_child_died(const std::string& why) {
  return "HDF5 could not read it: its reader (a child process) " + why +
         " (a damaged file: HDF5 1.10.8 fails on some damaged metadata; docs/reliability.md, \"Reading HDF5 files\")";
}

}  // namespace arnoldweb::detail
