// arnoldweb Python module (_arnoldweb): what the binding files share. Each
// file binds one concern of the library's public API (lib/include/arnoldweb);
// the package python/arnoldweb builds the user-facing API on top.
#pragma once

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/ndarray.h>

#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "arnoldweb/arnoldweb.hpp"

namespace awpy {
namespace nb = nanobind;

// json.loads(text): the library writes JSON (summary.json, the scene echo);
// Python gets the same values as dicts.
nb::object json_loads(const std::string& text);

// The scene as run planned into a job, "auto" steps resolved on the cpu
// backend like the CLI does (cli/scene_args.cpp). Releases the GIL.
// Arrays of rows of numbers, as numpy hands them (initial states).
using Rows = nb::ndarray<const double, nb::c_contig, nb::device::cpu>;
// Initial states from positions (radians or turns) and momenta, checked against
// the scene's model with the rules of a state file (StateError naming the row).
std::shared_ptr<arnoldweb::StateSet> states_of(const arnoldweb::Scene& scene, Rows x, Rows p, const std::string& units);

// With `states`: the initial states of a scene whose ensemble.initial is "file" (Python's initial=).
arnoldweb::Job plan_scene(const arnoldweb::Scene& scene, std::shared_ptr<const arnoldweb::StateSet> states = nullptr);

// A fresh numpy array owning `values` (for what the library does not hold
// contiguously, or what was read from a file).
template <class T>
nb::object owned(std::vector<T> values, std::initializer_list<std::size_t> shape) {
  auto* data = new std::vector<T>(std::move(values));
  nb::capsule owner(data, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
  return nb::cast(nb::ndarray<nb::numpy, T>(data->data(), shape, owner));
}

// A finished (or interrupted) run of a job: what Result objects view.
struct RunRecord {
  arnoldweb::Job job;
  arnoldweb::JobResult result;
  std::string written_dir;             // where write() last put the outputs ("": not written)
  std::vector<std::string> files;      // the paths it wrote
  nb::object stop_exception;           // what stopped the run early (KeyboardInterrupt, ...), or None
  std::exception_ptr write_error;      // why writing the outputs failed, if it did
};

void bind_errors(nb::module_& m);
void bind_catalogue(nb::module_& m);
void bind_scene(nb::module_& m);
void bind_result(nb::module_& m);
void bind_run(nb::module_& m);
void bind_accuracy(nb::module_& m);
void bind_sphere(nb::module_& m);
void bind_saved(nb::module_& m);
void bind_states(nb::module_& m);
void bind_model(nb::module_& m);

}  // namespace awpy
