// Initial states given as arrays (aw.run(scene, initial=(X, P)),
// aw.check_states): the library's rules for states (states.hpp), the same as
// for a state file. X and P arrive as float64 arrays of any shape; the
// library checks the shapes (N, 3), so its messages are the CLI's.
#include "bindings.hpp"

#include <nanobind/ndarray.h>
#include <nanobind/stl/string.h>

namespace awpy {
namespace {

std::size_t rows_of(const Rows& a) { return a.ndim() >= 1 ? a.shape(0) : 0; }
std::size_t columns_of(const Rows& a) { return a.ndim() == 2 ? a.shape(1) : (a.ndim() == 1 ? 1 : 0); }

}  // namespace

std::shared_ptr<arnoldweb::StateSet> states_of(const arnoldweb::Scene& scene, Rows x, Rows p, const std::string& units) {
  if (units != "radians" && units != "turns")
    throw arnoldweb::StateError("initial", "", -1,
                                "units is \"" + units + "\"; it must be \"radians\" or \"turns\"");
  auto s = std::make_shared<arnoldweb::StateSet>();
  nb::gil_scoped_release unlocked;
  *s = arnoldweb::states_from_arrays(x.data(), rows_of(x), columns_of(x), p.data(), rows_of(p), columns_of(p),
                                     units == "turns" ? arnoldweb::PositionUnits::Turns
                                                      : arnoldweb::PositionUnits::Radians,
                                     "initial");
  arnoldweb::check_states(*s, scene);
  return s;
}

namespace {

nb::dict check_states(const arnoldweb::Scene& scene, Rows x, Rows p, const std::string& units) {
  arnoldweb::StateSet s = *states_of(scene, x, p, units);
  auto* energy = new std::vector<double>(std::move(s.energy));
  nb::capsule owner(energy, [](void* v) noexcept { delete static_cast<std::vector<double>*>(v); });
  nb::dict d;
  d["count"] = s.count;
  d["energy"] = nb::ndarray<nb::numpy, const double>(energy->data(), {energy->size()}, owner);
  d["energy_min"] = s.energy_min;
  d["energy_max"] = s.energy_max;
  return d;
}

}  // namespace

void bind_states(nb::module_& m) {
  m.def("_check_states", &check_states, nb::arg("scene"), nb::arg("x"), nb::arg("p"), nb::arg("units"),
        "Checks initial states given as arrays against the scene's model; returns count, energy (per state), "
        "energy_min, energy_max. Raises StateError naming the row.");
}

}  // namespace awpy
