// arnoldweb: states of trajectories a run starts from (open runs:
// ensemble.initial = "file", Python's initial=(X, P), continuing a run):
// positions wrapped to [-1/2, 1/2] turns with whole turns apart
// (X = 2 pi (winding + position_turns) radians), momenta, a status per state
// (0: integrate it; else the status a states.h5 gave it, kept), the time.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace arnoldweb {

struct StateSet {
  std::string source;                  // for messages
  std::uint64_t count = 0;             // N
  std::vector<double> position_turns;  // 3 N, each in [-1/2, 1/2]
  std::vector<std::int64_t> winding;   // 3 N, whole turns
  std::vector<double> momentum;        // 3 N
  std::vector<std::int64_t> status;    // N
  bool has_time = false;
  double time = 0;                     // in T
};

}  // namespace arnoldweb
