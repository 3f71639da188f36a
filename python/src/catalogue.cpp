// What this build and machine offer: devices, methods, scene keys.
#include "bindings.hpp"

#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

namespace awpy {
namespace {

nb::dict device_dict(const arnoldweb::DeviceInfo& d) {
  nb::dict r;
  r["id"] = d.id;
  r["backend"] = d.backend;
  r["name"] = d.name;
  r["vendor"] = d.vendor;
  r["version"] = d.version;
  r["fp64"] = d.fp64;
  r["compute_units"] = d.compute_units;
  r["memory"] = d.memory;
  r["max_allocation"] = d.max_allocation;
  r["is_cpu"] = d.is_cpu;
  return r;
}

nb::list devices() {
  nb::list out;
  for (const auto& d : arnoldweb::list_devices()) out.append(device_dict(d));
  return out;
}

nb::list methods() {
  nb::list out;
  for (const auto& m : arnoldweb::methods()) {
    nb::dict r;
    r["name"] = m.name;
    r["title"] = m.title;
    r["source"] = m.source;
    r["order"] = m.order;
    r["eps_orders"] = arnoldweb::eps_order_string(m);
    r["stages"] = m.stages;
    r["kick_first"] = m.kick_first;
    r["family"] = m.family;
    r["stability"] = m.stability;
    r["drift"] = m.drift;
    r["kick"] = m.kick;
    r["gradient"] = m.gradient;  // force-gradient coefficients g_i (empty: none)
    r["work"] = m.work();        // cost of a step in plain force evaluations
    out.append(r);
  }
  return out;
}

nb::list scene_keys() {
  nb::list out;
  for (const auto& k : arnoldweb::scene_keys()) {
    nb::dict r;
    r["key"] = k.key;
    r["type"] = k.type;
    r["allowed"] = k.allowed;
    r["default"] = k.default_value;
    r["meaning"] = k.meaning;
    out.append(r);
  }
  return out;
}

}  // namespace

void bind_catalogue(nb::module_& m) {
  m.def("devices", &devices,
        "The devices present, cpu first, as dicts (id, backend, name, vendor, version, fp64, "
        "compute_units, memory, max_allocation, is_cpu).");
  m.def("backend_problems", &arnoldweb::backend_problems,
        "Why a backend contributes no device on this machine (one line each), e.g. no CUDA driver.");
  m.def("default_device", &arnoldweb::default_device_id, "The device id run.device = \"auto\" resolves to here.");
  m.def("methods", &methods,
        "The integration methods, as dicts (name, title, source, order, eps_orders, stages, "
        "kick_first, family, stability, drift and kick coefficients).");
  m.def("scene_keys", &scene_keys,
        "Every scene key, as dicts (key, type, allowed, default, meaning): the table of docs/scenes.md.");
  m.def("_output_fields", &arnoldweb::output_fields, nb::arg("output"),
        "The names of an output's real columns in column order (the output table's datasets of one "
        "column), or [] if they are not named one by one.");
}

}  // namespace awpy
