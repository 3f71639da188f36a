// arnoldweb: a researcher's own initial states (issue 25, item 1):
// ensemble.initial = "file" with ensemble.file = "path.h5", or arrays from
// Python (aw.run(scene, initial=(X, P))). The HDF5 schema is documented in
// docs/outputs.md ("State files"); the /final group of a states.h5 that
// arnoldweb wrote is one such file as it is. A state set is read, then checked
// against the scene's model: every problem is a StateError (exit 2) naming the
// file (or "initial"), the dataset and the row (counted from 0, as h5py and
// numpy count).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "arnoldweb/scene.hpp"

namespace arnoldweb {

// States as the kernels take them: positions wrapped to [-1/2, 1/2] turns
// with whole turns apart (X = 2 pi (winding + position_turns) radians),
// momenta, the common time, and a status per state.
struct StateSet {
  std::string source;                    // for messages: "init.h5", "states.h5:/final", "initial"
  std::string group;                     // the HDF5 group read ("/", "/final"); "" for arrays
  std::uint64_t count = 0;               // N
  std::vector<double> position_turns;    // 3 N, each in [-1/2, 1/2]
  std::vector<std::int64_t> winding;     // 3 N, whole turns
  std::vector<double> momentum;          // 3 N
  // 0: a state to integrate; else the status a states.h5 gave it (1 non-finite, 2 energy error
  // above the limit, 3 no initial state, 4 left the confinement region): kept as it is, not checked.
  std::vector<std::int64_t> status;      // N
  bool has_time = false;                 // the file gave a time
  double time = 0;                       // in T (0 when none was given)
  // Filled by check_states: H = T(P) + V(X) of each state under the scene's model (NaN where
  // status != 0), and their range over the states checked.
  std::vector<double> energy;
  double energy_min = 0, energy_max = 0;
};

// Far from model.energy: |H(state) - E| > kStateEnergyTolerance * max(|E|, max V - min V).
constexpr double kStateEnergyTolerance = 0.01;
// Without winding counts, positions are split into whole and wrapped turns exactly up to this
// many turns (2^52); larger ones are out of range.
constexpr double kMaxStateTurns = 4503599627370496.0;

// Reads a state file: the datasets at its root, or, where the root has no
// momentum dataset, those of its /final group (a states.h5). Throws
// StateError for a file that cannot be read or does not follow the schema
// (shapes, types, units, non-finite or out-of-range values).
StateSet read_state_file(const std::string& path);

enum class PositionUnits { Radians, Turns };

// States from arrays (rows of 3: x, y, z and p_x, p_y, p_z), row-major, with
// the shape each has: the rules of a file's datasets without winding counts.
// `source` names them in messages ("initial").
StateSet states_from_arrays(const double* positions, std::size_t position_rows, std::size_t position_columns,
                            const double* momenta, std::size_t momentum_rows, std::size_t momentum_columns,
                            PositionUnits units, const std::string& source);

// Checks the states against the scene's model (model.kind, its parameters,
// model.energy) and fills their energies; StateError for the first state
// whose energy is not finite or far from model.energy (see kStateEnergyTolerance).
void check_states(StateSet& states, const Scene& scene);

// ensemble.file read and checked against the scene (read_state_file, check_states).
StateSet load_initial_states(const Scene& scene);

}  // namespace arnoldweb
