// arnoldweb: reading back what a run wrote (saved_run.hpp): summary.json,
// checked, then every other file against its size and digest, and map.h5's
// maps against the shapes summary.json declares.
#include "output/saved_run.hpp"

#include <hdf5.h>

#include <cerrno>
#include <filesystem>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "arnoldweb/scene.hpp"
#include "aw_params.h"
#include "os/regular_file.hpp"
#include "output/file_digest.hpp"
#include "output/h5_reader.hpp"

namespace arnoldweb {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using detail::H5Fail;
using detail::H5File;

constexpr std::uint64_t kMaxSummaryBytes = 64u << 20;  // as output_dir.cpp: far above any summary.json
constexpr std::uint64_t kMaxNside = 8192;
constexpr std::uint64_t kMaxZoom = 8192;

// The node at a JSON pointer through objects only, or nullptr.
const json* at_pointer(const json& j, const std::string& pointer) {
  const json* node = &j;
  std::size_t start = 1;
  while (start <= pointer.size()) {
    const std::size_t slash = pointer.find('/', start);
    const std::string part = pointer.substr(start, slash == std::string::npos ? slash : slash - start);
    if (!node->is_object()) return nullptr;
    const auto it = node->find(part);
    if (it == node->end()) return nullptr;
    node = &*it;
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  return node;
}

std::string field_name(const std::string& pointer) {
  std::string name = pointer.substr(1);
  for (char& c : name)
    if (c == '/') c = '.';
  return name;
}

bool hex_digest(const json& v) {
  if (!v.is_string()) return false;
  const std::string& s = v.get_ref<const std::string&>();
  return s.size() == 32 && s.find_first_not_of("0123456789abcdef") == std::string::npos;
}

// The dimensions of a dataset, or an empty vector when the file has none by
// that name.
std::vector<hsize_t> dims_of(const H5File& file, const char* name, const std::string& path) {
  const std::string at = std::string("/") + name;
  if (!file.has(at)) return {};
  const H5Handle d = file.dataset(at);
  std::vector<hsize_t> dims = file.dims(d.id, at);
  if (dims.size() < 1 || dims.size() > 2) throw SavedRunError(path, std::string("the dataset ") + name + " is not a list or a table");
  return dims;
}

// The stored type of a dataset or attribute must be an integer of at most 8
// bytes: a damaged type of gigabytes per element would have the conversion
// allocate that much before the read fails.
void require_integer_type(hid_t type, const std::string& path, const std::string& what) {
  const H5Handle t{type, H5Tclose};
  if (t.id < 0 || H5Tget_class(t.id) != H5T_INTEGER || H5Tget_size(t.id) == 0 || H5Tget_size(t.id) > 8)
    throw SavedRunError(path, what + " is not stored as integers of at most 64 bits");
}

std::string shape(const std::vector<hsize_t>& dims) {
  std::string s;
  for (hsize_t d : dims) s += (s.empty() ? "" : " x ") + std::to_string(d);
  return s.empty() ? "none" : s;
}

// The dataset `name` as unsigned 64-bit counts; its dimensions must be `want`
// (checked before anything is allocated or read; the reader checked that its
// data is in the file).
std::vector<std::uint64_t> read_counts(const H5File& file, const char* name, const std::vector<hsize_t>& want,
                                       const std::string& path, const std::string& declared) {
  const std::vector<hsize_t> dims = dims_of(file, name, path);
  if (dims != want)
    throw SavedRunError(path, std::string("the dataset ") + name + " is " + shape(dims) + ", but " + declared +
                                  " (summary.json) makes it " + shape(want));
  std::size_t n = 1;
  for (hsize_t d : dims) n *= static_cast<std::size_t>(d);
  std::vector<std::uint64_t> v(dims.empty() ? 0 : n);
  if (v.empty()) return v;
  const H5Handle d = file.dataset(std::string("/") + name);
  require_integer_type(H5Dget_type(d.id), path, std::string("the dataset ") + name);
  if (H5Dread(d.id, H5T_NATIVE_UINT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
    throw SavedRunError(path, std::string("cannot read the dataset ") + name + " as unsigned 64-bit counts");
  return v;
}

std::int64_t nside_attribute(const H5File& file, const std::string& path) {
  const H5Handle d = file.dataset("/map");
  std::int64_t nside = -1;
  if (H5Aexists(d.id, "nside") <= 0) throw SavedRunError(path, "the dataset map has no nside");
  const H5Handle a{H5Aopen(d.id, "nside", H5P_DEFAULT), H5Aclose};
  const H5Handle space{a.id < 0 ? -1 : H5Aget_space(a.id), H5Sclose};
  if (a.id >= 0) require_integer_type(H5Aget_type(a.id), path, "the attribute nside of the dataset map");
  if (a.id < 0 || space.id < 0 || H5Sget_simple_extent_npoints(space.id) != 1 ||
      H5Aread(a.id, H5T_NATIVE_INT64, &nside) < 0)
    throw SavedRunError(path, "cannot read the attribute nside of the dataset map");
  return nside;
}

// The reader's refusals as SavedRunError naming the file (and the object).
H5Fail saved_run_error(const std::string& path) {
  return [path](const std::string& object, const std::string& message) {
    throw SavedRunError(path, object.empty() ? message : object + " " + message);
  };
}

// map.h5's maps from its bytes (checked against their digest), each checked against the
// shape summary.json declares for it ("maps"): r.map, r.frames, r.zoom.
void read_map_bytes(std::string& bytes, const std::string& path, std::uint64_t nside, std::uint64_t frames,
                    std::uint64_t zoom, Result& r) {
  const H5File f(bytes, path, saved_run_error(path));  // the bytes that were checked are the bytes read
  const hsize_t npix = 12 * nside * nside;
  const std::string declared_nside = "maps.nside = " + std::to_string(nside);
  // no velocity map: the dataset map is empty (a run with a zoom) or absent
  const bool no_map = nside == 0 && dims_of(f, "map", path).empty();
  r.map = no_map ? std::vector<std::uint64_t>() : read_counts(f, "map", {npix}, path, declared_nside);
  if (npix && nside_attribute(f, path) != static_cast<std::int64_t>(nside))
    throw SavedRunError(path, "the dataset map says nside " + std::to_string(nside_attribute(f, path)) +
                                  ", but " + declared_nside + " (summary.json)");
  r.frames.clear();
  if (!dims_of(f, "frames", path).empty() || frames > 1) {
    const auto all = read_counts(f, "frames", {frames, npix}, path,
                                 "maps.frames = " + std::to_string(frames) + " and " + declared_nside);
    for (std::size_t k = 0; k < frames; ++k)
      r.frames.emplace_back(all.begin() + static_cast<std::ptrdiff_t>(k * npix),
                            all.begin() + static_cast<std::ptrdiff_t>((k + 1) * npix));
  }
  r.zoom.clear();
  if (!dims_of(f, "zoom", path).empty() || zoom > 0)
    r.zoom = read_counts(f, "zoom", {zoom, zoom}, path, "maps.zoom_resolution = " + std::to_string(zoom));
}

}  // namespace

namespace detail {

SavedDir::SavedDir(const std::string& dir) : dir_(dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw SavedRunError(dir, "no such directory (an output directory of arnoldweb run, with its summary.json)");
  const RegularFile f = read_regular_file(summary_path(), kMaxSummaryBytes);
  if (!f.why.empty())
    throw SavedRunError(summary_path(), "cannot read it: " + f.why +
                                            (f.error == ENOENT ? " (is this an arnoldweb output directory?)" : ""));
  *this = SavedDir(dir, f.bytes);
}

SavedDir::SavedDir(const SavedDir& parent, const std::string& subdir)
    : SavedDir(parent.path(subdir), parent.read(subdir + "/summary.json")) {}

SavedDir::SavedDir(std::string dir, std::string text) : dir_(std::move(dir)), text_(std::move(text)) {
  try {
    j_ = json::parse(text_);
  } catch (const std::exception& e) {
    throw SavedRunError(summary_path(), std::string("not valid JSON: ") + e.what());
  }
  check_fields();
}

const json* SavedDir::digests() const { return at_pointer(j_, "/file_digests"); }

void SavedDir::bad_field(const std::string& pointer, const std::string& expected) const {
  const json* v = at_pointer(j_, pointer);
  throw SavedRunError(summary_path(), field_name(pointer) + " must be " + expected + ", " +
                                          (v ? std::string("it is ") + v->type_name() : "it is missing") +
                                          " (not a summary.json as arnoldweb writes it)");
}

void SavedDir::check_fields() const {
  if (!j_.is_object())
    throw SavedRunError(summary_path(), std::string("must be a JSON object, it is ") + j_.type_name() +
                                            " (not a summary.json as arnoldweb writes it)");
  // what every reader takes from it, so that render and compare agree on what is damaged
  for (const char* p : {"/arnoldweb", "/scene_toml", "/device/id", "/device/name"}) text(p);
  for (const char* p : {"/trajectories", "/completed", "/binned", "/maps/nside", "/maps/frames",
                        "/maps/zoom_resolution"})
    count(p);
  if (const json* files = at_pointer(j_, "/files")) {
    if (!files->is_array()) bad_field("/files", "a list of file names");
    for (const json& f : *files)
      if (!f.is_string()) bad_field("/files", "a list of file names");
  }
  if (const json* digests = at_pointer(j_, "/file_digests")) {
    if (!digests->is_object()) bad_field("/file_digests", "an object of files");
    for (const auto& [name, d] : digests->items())
      if (!d.is_object() || !d.contains("bytes") || !d["bytes"].is_number_unsigned() || !d.contains("xxh3_128") ||
          !hex_digest(d["xxh3_128"]))
        throw SavedRunError(summary_path(), "file_digests." + name +
                                                " must be {\"bytes\": <size>, \"xxh3_128\": <32 hex digits>}");
  }
}

std::uint64_t SavedDir::count(const std::string& pointer) const {
  const json* v = at_pointer(j_, pointer);
  if (!v || !v->is_number_unsigned()) bad_field(pointer, "a count (an integer >= 0)");
  return v->get<std::uint64_t>();
}

std::string SavedDir::text(const std::string& pointer) const {
  const json* v = at_pointer(j_, pointer);
  if (!v || !v->is_string()) bad_field(pointer, "a string");
  return v->get<std::string>();
}

std::optional<std::uint64_t> SavedDir::optional_count(const std::string& pointer) const {
  const json* v = at_pointer(j_, pointer);
  if (!v || !v->is_number_unsigned()) return std::nullopt;
  return v->get<std::uint64_t>();
}

bool SavedDir::holds(const std::string& name) const {
  if (const json* d = digests()) return d->contains(name);
  std::error_code ec;
  return fs::exists(path(name), ec);
}

const json* SavedDir::recorded(const std::string& name) const {
  const json* digests = this->digests();
  return digests && digests->contains(name) ? &(*digests)[name] : nullptr;
}

void SavedDir::check_size(const std::string& name, std::uint64_t size) const {
  const json* want = recorded(name);
  if (!want || size == (*want)["bytes"].get<std::uint64_t>()) return;
  throw SavedRunError(path(name), "it is " + std::to_string(size) + " bytes, but summary.json records " +
                                      std::to_string((*want)["bytes"].get<std::uint64_t>()) +
                                      ": it was changed or replaced after the run wrote it");
}

void SavedDir::check_digest(const std::string& name, const FileDigest& got) const {
  check_size(name, got.bytes);
  const json* want = recorded(name);
  if (!want) return;
  const std::string expected = (*want)["xxh3_128"].get<std::string>();
  if (got.xxh3_128 != expected)
    throw SavedRunError(path(name), "its XXH3-128 digest is " + got.xxh3_128 + ", but summary.json records " +
                                        expected + ": it was damaged, or changed or replaced after the run wrote it");
}

std::string SavedDir::read(const std::string& name, const std::string& missing) const {
  const std::string p = path(name);
  const json* want = recorded(name);
  const std::string gone = "missing" + (missing.empty() ? "" : ": " + missing);
  if (checked() && !want) {
    std::error_code ec;
    if (!fs::exists(p, ec)) throw SavedRunError(p, gone);
    throw SavedRunError(p, "summary.json records no digest for it: it is not a file the run wrote");
  }
  const std::uint64_t most = want ? (*want)["bytes"].get<std::uint64_t>() : UINT64_MAX;
  const RegularFile f = read_regular_file(p, most);
  if (f.error == ENOENT) throw SavedRunError(p, gone);
  if (f.size > most) check_size(name, f.size);  // too large: said before it is read
  if (!f.why.empty()) throw SavedRunError(p, "cannot read it: " + f.why);
  check_digest(name, digest_bytes(f.bytes));
  return f.bytes;
}

std::optional<SavedDir> SavedDir::holding(const std::string& file) {
  std::error_code ec;
  const fs::path at = fs::canonical(file, ec);
  if (ec) return std::nullopt;
  const std::string dir = at.parent_path().string();
  const RegularFile f = read_regular_file(dir + "/summary.json", kMaxSummaryBytes);
  if (!f.why.empty()) return std::nullopt;
  const json j = json::parse(f.bytes, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("arnoldweb") || !j["arnoldweb"].is_string()) return std::nullopt;
  return SavedDir(dir, f.bytes);  // arnoldweb's: checked like any other
}

void check_run_file(const std::string& file, const OpenPlainFile& open) {
  const std::optional<SavedDir> saved = SavedDir::holding(file);
  if (!saved) return;
  const std::string name = fs::canonical(file).filename().string();
  if (!saved->recorded(name)) return;  // not a file the run wrote: the user's own, beside it
  saved->check_size(name, open.size());  // before a byte is read
  saved->check_digest(name, digest_file(open.fd(), saved->path(name)));
}

std::string SavedDir::note() const {
  if (digests()) return "";
  return summary_path() + " records no file digests (written before arnoldweb recorded them): its files were "
                          "read without checking them";
}

int read_saved_map_h5(const SavedDir& saved, Result& r) {
  const std::uint64_t nside = saved.count("/maps/nside"), frames = saved.count("/maps/frames"),
                      zoom = saved.count("/maps/zoom_resolution");
  if (nside > kMaxNside || (nside & (nside - 1)) != 0)
    throw SavedRunError(saved.summary_path(), "maps.nside = " + std::to_string(nside) +
                                                  " is not a HEALPix nside of arnoldweb (0, or a power of two up to 8192)");
  if (frames > AW_MAX_FRAMES)
    throw SavedRunError(saved.summary_path(), "maps.frames = " + std::to_string(frames) + " (at most " +
                                                  std::to_string(AW_MAX_FRAMES) + ")");
  if (zoom > kMaxZoom)
    throw SavedRunError(saved.summary_path(), "maps.zoom_resolution = " + std::to_string(zoom) + " (at most " +
                                                  std::to_string(kMaxZoom) + ")");
  const std::string path = saved.path("map.h5");
  std::string bytes = saved.read("map.h5", "the run made neither a velocity map nor a zoom "
                                           "(observe.velocity_map, observe.zoom)");
  detail::read_in_child_first(bytes.size(), saved_run_error(path),
                              [&] { read_map_bytes(bytes, path, nside, frames, zoom, r); });
  r.nside = static_cast<int>(nside);
  return static_cast<int>(zoom);
}

namespace {

// The scene as run must declare the maps that map.h5 holds: pictures are
// drawn with the scene's nside, frames and zoom.
void check_declared(const SavedDir& saved, const Plan& plan) {
  const auto differs = [&](const char* field, std::uint64_t declared, const std::string& key, std::uint64_t asked) {
    if (declared != asked)
      throw SavedRunError(saved.summary_path(), "scene_toml gives " + key + " = " + std::to_string(asked) + ", but " +
                                                    field + " = " + std::to_string(declared) +
                                                    ": the summary does not describe its map.h5");
  };
  differs("maps.nside", saved.count("/maps/nside"), "observe.velocity_map.nside",
          plan.scene.velocity_map ? static_cast<std::uint64_t>(plan.scene.nside) : 0);
  differs("maps.frames", saved.count("/maps/frames"), "the number of frames", static_cast<std::uint64_t>(plan.frames));
  differs("maps.zoom_resolution", saved.count("/maps/zoom_resolution"), "observe.zoom.resolution",
          static_cast<std::uint64_t>(plan.zoom_resolution));
}

}  // namespace

SavedRun read_saved_run(const SavedDir& saved) {
  SavedRun s;
  s.plan = make_plan(parse_scene(saved.text("/scene_toml"), saved.summary_path()));
  check_declared(saved, s.plan);
  Result& r = s.result;
  r.trajectories = saved.count("/trajectories");
  r.completed = saved.count("/completed");
  r.binned = saved.count("/binned");
  r.device.id = saved.text("/device/id");
  r.device.name = saved.text("/device/name");
  read_saved_map_h5(saved, r);
  return s;
}

}  // namespace detail

SavedMaps read_saved_maps(const std::string& dir) {
  const detail::SavedDir saved(dir);
  SavedMaps s;
  s.summary_file = saved.summary_path();
  s.map_file = saved.path("map.h5");
  s.trajectories = saved.count("/trajectories");
  s.binned = saved.count("/binned");
  s.seed = saved.optional_count("/scene/ensemble/seed");
  s.note = saved.note();
  Result r;
  s.zoom_resolution = detail::read_saved_map_h5(saved, r);
  s.nside = r.nside;
  s.map = std::move(r.map);
  s.frames = std::move(r.frames);
  s.zoom = std::move(r.zoom);
  return s;
}

std::string read_saved_summary(const std::string& dir) { return detail::SavedDir(dir).summary_text(); }

std::string read_saved_file(const std::string& dir, const std::string& name) {
  return detail::SavedDir(dir).read(name);
}

std::string read_saved_hdf5_file(const std::string& dir, const std::string& name) {
  const detail::SavedDir saved(dir);
  std::string bytes = saved.read(name);
  const std::string path = saved.path(name);
  // h5py iterates: all of it, first
  detail::read_in_child_first(bytes.size(), saved_run_error(path), [&] {
    detail::H5File(bytes, path, saved_run_error(path)).check_every_link();
  });
  return bytes;
}

}  // namespace arnoldweb
