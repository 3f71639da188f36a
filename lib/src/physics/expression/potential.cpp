// arnoldweb expression models: compile and check a potential (potential.hpp).
#include "physics/expression/potential.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/expression/derivative.hpp"
#include "physics/expression/parser.hpp"

namespace arnoldweb::detail::expression {

Potential compile_potential(const std::string& text, const std::vector<std::string>& parameters) {
  Potential p;
  p.text = text;
  p.parameters = parameters;
  RadianForm& r = p.radians;
  r.value = parse(r.graph, text, parameters);
  try {
    Differentiator d(r.graph);
    for (int i = 0; i < 3; ++i) r.gradient[static_cast<std::size_t>(i)] = d.d(r.value, i);
    static const int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
    for (std::size_t k = 0; k < 6; ++k) r.hessian[k] = d.d(r.gradient[static_cast<std::size_t>(pairs[k][0])], pairs[k][1]);
  } catch (const FoldError& e) {
    throw ExpressionError(0, "while differentiating: " + e.message);
  }
  if (r.graph.size() > kMaxNodes)
    throw ExpressionError(0, "too complex: V, its gradient and its Hessian take " + std::to_string(r.graph.size()) +
                                 " operations (at most " + std::to_string(kMaxNodes) + ")");
  p.lowered = lower(r);
  return p;
}

namespace {

const char* const kCoordinate[] = {"x", "y", "z"};

std::string point_text(double ux, double uy, double uz) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "(x, y, z) = (%.6g, %.6g, %.6g)", ux * kTwoPi, uy * kTwoPi, uz * kTwoPi);
  return buf;
}

}  // namespace

void check_periodic(const Potential& p, const std::vector<double>& values) {
  Evaluator ev(p.lowered);
  // 9 x 9 x 9 points u = j/8 - 1/2 + 1/64 (few bits: u + 1 is exact), and
  // offsets 1/64 off the quarter turns, where many potentials are symmetric
  constexpr int kN = 9;
  std::vector<double> grid;
  for (int j = 0; j < kN; ++j) grid.push_back(j / 8.0 - 0.5 + 1.0 / 64 + (j % 3) / 256.0);
  double scale = 0;
  struct Sample {
    double u[3];
    double v;
  };
  std::vector<Sample> samples;
  for (double ux : grid)
    for (double uy : grid)
      for (double uz : grid) {
        const PointValues pv = ev.all(ux, uy, uz, values);
        if (!std::isfinite(pv.value))
          throw ExpressionError(0, "V is not finite at " + point_text(ux, uy, uz) + " (V = " +
                                       std::to_string(pv.value) + ")");
        for (int i = 0; i < 3; ++i)
          if (!std::isfinite(pv.force[static_cast<std::size_t>(i)]))
            throw ExpressionError(0, std::string("the force -dV/d") + kCoordinate[i] + " is not finite at " +
                                         point_text(ux, uy, uz) + " (V is not smooth there)");
        scale = std::max(scale, std::fabs(pv.value));
        samples.push_back({{ux, uy, uz}, pv.value});
      }
  const double tolerance = 1e-9 * std::max(scale, 1e-300);
  for (const Sample& s : samples)
    for (int i = 0; i < 3; ++i) {
      double u[3] = {s.u[0], s.u[1], s.u[2]};
      u[i] += 1.0;  // one turn: x_i + 2 pi
      const double shifted = ev.potential(u[0], u[1], u[2], values);
      if (!(std::fabs(shifted - s.v) <= tolerance)) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "V is not 2*pi-periodic in %s: V(%s + 2 pi) - V = %.6g at ", kCoordinate[i],
                      kCoordinate[i], shifted - s.v);
        throw ExpressionError(0, buf + point_text(s.u[0], s.u[1], s.u[2]) +
                                     " (a potential on the 3-torus needs integer multiples of x, y, z inside "
                                     "sin and cos)");
      }
    }
}

}  // namespace arnoldweb::detail::expression
