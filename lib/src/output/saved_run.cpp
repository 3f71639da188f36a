// arnoldweb: reading back what a run wrote (summary.json, map.h5): for
// render_saved and for read_saved_maps (output.hpp).
#include "output/saved_run.hpp"

#include <hdf5.h>

#include <filesystem>
#include <fstream>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "output/hdf5_handle.hpp"

namespace arnoldweb {
namespace {

namespace fs = std::filesystem;

// A dataset of uint64 counts, or an empty vector when the file has none by
// that name; its dimensions go to *dims.
std::vector<std::uint64_t> read_counts(hid_t file, const char* name, const std::string& path,
                                       std::vector<hsize_t>* dims, std::int64_t* nside = nullptr) {
  std::vector<std::uint64_t> v;
  dims->clear();
  if (H5Lexists(file, name, H5P_DEFAULT) <= 0) return v;
  const H5Handle d{H5Dopen2(file, name, H5P_DEFAULT), H5Dclose};
  if (d.id < 0) throw OutputError(path, std::string("cannot open the dataset ") + name);
  const H5Handle space{H5Dget_space(d.id), H5Sclose};
  const int rank = space.id < 0 ? -1 : H5Sget_simple_extent_ndims(space.id);
  if (rank < 1) throw OutputError(path, std::string("the dataset ") + name + " has no shape");
  dims->resize(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.id, dims->data(), nullptr);
  v.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.id)));
  if (!v.empty() && H5Dread(d.id, H5T_NATIVE_UINT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
    throw OutputError(path, std::string("cannot read the dataset ") + name + " as unsigned 64-bit counts");
  if (nside && H5Aexists(d.id, "nside") > 0) {
    const H5Handle a{H5Aopen(d.id, "nside", H5P_DEFAULT), H5Aclose};
    if (a.id < 0 || H5Aread(a.id, H5T_NATIVE_INT64, nside) < 0)
      throw OutputError(path, std::string("cannot read the attribute nside of ") + name);
  }
  return v;
}

}  // namespace

namespace detail {

nlohmann::json read_summary(const std::string& dir) {
  if (!fs::is_directory(dir)) throw OutputError(dir, "no such directory (an output directory of arnoldweb run)");
  const std::string path = dir + "/summary.json";
  std::ifstream in(path);
  if (!in) throw OutputError(path, "cannot read it (is this an arnoldweb output directory?)");
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw OutputError(path, std::string("not valid JSON: ") + e.what());
  }
}

int read_map_h5(const std::string& dir, Result& r) {
  const std::string path = dir + "/map.h5";
  if (!fs::exists(path))
    throw OutputError(path, "missing: the run made neither a velocity map nor a zoom "
                            "(observe.velocity_map, observe.zoom)");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const H5Handle f{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  if (f.id < 0) throw OutputError(path, "cannot open it (not an HDF5 file?)");
  std::vector<hsize_t> dims;
  std::int64_t nside = 0;
  r.map = read_counts(f.id, "map", path, &dims, &nside);
  const std::size_t npix = r.map.size();
  if (npix && 12 * static_cast<std::size_t>(nside) * static_cast<std::size_t>(nside) != npix)
    throw OutputError(path, "the dataset map has " + std::to_string(npix) + " counts, not 12 nside^2 for its nside " +
                                std::to_string(nside));
  r.nside = npix ? static_cast<int>(nside) : 0;
  const auto frames = read_counts(f.id, "frames", path, &dims);
  r.frames.clear();
  for (std::size_t k = 0; npix && k * npix < frames.size(); ++k)
    r.frames.emplace_back(frames.begin() + static_cast<std::ptrdiff_t>(k * npix),
                          frames.begin() + static_cast<std::ptrdiff_t>((k + 1) * npix));
  r.zoom = read_counts(f.id, "zoom", path, &dims);
  return r.zoom.empty() ? 0 : static_cast<int>(dims[0]);
}

}  // namespace detail

SavedMaps read_saved_maps(const std::string& dir) {
  const nlohmann::json j = detail::read_summary(dir);
  SavedMaps s;
  s.summary_file = dir + "/summary.json";
  s.map_file = dir + "/map.h5";
  try {
    s.trajectories = j.at("trajectories").get<std::uint64_t>();
    s.binned = j.at("binned").get<std::uint64_t>();
  } catch (const std::exception& e) {
    throw OutputError(s.summary_file, std::string("no trajectory counts: ") + e.what());
  }
  const nlohmann::json::json_pointer seed("/scene/ensemble/seed");
  if (j.contains(seed) && j.at(seed).is_number_unsigned()) s.seed = j.at(seed).get<std::uint64_t>();
  Result r;
  s.zoom_resolution = detail::read_map_h5(dir, r);
  s.nside = r.nside;
  s.map = std::move(r.map);
  s.frames = std::move(r.frames);
  s.zoom = std::move(r.zoom);
  return s;
}

}  // namespace arnoldweb
