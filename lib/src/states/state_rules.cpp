// arnoldweb: the rules of initial states (state_rules.hpp) and states from arrays (states.hpp).
#include "states/state_rules.hpp"

#include <cmath>

#include "arnoldweb/errors.hpp"

namespace arnoldweb::detail {
namespace {

constexpr double kTwoPi = 6.283185307179586476925;
constexpr auto kMaxStateWinding = static_cast<std::int64_t>(kMaxStateTurns);  // 2^52

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
        const std::int64_t w = (*winding)[3 * i + k];
        if (checked && (w > kMaxStateWinding || w < -kMaxStateWinding))
          fail(winding_dataset, i,
               "the winding count " + std::to_string(w) +
                   " is out of range: at most 2^52 whole turns (4503599627370496) either way, as for unwrapped "
                   "positions (docs/outputs.md, \"State files\")");
        if (checked && std::fabs(x[k]) > half)
          fail(dataset, i,
               "the position " + show_row(x) + " is out of range: with " + winding_dataset +
                   ", positions are the wrapped part, within [-1/2, 1/2] turns ([-pi, pi] radians); leave " +
                   winding_dataset + " out to give unwrapped positions");
        wrapped = u;
        whole = w;
      } else if (std::isfinite(u) && std::fabs(u) <= kMaxStateTurns) {
        const double w = std::nearbyint(u);  // exact: |u| <= 2^52
        wrapped = u - w;
        whole = static_cast<std::int64_t>(w);
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

void check_start_time(const StateSet& s, double duration) {
  if (!s.has_time || !(duration > 0)) return;
  const double end = s.time + duration;
  const double spacing = std::nextafter(end, HUGE_VAL) - end;  // between doubles at the end time
  if (std::isfinite(end) && spacing <= std::ldexp(duration, -20)) return;
  // the largest time whose end time keeps that resolution: below 2^(33 + floor(log2 duration))
  const double most = std::ldexp(1.0, 33 + std::ilogb(duration)) - duration;
  throw StateError(s.source, "", -1,
                   "the attribute time is " + show_number(s.time) + " T, too large for run.duration = " +
                       show_number(duration) + ": doubles there are " + show_number(spacing) +
                       " T apart, so the run's end time (time + run.duration) would not be its start plus " +
                       show_number(duration) + " T; with this run.duration the time must be below " +
                       show_number(most) + " T (about 2^32 durations: the end time then exact to 2^-20 of the "
                       "duration)");
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
