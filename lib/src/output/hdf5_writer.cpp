// arnoldweb: HDF5 outputs. map.h5: the velocity map (HEALPix RING), its
// frames and the zoom histogram; states.h5: initial and final states. Every
// dataset carries what is needed to read it (nside, ordering, scene).
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "arnoldweb/version.hpp"
#include "aw_params.h"
#include "output/atomic_file.hpp"

namespace arnoldweb {
namespace {

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

  // A dataset of `dims`, chunked and deflated when large.
  hid_t dataset(hid_t where, const char* name, hid_t type, const std::vector<hsize_t>& dims, const void* data) {
    hid_t space = keep(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), name));
    hid_t props = keep(check(H5Pcreate(H5P_DATASET_CREATE), name));
    hsize_t total = 1;
    for (auto d : dims) total *= d;
    if (total >= 4096) {
      std::vector<hsize_t> chunk = dims;
      chunk[0] = std::min<hsize_t>(dims[0], std::max<hsize_t>(1, 65536 / std::max<hsize_t>(1, total / dims[0])));
      check(H5Pset_chunk(props, static_cast<int>(chunk.size()), chunk.data()), name);
      check(H5Pset_deflate(props, 4), name);
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

void common_attributes(H5Writer& h, hid_t where, const Plan& plan, const Result& r) {
  h.attr(where, "arnoldweb", std::string(ARNOLDWEB_VERSION));
  h.attr(where, "scene", plan.scene.to_toml());
  h.attr(where, "energy", plan.scene.energy);
  h.attr(where, "trajectories", static_cast<std::int64_t>(r.trajectories));
  h.attr(where, "binned", static_cast<std::int64_t>(r.binned));
  h.attr(where, "device", r.device.id + " (" + r.device.name + ")");
}

}  // namespace

void write_map_hdf5(const std::string& path, const Plan& plan, const Result& r) {
  H5Writer h(path);
  {
    common_attributes(h, h.root(), plan, r);
    const hsize_t npix = r.map.size();
    hid_t map = h.dataset(h.root(), "map", H5T_NATIVE_UINT64, {npix}, r.map.data());
    h.attr(map, "nside", static_cast<std::int64_t>(plan.scene.nside));
    h.attr(map, "ordering", std::string("RING"));
    h.attr(map, "coordinate", std::string("direction of the averaged velocity V = (X(t + dt) - X(t)) / dt"));
    h.attr(map, "average", plan.scene.average);
    h.attr(map, "windows_per_trajectory", static_cast<std::int64_t>(plan.windows));
    h.attr(map, "digest", digest_map(r));
    if (!r.frames.empty()) {
      std::vector<std::uint64_t> all;
      for (const auto& f : r.frames) all.insert(all.end(), f.begin(), f.end());
      hid_t frames = h.dataset(h.root(), "frames", H5T_NATIVE_UINT64, {r.frames.size(), npix}, all.data());
      h.attr(frames, "nside", static_cast<std::int64_t>(plan.scene.nside));
      h.attr(frames, "ordering", std::string("RING"));
      h.attr(frames, "times", plan.scene.frame_times);
      h.attr(frames, "meaning", std::string("frame k: windows starting in [times[k], times[k+1]) T"));
    }
    if (!r.zoom.empty()) {
      const hsize_t res = static_cast<hsize_t>(plan.zoom_resolution);
      hid_t zoom = h.dataset(h.root(), "zoom", H5T_NATIVE_UINT64, {res, res}, r.zoom.data());
      h.attr(zoom, "center_lon_lat", std::vector<double>{plan.scene.zoom_center[0], plan.scene.zoom_center[1]});
      h.attr(zoom, "width", plan.scene.zoom_width);
      h.attr(zoom, "projection",
             std::string("gnomonic about the centre: column x (east), row y (north), tangent-plane "
                         "coordinates from -tan(width/2) to tan(width/2)"));
    }
  }
  detail::write_file_atomically(path, h.finish());
}

void write_states_hdf5(const std::string& path, const Plan& plan, const Result& r) {
  H5Writer h(path);
  {
    common_attributes(h, h.root(), plan, r);
    const hsize_t n = r.completed;
    auto split = [&](const std::vector<double>& rec, int first) {
      std::vector<double> out(n * 3);
      for (hsize_t t = 0; t < n; ++t)
        for (int k = 0; k < 3; ++k) out[t * 3 + k] = rec[t * AW_STATE_REALS + first + k];
      return out;
    };
    if (!r.initial_r.empty()) {
      hid_t g = h.group("initial");
      h.dataset(g, "position_turns", H5T_NATIVE_DOUBLE, {n, 3}, split(r.initial_r, 0).data());
      h.dataset(g, "momentum", H5T_NATIVE_DOUBLE, {n, 3}, split(r.initial_r, 3).data());
      h.attr(g, "digest", digest_initial_states(r));
    }
    if (!r.final_r.empty()) {
      hid_t g = h.group("final");
      const auto u = split(r.final_r, 0);
      std::vector<std::int64_t> winding(n * 3), status(n);
      std::vector<double> position(n * 3);
      for (hsize_t t = 0; t < n; ++t) {
        for (int k = 0; k < 3; ++k) {
          winding[t * 3 + k] = r.final_i[t * AW_STATE_INTS + k];
          position[t * 3 + k] = 2 * M_PI * (static_cast<double>(winding[t * 3 + k]) + u[t * 3 + k]);
        }
        status[t] = r.final_i[t * AW_STATE_INTS + 3];
      }
      h.dataset(g, "position_turns", H5T_NATIVE_DOUBLE, {n, 3}, u.data());
      h.dataset(g, "winding", H5T_NATIVE_INT64, {n, 3}, winding.data());
      h.dataset(g, "momentum", H5T_NATIVE_DOUBLE, {n, 3}, split(r.final_r, 3).data());
      hid_t st = h.dataset(g, "status", H5T_NATIVE_INT64, {n}, status.data());
      h.attr(st, "meaning", std::string("0 ok, 1 non-finite, 2 energy error above the limit, 3 no initial "
                                        "state, 4 left the confinement region"));
      hid_t pos = h.dataset(g, "position", H5T_NATIVE_DOUBLE, {n, 3}, position.data());
      h.attr(pos, "meaning", std::string("2 pi (winding + position_turns): unwrapped, in radians"));
      h.attr(g, "digest", digest_final_states(r));
    }
  }
  detail::write_file_atomically(path, h.finish());
}

}  // namespace arnoldweb

