// Geometry on the sphere of directions (sphere.hpp): HEALPix RING pixel
// centres, as the kernels bin them, and the resonance circles m.P = 0; the
// two-sample chi-square test of two maps (analysis.hpp).
#include "bindings.hpp"

#include <nanobind/ndarray.h>
#include <nanobind/stl/string.h>

namespace awpy {
namespace {

nb::object pixel_directions(int nside) {
  if (nside < 1 || nside > 8192 || (nside & (nside - 1)) != 0)
    throw nb::value_error("nside must be a power of two from 1 to 8192");
  const std::uint64_t npix = 12ull * nside * nside;
  auto* data = new std::vector<double>(npix * 3);
  for (std::uint64_t p = 0; p < npix; ++p) {
    const arnoldweb::Vec3 v = arnoldweb::pix2vec_ring(nside, p);
    for (int k = 0; k < 3; ++k) (*data)[p * 3 + k] = v[k];
  }
  nb::capsule owner(data, [](void* d) noexcept { delete static_cast<std::vector<double>*>(d); });
  return nb::cast(nb::ndarray<nb::numpy, double>(data->data(), {static_cast<std::size_t>(npix), std::size_t(3)}, owner));
}

nb::list resonances(int max_order) {
  if (max_order < 1 || max_order > 20) throw nb::value_error("max_order must be from 1 to 20");
  nb::list out;
  for (const auto& r : arnoldweb::resonances(max_order)) {
    nb::dict d;
    d["m"] = nb::make_tuple(r.m[0], r.m[1], r.m[2]);
    d["order"] = r.order;
    d["label"] = r.label();
    out.append(d);
  }
  return out;
}

using Counts = nb::ndarray<const std::uint64_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

nb::dict compare_maps(Counts a, Counts b, double min_count) {
  const std::vector<std::uint64_t> va(a.data(), a.data() + a.shape(0)), vb(b.data(), b.data() + b.shape(0));
  arnoldweb::MapComparison c;
  try {
    c = arnoldweb::compare_maps(va, vb, min_count);
  } catch (const std::invalid_argument& e) {
    throw nb::value_error(e.what());
  }
  nb::dict d;
  d["chi2"] = c.chi2;
  d["dof"] = c.dof;
  d["chi2_per_dof"] = c.chi2_per_dof();
  d["p_value"] = c.p_value;
  d["total_a"] = c.total_a;
  d["total_b"] = c.total_b;
  d["bins"] = c.bins;
  d["used_bins"] = c.used_bins;
  d["pooled_bins"] = c.pooled_bins;
  d["empty_bins"] = c.empty_bins;
  return d;
}

}  // namespace

void bind_sphere(nb::module_& m) {
  m.def("pixel_directions", &pixel_directions, nb::arg("nside"),
        "Unit vectors to the centres of the HEALPix pixels in RING order, shape (12 nside^2, 3): "
        "the directions the velocity map bins (result.map[i] counts velocities near row i).");
  m.def("resonances", &resonances, nb::arg("max_order"),
        "The resonances m.P = 0 with max |m_i| <= max_order, lowest order first, as dicts (m, order, label); "
        "each is the great circle of directions P with m.P = 0.");
  m.def("compare_maps", &compare_maps, nb::arg("a"), nb::arg("b"), nb::arg("min_count") = 5.0,
        "The two-sample chi-square test of two count maps of the same size (docs/outputs.md).");
}

}  // namespace awpy
