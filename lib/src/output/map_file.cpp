// arnoldweb: map.h5, the velocity map (HEALPix RING), its frames and the
// zoom histogram, with what is needed to read them (nside, ordering, scene).
#include <vector>

#include "arnoldweb/output.hpp"
#include "output/atomic_file.hpp"
#include "output/h5_writer.hpp"

namespace arnoldweb {

using detail::H5Writer;

void write_map_hdf5(const std::string& path, const Plan& plan, const Result& r) {
  H5Writer h(path);
  {
    detail::run_attributes(h, h.root(), plan, r);
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

}  // namespace arnoldweb