namespace arnoldweb {

// indicators.h5 (docs/indicators.md): one dataset per indicator asked for, of
// the grid's shape (healpix: 12 nside^2 in RING order; lonlat and plane:
// [n2][n1], row = the second coordinate), the grid's coordinates, the scene.
void write_indicators_hdf5(const std::string& path, const Plan& plan, const Result& r) {
  const Scene& s = plan.scene;
  H5Writer h(path);
  {
    common_attributes(h, h.root(), plan, r);
    const hsize_t n = r.indicators.size() / AW_IND_REALS;
    std::vector<hsize_t> dims = {n};
    const bool grid = s.initial == "grid";
    if (grid && s.grid_kind != "healpix" && n == static_cast<hsize_t>(s.grid_resolution[0] * s.grid_resolution[1]))
      dims = {static_cast<hsize_t>(s.grid_resolution[1]), static_cast<hsize_t>(s.grid_resolution[0])};
    auto column = [&](int k) {
      std::vector<double> v(n);
      for (hsize_t t = 0; t < n; ++t) v[t] = r.indicators[t * AW_IND_REALS + k];
      return v;
    };
    struct Row {
      bool asked;
      const char* name;
      int slot;
      const char* meaning;
    };
    const Row rows[] = {
        {s.fli, "fli", AW_IND_FLI, "max over the run of log|w(t)|, |w(0)| = 1 (natural log)"},
        {s.megno, "megno", AW_IND_MEGNO, "mean MEGNO <Y>(t) at the end of the run (2: regular)"},
        {s.megno, "megno_lyapunov", AW_IND_MEGNO_LYAPUNOV, "slope of Y(t) against t (Y ~ lambda t): Lyapunov exponent, 1/T"},
        {s.lyapunov, "lyapunov", AW_IND_LYAPUNOV, "log|w(t)| / t at the end of the run: finite-time Lyapunov exponent, 1/T"},
    };
    for (const Row& row : rows) {
      if (!row.asked) continue;
      hid_t d = h.dataset(h.root(), row.name, H5T_NATIVE_DOUBLE, dims, column(row.slot).data());
      h.attr(d, "meaning", std::string(row.meaning) + "; NaN: trajectory flagged");
    }
    h.attr(h.root(), "duration", s.duration);
    h.attr(h.root(), "tangent_initial", s.tangent_initial);
    h.attr(h.root(), "digest", digest_indicators(r));
    if (grid) {
      hid_t g = h.group("grid");
      h.attr(g, "kind", s.grid_kind);
      h.attr(g, "position", s.grid_position);
      if (s.grid_kind == "healpix") {
        h.attr(g, "nside", static_cast<std::int64_t>(s.grid_nside));
        h.attr(g, "ordering", std::string("RING: trajectory i has its momentum along the centre of pixel i"));
      } else {
        auto centres = [](double lo, double hi, double count) {
          std::vector<double> c(static_cast<std::size_t>(count));
          for (std::size_t j = 0; j < c.size(); ++j) c[j] = lo + (static_cast<double>(j) + 0.5) * (hi - lo) / count;
          return c;
        };
        const bool lonlat = s.grid_kind == "lonlat";
        const auto a = lonlat ? centres(s.box_lon[0], s.box_lon[1], s.grid_resolution[0])
                              : centres(s.grid_range1[0], s.grid_range1[1], s.grid_resolution[0]);
        const auto b = lonlat ? centres(s.box_lat[0], s.box_lat[1], s.grid_resolution[1])
                              : centres(s.grid_range2[0], s.grid_range2[1], s.grid_resolution[1]);
        hid_t da = h.dataset(g, lonlat ? "lon" : "axis1", H5T_NATIVE_DOUBLE, {a.size()}, a.data());
        hid_t db = h.dataset(g, lonlat ? "lat" : "axis2", H5T_NATIVE_DOUBLE, {b.size()}, b.data());
        h.attr(da, "meaning", std::string(lonlat ? "longitude of the momentum direction, degrees (column i)"
                                                 : "momentum p[axes[0]] (column i)"));
        h.attr(db, "meaning", std::string(lonlat ? "latitude of the momentum direction, degrees (row j)"
                                                 : "momentum p[axes[1]] (row j)"));
        if (!lonlat) {
          h.attr(g, "axes", std::vector<double>{s.grid_axes[0], s.grid_axes[1]});
          h.attr(g, "fixed", s.grid_fixed);
        }
        h.attr(g, "ordering", std::string("trajectory j n1 + i is row j, column i (cell centres)"));
      }
    }
  }
  detail::write_file_atomically(path, h.finish());
}

}  // namespace arnoldweb
