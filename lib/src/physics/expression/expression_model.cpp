// arnoldweb expression models: from the scene's text to the kernels (expression_model.hpp).
#include "physics/expression/expression_model.hpp"

#include <algorithm>
#include <cmath>

#include "physics/expression/parser.hpp"

namespace arnoldweb::detail::expression {

double ExpressionModel::value(double ux, double uy, double uz) const {
  Evaluator ev(potential->lowered);
  return ev.potential(ux, uy, uz, parameter_values);
}

std::array<double, 2> ExpressionModel::sampled_range() const {
  Evaluator ev(potential->lowered);
  constexpr int kN = 48;
  std::array<double, 2> r{INFINITY, -INFINITY};
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j)
      for (int k = 0; k < kN; ++k) {
        const double v = ev.potential(i / double(kN) - 0.5, j / double(kN) - 0.5, k / double(kN) - 0.5,
                                      parameter_values);
        r[0] = std::min(r[0], v);
        r[1] = std::max(r[1], v);
      }
  return r;
}

ExpressionModel make_expression_model(const std::string& text,
                                      const std::vector<std::pair<std::string, double>>& parameters) {
  std::vector<std::string> names;
  ExpressionModel m;
  for (const auto& [name, value] : parameters) {
    std::string why;
    if (!valid_parameter_name(name, &why)) throw ExpressionError(0, "parameter " + why);
    if (std::find(names.begin(), names.end(), name) != names.end())
      throw ExpressionError(0, "parameter \"" + name + "\" is given twice");
    if (!std::isfinite(value)) throw ExpressionError(0, "parameter \"" + name + "\" is not a finite number");
    names.push_back(name);
    m.parameter_values.push_back(value);
  }
  auto p = std::make_shared<Potential>(compile_potential(text, names));
  check_periodic(*p, m.parameter_values);
  EmitOptions o;
  o.source = text;
  o.parameter_names = names;
  o.parameter_base = kFirstParameter;
  o.kinetic = true;
  m.device_header = emit_device_header(p->lowered, o);
  m.potential = std::move(p);
  return m;
}

std::vector<std::array<int, 3>> wave_vectors(const ExpressionModel& m) {
  const Graph& g = m.potential->lowered.graph;
  Evaluator ev(m.potential->lowered);
  const std::vector<double> at0 = ev.nodes(0, 0, 0, m.parameter_values);
  std::vector<double> quarter[3], half[3];
  for (int i = 0; i < 3; ++i) {
    double u[3] = {0, 0, 0};
    u[i] = 0.25;
    quarter[i] = ev.nodes(u[0], u[1], u[2], m.parameter_values);
    u[i] = 0.5;
    half[i] = ev.nodes(u[0], u[1], u[2], m.parameter_values);
  }
  std::vector<std::array<int, 3>> out;
  for (int id = 0; id < g.size(); ++id) {
    if (g[id].op != Op::SinTurns && g[id].op != Op::CosTurns) continue;
    const auto a = static_cast<std::size_t>(g[id].a);
    std::array<int, 3> k{};
    bool linear = true;
    for (int i = 0; i < 3; ++i) {
      const double d1 = quarter[i][a] - at0[a], d2 = half[i][a] - at0[a];  // turns per quarter turn of u_i
      linear = linear && std::fabs(d2 - 2 * d1) <= 1e-9 * (1 + std::fabs(d2));
      const double ki = 4 * d1;
      k[static_cast<std::size_t>(i)] = static_cast<int>(std::fabs(ki - std::rint(ki)) < 1e-6
                                                            ? std::rint(ki)
                                                            : (ki > 0 ? std::ceil(ki) : std::floor(ki)));
    }
    if (!linear || (k[0] == 0 && k[1] == 0 && k[2] == 0)) continue;
    const int first = k[0] != 0 ? k[0] : k[1] != 0 ? k[1] : k[2];
    if (first < 0) k = {-k[0], -k[1], -k[2]};
    if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
  }
  return out;
}

void fill_parameter_slots(const ExpressionModel& m, double* model, int slots) {
  const int n = static_cast<int>(m.parameter_values.size());
  if (kFirstParameter + n > slots)
    throw ExpressionError(0, std::to_string(n) + " parameters are more than the " +
                                 std::to_string(slots - kFirstParameter) + " an expression model can hold");
  for (int i = 0; i < n; ++i) model[kFirstParameter + i] = m.parameter_values[static_cast<std::size_t>(i)];
}

}  // namespace arnoldweb::detail::expression
