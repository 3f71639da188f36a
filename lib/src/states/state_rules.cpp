// arnoldweb: the rules of initial states (state_rules.hpp) and states from arrays (states.hpp).
#include "states/state_rules.hpp"

#include <cmath>

#include "arnoldweb/errors.hpp"

namespace arnoldweb::detail {
namespace {

constexpr double kTwoPi = 6.283185307179586476925;

bool finite3(const double* v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

}  // namespace

std::string show_row(const double* v) {
  return "(" + show_number(v[0]) + ", " + show_number(v[1]) + ", " + show_number(v[2]) + ")";
}

void StateRows::fail(const std::string& dataset, std::uint64_t row, const std::string& message) const {
  throw StateError(source_, dataset, static_cast<std::int64_t>(row), message);
}

void StateRows::check_status(const StateSet& s, const std::string& dataset) const {
  for (std::uint64_t i = 0; i < s.count; ++i)
    if (s.status[i] < 0 || s.status[i] > 4)
      fail(dataset, i, "status " + std::to_string(s.status[i]) +
                           " is none of 0 (ok), 1 (non-finite), 2 (energy error), 3 (no initial state), 4 (left the "
                           "confinement region)");
}

void StateRows::set_positions(StateSet& s, const std::vector<double>& positions, PositionUnits units,
                              const std::vector<std::int64_t>* winding, const std::string& dataset,
                              const std::string& winding_dataset) const {
  const bool radians = units == PositionUnits::Radians;
  const double half = radians ? kTwoPi / 2 : 0.5;  // kTwoPi / 2 is M_PI exactly
  s.position_turns.assign(3 * s.count, 0);
  s.winding.assign(3 * s.count, 0);
  for (std::uint64_t i = 0; i < s.count; ++i) {
    const double* x = &positions[3 * i];
    const bool checked = s.status[i] == 0;
    if (checked && !finite3(x)) fail(dataset, i, "the position " + show_row(x) + " is not finite");
    for (int k = 0; k < 3; ++k) {
      const double u = radians ? x[k] / kTwoPi : x[k];
      double& wrapped = s.position_turns[3 * i + k];
      std::int64_t& whole = s.winding[3 * i + k];
      if (winding) {
        if (checked && std::fabs(x[k]) > half)
          fail(dataset, i,
               "the position " + show_row(x) + " is out of range: with " + winding_dataset +
                   ", positions are the wrapped part, within [-1/2, 1/2] turns ([-pi, pi] radians); leave " +
                   winding_dataset + " out to give unwrapped positions");
        wrapped = u;
        whole = (*winding)[3 * i + k];
      } else if (std::isfinite(u) && std::fabs(u) <= kMaxStateTurns) {
        wrapped = wrapped_turns(u);  // exact: |u| <= 2^52
        whole = static_cast<std::int64_t>(u - wrapped);
      } else {
        if (checked)
          fail(dataset, i,
               "the position " + show_row(x) + " is out of range: at most 2^52 turns from the origin (" +
                   (radians ? "2.8e16 radians" : "4.5e15 turns") + ")");
        wrapped = u;  // a flagged row, kept as it is
      }
    }
  }
}

void StateRows::check_momenta(const StateSet& s, const std::string& dataset) const {
  for (std::uint64_t i = 0; i < s.count; ++i)
    if (s.status[i] == 0 && !finite3(&s.momentum[3 * i]))
      fail(dataset, i, "the momentum " + show_row(&s.momentum[3 * i]) + " is not finite");
}

}  // namespace arnoldweb::detail

namespace arnoldweb {

StateSet states_from_arrays(const double* positions, std::size_t position_rows, std::size_t position_columns,
                            const double* momenta, std::size_t momentum_rows, std::size_t momentum_columns,
                            PositionUnits units, const std::string& source) {
  auto shape = [&](const char* name, std::size_t rows, std::size_t columns) {
    if (columns != 3 || rows == 0)
      throw StateError(source, name, -1,
                       "has the shape (" + std::to_string(rows) + ", " + std::to_string(columns) +
                           "); it must be (N, 3) with N >= 1, one row per state");
  };
  shape("X", position_rows, position_columns);
  shape("P", momentum_rows, momentum_columns);
  if (position_rows != momentum_rows)
    throw StateError(source, "P", -1,
                     "has " + std::to_string(momentum_rows) + " rows and X " + std::to_string(position_rows) +
                         ": one row per state in each");
  StateSet s;
  s.source = source;
  s.count = position_rows;
  s.status.assign(s.count, 0);
  s.momentum.assign(momenta, momenta + 3 * s.count);
  const detail::StateRows rows(source);
  rows.set_positions(s, std::vector<double>(positions, positions + 3 * s.count), units, nullptr, "X", "");
  rows.check_momenta(s, "P");
  return s;
}

}  // namespace arnoldweb
