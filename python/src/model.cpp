// The scene's model evaluated on the host (models.hpp: SceneModel): V(X),
// H(X, P) and the momenta on the energy shell for given directions, over rows
// of three (arnoldweb._model broadcasts and shapes the arrays), with the GIL
// released. Positions in radians or turns, as for initial states.
#include "bindings.hpp"

#include <nanobind/stl/string.h>

#include <cmath>
#include <limits>

#include "arnoldweb/models.hpp"

namespace awpy {
namespace {

using Rows3 = nb::ndarray<const double, nb::ndim<2>, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu>;

// What positions in `units` are divided by to give turns (2 pi for radians, as states are read; 0: turns)
double turns_per_unit(const std::string& units) {
  if (units == "turns") return 0;
  if (units == "radians") return 6.283185307179586476925;
  throw nb::value_error(("units is \"" + units + "\"; it must be \"radians\" or \"turns\"").c_str());
}

// Calls each(model, u, row) for every row with u in turns; returns a fresh array of `width` per row.
template <class Each>
nb::object per_row(const arnoldweb::Scene& scene, const Rows3& x, const std::string& units, std::size_t width,
                   Each each) {
  const double divide = turns_per_unit(units);
  const std::size_t n = x.shape(0);
  std::vector<double> out(n * width);
  {
    nb::gil_scoped_release unlocked;
    const arnoldweb::SceneModel model(scene);
    for (std::size_t i = 0; i < n; ++i) {
      double u[3];
      for (int k = 0; k < 3; ++k) u[k] = divide ? x(i, k) / divide : x(i, k);
      each(model, u, i, &out[i * width]);
    }
  }
  return width == 1 ? owned(std::move(out), {n}) : owned(std::move(out), {n, width});
}

nb::object potential(const arnoldweb::Scene& scene, Rows3 x, const std::string& units) {
  return per_row(scene, x, units, 1, [](const arnoldweb::SceneModel& m, const double* u, std::size_t, double* out) {
    *out = m.potential(u);
  });
}

nb::object energy(const arnoldweb::Scene& scene, Rows3 x, Rows3 p, const std::string& units) {
  return per_row(scene, x, units, 1, [&p](const arnoldweb::SceneModel& m, const double* u, std::size_t i, double* out) {
    const double row[3] = {p(i, 0), p(i, 1), p(i, 2)};
    *out = m.hamiltonian(u, row);
  });
}

// n: unit directions; rows without a momentum on the shell are NaN
nb::object shell_momenta(const arnoldweb::Scene& scene, Rows3 x, Rows3 n, const std::string& units) {
  return per_row(scene, x, units, 3, [&n](const arnoldweb::SceneModel& m, const double* u, std::size_t i, double* out) {
    const double d[3] = {n(i, 0), n(i, 1), n(i, 2)};
    if (!m.shell_momentum(u, d, out)) out[0] = out[1] = out[2] = std::numeric_limits<double>::quiet_NaN();
  });
}

}  // namespace

void bind_model(nb::module_& m) {
  m.def("_potential", &potential, nb::arg("scene"), nb::arg("x"), nb::arg("units"),
        "V(X) of the scene's model for rows of positions (N, 3).");
  m.def("_energy", &energy, nb::arg("scene"), nb::arg("x"), nb::arg("p"), nb::arg("units"),
        "H = T(P) + V(X) of the scene's model for rows of positions and momenta (N, 3).");
  m.def("_shell_momenta", &shell_momenta, nb::arg("scene"), nb::arg("x"), nb::arg("n"), nb::arg("units"),
        "P = s n on the shell H = model.energy for rows of positions and unit directions (N, 3); NaN where none.");
}

}  // namespace awpy
