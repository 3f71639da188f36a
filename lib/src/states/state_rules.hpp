// arnoldweb: the rules every source of initial states follows (a state file,
// arrays from Python): positions become wrapped turns and winding counts,
// rows are checked one by one, and the first bad row is a StateError naming
// the source, the dataset and the row. Rows whose status is not 0 (a states.h5
// keeps flagged trajectories) are carried as they are, without checks.
#pragma once

#include <string>
#include <vector>

#include "arnoldweb/states.hpp"
#include "plan/checks.hpp"  // show_number

namespace arnoldweb::detail {

class StateRows {
 public:
  explicit StateRows(std::string source) : source_(std::move(source)) {}
  // status values: 0 to 4 (the meanings of a states.h5's /final/status)
  void check_status(const StateSet& s, const std::string& dataset) const;
  // positions (3 per state, in `units`) into s.position_turns and s.winding:
  // with winding counts, each must be the wrapped part (within half a turn)
  // and each count within 2^52 turns (kMaxStateTurns);
  // without, any finite position within kMaxStateTurns, split exactly.
  void set_positions(StateSet& s, const std::vector<double>& positions, PositionUnits units,
                     const std::vector<std::int64_t>* winding, const std::string& dataset,
                     const std::string& winding_dataset) const;
  // every component finite
  void check_momenta(const StateSet& s, const std::string& dataset) const;

 private:
  [[noreturn]] void fail(const std::string& dataset, std::uint64_t row, const std::string& message) const;
  std::string source_;
};

// The states' time (a file's attribute time) against the run's duration:
// the end time, time + duration, must resolve the duration to 2^-20 of it
// (1e17 + 2 is 1e17). StateError naming run.duration and the largest time
// allowed otherwise; nothing for states without a time.
void check_start_time(const StateSet& s, double duration);

// "(1, nan, 3)"
std::string show_row(const double* v);

}  // namespace arnoldweb::detail
