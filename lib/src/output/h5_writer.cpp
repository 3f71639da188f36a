// arnoldweb: the attributes of every HDF5 file of a run (h5_writer.hpp).
#include "output/h5_writer.hpp"

#include "arnoldweb/version.hpp"

namespace arnoldweb::detail {

void run_attributes(H5Writer& h, hid_t where, const Plan& plan, const Result& r) {
  h.attr(where, "arnoldweb", std::string(ARNOLDWEB_VERSION));
  h.attr(where, "scene", plan.scene.to_toml());
  h.attr(where, "energy", plan.scene.energy);
  h.attr(where, "trajectories", static_cast<std::int64_t>(r.trajectories));
  h.attr(where, "binned", static_cast<std::int64_t>(r.binned));
  h.attr(where, "device", r.device.id + " (" + r.device.name + ")");
}

}  // namespace arnoldweb::detail
