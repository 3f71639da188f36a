// arnoldweb: what a model is to the host. A built-in model is its device
// header (lib/device/models/aw_<name>.h) and ONE descriptor
// (lib/src/physics/models/<name>.cpp): its parameters (scene key, slot in the
// kernels' rp.model, default, allowed range, help) and its capabilities (the
// kinetic form, bounds on V and on its Hessian, the wave vectors of its
// harmonics). The scene keys of the parameters, the filling of rp.model, the
// check of other models' keys, the echo of the scene, `arnoldweb models`, the
// help of model.kind and the tests' model lists all follow from the list of
// descriptors (model_table.hpp). Physics knows no scene: a model is given the
// values of its keys as written (ModelValues).
#pragma once

#include <array>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "params/kernel_params.hpp"
#include "physics/host_model.hpp"

// A built-in model's id: its AW_MODEL_<NAME> in the kernels (-DAW_MODEL=<id>), in kernel caches
// and in the kernel lines of run summaries. Declared once, in its descriptor, as a line
// "AW_MODEL_ID(<id>);": cmake/ArnoldwebModels.cmake reads it there, refuses a descriptor without
// one and two models with one id, and generates the dispatch and the table's list in the order of
// the ids. An id is never changed or given again: a new model takes a free one.
#define AW_MODEL_ID(id) static_assert((id) >= 0 && (id) < 1000, "a model id is 0 to 999 (1000: expression models)")

namespace arnoldweb::detail {

// A model parameter's values as written in a scene, by key (a number, an array,
// or a table's rows flattened); a key not written takes its default.
using ModelValues = std::map<std::string, std::vector<double>>;

// One scene key of a model.
struct ModelParameter {
  std::string key;      // "model.epsilon"
  std::string type;     // as the docs show it: "float", "array of 3 floats", ...
  std::string allowed;  // as the docs show it: ">= 0 and <= 1"
  std::string must;     // what a value must be, completing "must be ...": "a float from 0 to 1"
  std::string help;     // what it means (docs/scenes.md, `arnoldweb keys`)
  int width = 1;        // values per row
  int max_rows = 0;     // 0: one row (a number, or a fixed array of `width`); else a table of 1 to max_rows rows
  int integer_columns = 0;  // a row's first columns are integers (the echo writes them so)
  double lo = -1e300, hi = 1e300;  // every value within [lo, hi], and finite
  std::vector<double> default_value;  // its rows, flattened
  // Further checks of the values as read: "" or what is wrong, e.g. " (harmonic 2): k = 0 is a constant".
  std::function<std::string(const std::vector<double>&)> check = nullptr;
  int slot = 0;  // rp.model[slot ...] receive the values in order, unless `place` does it
  std::function<void(const std::vector<double>&, double* model)> place = nullptr;

  bool is_number() const { return width == 1 && max_rows == 0; }
};

struct ModelDescriptor {
  std::string name;     // model.kind
  int id = 0;           // AW_MODEL_* (generated: cmake/ArnoldwebModels.cmake)
  std::string title;    // human name and source
  std::string formula;  // H, as text
  std::string notes;    // about its parameters, for `arnoldweb models`
  std::vector<ModelParameter> parameters;
  // Keys of its own that are not numbers (an expression model's potential and
  // its named parameters): the scene layer reads them itself.
  std::vector<std::string> text_keys;

  // Capabilities, from its slots of the real parameters:
  // kinetic coefficients {a_x, a_y, a_z, b_x, b_y, b_z}: T = sum a_i p_i^2 / 2 + b_i p_i
  std::function<std::array<double, 6>(const RealParams& rp)> kinetic;
  // bounds of V over the torus: v[0] <= V <= v[1]
  std::function<std::array<double, 2>(const RealParams& rp)> v_range;
  // a bound on the norm of the Hessian of V (radians^-2)
  std::function<double(const RealParams& rp)> hessian_bound;
  // the wave vectors k of its harmonics (the step-size guard and the resonance circles m.P = 0)
  std::function<std::vector<std::array<int, 3>>(const RealParams& rp)> wave_vectors;
  // its own closed-form largest frequency at energy E (the paper's guard), or null
  std::function<double(double energy, const RealParams& rp)> closed_frequency = nullptr;
  // its effective perturbation at energy E (the paper's 2/E), for plans; or null
  std::function<double(double energy)> effective_perturbation = nullptr;
  // The resonance overlay of its maps draws every circle m.P = 0 of low order
  // (a potential whose harmonics make the whole web, like the paper's), or else
  // the circles k.V = 0 of its own wave vectors.
  bool overlay_all_resonances = false;

  // Its device code on the host (the built-ins' from host_model.cpp.in; an
  // expression model's from its compiled potential).
  std::function<double(double ux, double uy, double uz, const RealParams& rp)> potential;
  std::function<bool(int kind, std::uint64_t index, const RealParams& rp, const IntParams& ip, double* u,
                     double* p)>
      initial_state;
  std::function<bool(double ke, const double* n, const RealParams& rp, double& s)> speed;
  // A built-in's whole device interface on the host (its header compiled in
  // double: host_model.cpp.in); nullptr for an expression model.
  const HostModel* host = nullptr;

  // An expression model's device header (compiled at run time by OpenCL and
  // CUDA as models/aw_expression.h) and what it adds to rp.model; empty for the built-ins.
  std::string device_source;
  std::function<void(RealParams& rp)> fill_more = nullptr;

  // Its scene keys: its parameters', then its text keys.
  std::vector<std::string> keys() const;
  // rp.model from the values written (the others take their defaults).
  void fill(const ModelValues& written, RealParams& rp) const;
  // The parameter of a key, or nullptr.
  const ModelParameter* parameter(const std::string& key) const;
};

// A value that is wrong for its model, found while making a model's row (an
// expression that does not parse, ...): the key and why. The planner reports
// it where the scene wrote the key.
class ModelError : public std::runtime_error {
 public:
  ModelError(std::string key, const std::string& message) : std::runtime_error(message), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

}  // namespace arnoldweb::detail
