// arnoldweb: the model table (model_table.hpp) and what every descriptor
// shares (model_descriptor.hpp). The built-ins come from the generated list
// (cmake/ArnoldwebModels.cmake): one AW_MODEL_ENTRY per device header, its
// descriptor (models/<name>.cpp) and its host code (host_model_<name>.cpp).
#include "physics/model_table.hpp"

#include <algorithm>
#include <cmath>

#include "arnoldweb/models.hpp"
#include "aw_cpp_std.h"
#include "physics/expression/expression_model.hpp"

namespace arnoldweb::detail {

#define AW_MODEL_ENTRY(name, id) \
  ModelDescriptor describe_##name(); \
  const HostModel& host_model_##name();
#include "model_list.inc"
#undef AW_MODEL_ENTRY

namespace host_base {
#include "aw_rng.h"
}  // namespace host_base

namespace {

constexpr double kTwoPi = 6.283185307179586476925;

ModelDescriptor built_in(ModelDescriptor d, const char* name, int id, const HostModel& host) {
  d.name = name;
  d.id = id;
  d.potential = host.potential;
  d.initial_state = host.initial_state;
  d.speed = host.speed;
  d.host = &host;
  return d;
}

// The table's row of the kind "expression": what every expression model
// shares; a scene's own row, with its compiled potential, is made by
// expression_row (expression/expression_row.cpp).
ModelDescriptor expression_kind() {
  ModelDescriptor r;
  r.name = "expression";
  r.id = expression::kExpressionModelId;
  r.title = "A potential written in the scene, differentiated and compiled at run time (OpenCL, CUDA)";
  r.formula = "H = sum_i a_i p_i^2/2 + sum_i b_i p_i + V(x, y, z), V = model.potential";
  r.notes = "model.potential = \"...\" (x, y, z, + - * / ^ sin cos exp sqrt pi), model.parameters = "
            "{ name = value, ... }, model.kinetic_a, model.kinetic_b as for fourier (docs/models.md)";
  r.parameters = {kinetic_a_parameter(), kinetic_b_parameter()};
  r.text_keys = {"model.potential", "model.parameters"};
  r.kinetic = kinetic_in_slots;
  return r;
}

std::vector<ModelDescriptor> build() {
  std::vector<ModelDescriptor> rows;
#define AW_MODEL_ENTRY(name, id) rows.push_back(built_in(describe_##name(), #name, id, host_model_##name()));
#include "model_list.inc"
#undef AW_MODEL_ENTRY
  rows.push_back(expression_kind());
  return rows;
}

ModelParameter kinetic_triple(const char* key, int slot) {
  ModelParameter p;
  p.key = key;
  p.type = "array of 3 floats";
  p.width = 3;
  p.slot = slot;
  return p;
}

}  // namespace

// ------------------------------------------------------------- descriptors
std::vector<std::string> ModelDescriptor::keys() const {
  std::vector<std::string> k;
  for (const ModelParameter& p : parameters) k.push_back(p.key);
  k.insert(k.end(), text_keys.begin(), text_keys.end());
  return k;
}

const ModelParameter* ModelDescriptor::parameter(const std::string& key) const {
  for (const ModelParameter& p : parameters)
    if (p.key == key) return &p;
  return nullptr;
}

void ModelDescriptor::fill(const ModelValues& written, RealParams& rp) const {
  for (const ModelParameter& p : parameters) {
    const auto it = written.find(p.key);
    const std::vector<double>& v = it != written.end() ? it->second : p.default_value;
    if (p.place) {
      p.place(v, rp.model);
    } else {
      for (std::size_t i = 0; i < v.size(); ++i) rp.model[static_cast<std::size_t>(p.slot) + i] = v[i];
    }
  }
  if (fill_more) fill_more(rp);
}

ModelParameter kinetic_a_parameter() {
  ModelParameter p = kinetic_triple("model.kinetic_a", 0);
  p.allowed = ">= 0";
  p.must = "an array [a_x, a_y, a_z] of floats >= 0";
  p.help = "the quadratic kinetic coefficients of T = sum a_i p_i^2/2 + b_i p_i.";
  p.lo = 0;
  p.hi = 1e6;
  p.default_value = {1, 1, 1};
  return p;
}

ModelParameter kinetic_b_parameter() {
  ModelParameter p = kinetic_triple("model.kinetic_b", 3);
  p.allowed = "finite";
  p.must = "an array [b_x, b_y, b_z] of finite floats";
  p.help = "the linear kinetic coefficients of T = sum a_i p_i^2/2 + b_i p_i.";
  p.lo = -1e6;
  p.hi = 1e6;
  p.default_value = {0, 0, 0};
  return p;
}

// ------------------------------------------------------------- the table
const std::vector<ModelDescriptor>& models() {
  static const std::vector<ModelDescriptor> rows = build();
  return rows;
}

const ModelDescriptor* find_model(const std::string& name) {
  for (const ModelDescriptor& m : models())
    if (m.name == name) return &m;
  return nullptr;
}

std::array<double, 6> kinetic_in_slots(const RealParams& rp) {
  return {rp.model[0], rp.model[1], rp.model[2], rp.model[3], rp.model[4], rp.model[5]};
}

bool standard_kinetic(const ModelDescriptor& model, const RealParams& rp) {
  return model.kinetic(rp) == std::array<double, 6>{1, 1, 1, 0, 0, 0};
}

bool energy_bounds_momenta(const ModelDescriptor& model, const RealParams& rp) {
  const auto k = model.kinetic(rp);
  return k[0] > 0 && k[1] > 0 && k[2] > 0;
}

double accessible_fraction(const ModelDescriptor& model, const RealParams& rp, double energy) {
  constexpr int kSamples = 1 << 16;
  int inside = 0;
  for (int i = 0; i < kSamples; ++i) {
    double a, b, c, d;
    host_base::aw_uniform2(0x5eedULL, static_cast<std::uint64_t>(i), 0u, 0u, &a, &b);
    host_base::aw_uniform2(0x5eedULL, static_cast<std::uint64_t>(i), 0u, 1u, &c, &d);
    if (model.potential(a - 0.5, b - 0.5, c - 0.5, rp) < energy) ++inside;
  }
  return static_cast<double>(inside) / kSamples;
}

double reachable_fraction(const ModelDescriptor& model, const RealParams& rp, double energy) {
  constexpr int kSamples = 1 << 16;
  int reached = 0;
  for (int i = 0; i < kSamples; ++i) {
    double a, b, c, d, e, f;
    host_base::aw_uniform2(0x5eedULL, static_cast<std::uint64_t>(i), 0u, 0u, &a, &b);
    host_base::aw_uniform2(0x5eedULL, static_cast<std::uint64_t>(i), 0u, 1u, &c, &d);
    host_base::aw_uniform2(0x5eedULL, static_cast<std::uint64_t>(i), 0u, 2u, &e, &f);
    const double ct = 2.0 * d - 1.0, st = std::sqrt((1.0 - ct) * (1.0 + ct));
    const double n[3] = {st * std::cos(kTwoPi * e), st * std::sin(kTwoPi * e), ct};
    double s = 0;
    if (model.speed(energy - model.potential(a - 0.5, b - 0.5, c - 0.5, rp), n, rp, s)) ++reached;
  }
  return static_cast<double>(reached) / kSamples;
}

}  // namespace arnoldweb::detail

namespace arnoldweb {

std::vector<ModelInfo> model_list() {
  std::vector<ModelInfo> out;
  for (const detail::ModelDescriptor& m : detail::models())
    out.push_back({m.name, m.title, m.formula, m.notes, m.keys()});
  return out;
}

}  // namespace arnoldweb
