// arnoldweb: the output table (output_table.hpp).
#include "plan/output_table.hpp"

#include "arnoldweb/plan.hpp"
#include "aw_params.h"

namespace arnoldweb::detail {

const std::vector<RecordOutput>& record_outputs() {
  static const std::vector<RecordOutput> rows = {
      {"initial_states", AW_OUT_INITIAL_STATE, AW_F_INITIAL_STATES, AW_STATE_REALS, 0, "states.h5", "initial",
       false,
       {{"position_turns", false, 0, 3, ""}, {"momentum", false, 3, 3, ""}},
       "the initial state of every trajectory: position in turns (wrapped to [-1/2, 1/2]) and momentum",
       {"time_start"}},
      {"final_states", AW_OUT_FINAL_STATE, AW_F_FINAL_STATES, AW_STATE_REALS, AW_STATE_INTS, "states.h5", "final",
       false,
       {{"position_turns", false, 0, 3, ""},
        {"winding", true, 0, 3, ""},
        {"momentum", false, 3, 3, ""},
        {"status", true, 3, 1,
         "0 ok, 1 non-finite, 2 energy error above the limit, 3 no initial state, 4 left the confinement region"},
        {"position", false, 0, 3, "2 pi (winding + position_turns): unwrapped, in radians", 0, true}},
       "the final state of every trajectory: position in turns with its winding counts, momentum, status",
       {"time_end"}},
      {"indicators", AW_OUT_INDICATORS, AW_F_TANGENT, AW_IND_REALS, 0, "indicators.h5", "", true,
       {{"fli", false, AW_IND_FLI, 1, "max over the run of log|w(t)|, |w(0)| = 1 (natural log); NaN: trajectory flagged",
         AW_F_FLI},
        {"megno", false, AW_IND_MEGNO, 1,
         "mean MEGNO <Y>(t) at the end of the run (2: regular); NaN: trajectory flagged", AW_F_MEGNO},
        {"megno_lyapunov", false, AW_IND_MEGNO_LYAPUNOV, 1,
         "slope of Y(t) against t (Y ~ lambda t): Lyapunov exponent, 1/T; NaN: trajectory flagged", AW_F_MEGNO},
        {"lyapunov", false, AW_IND_LYAPUNOV, 1,
         "log|w(t)| / t at the end of the run: finite-time Lyapunov exponent, 1/T; NaN: trajectory flagged",
         AW_F_LYAPUNOV}},
       "the chaos indicators of every trajectory (FLI, MEGNO, Lyapunov exponents; docs/indicators.md)",
       {"duration", "tangent_initial"}},
      // internal (no file): the state between two launches (open runs), in checkpoints only
      {"carry", AW_OUT_CARRY, AW_F_CARRY, AW_CARRY_REALS, AW_CARRY_INTS, "", "", false, {},
       "a trajectory's whole state between two time slices, or the state it starts from (ensemble.initial = "
       "\"file\")"},
  };
  return rows;
}

const RecordOutput* find_record_output(const std::string& name) {
  for (const RecordOutput& r : record_outputs())
    if (r.name == name) return &r;
  return nullptr;
}

std::vector<const RecordOutput*> records_written(std::uint32_t features) {
  std::vector<const RecordOutput*> rows;
  for (const RecordOutput& r : record_outputs())
    if (features & r.feature) rows.push_back(&r);
  return rows;
}

std::vector<const RecordOutput*> records_reported(std::uint32_t features) {
  std::vector<const RecordOutput*> rows;
  for (const RecordOutput* r : records_written(features))
    if (!r->internal()) rows.push_back(r);
  return rows;
}

void lay_out_records(std::uint32_t features, IntParams& ip) {
  ip.rec_reals = 0;
  ip.rec_ints = 0;
  for (const RecordOutput* r : records_written(features)) {
    ip.rec_col_r[r->slot] = ip.rec_reals;
    ip.rec_col_i[r->slot] = ip.rec_ints;
    ip.rec_reals += r->reals;
    ip.rec_ints += r->ints;
  }
}

}  // namespace arnoldweb::detail

namespace arnoldweb {

std::vector<std::string> output_names() {
  std::vector<std::string> names;
  for (const detail::RecordOutput& r : detail::record_outputs())
    if (!r.internal()) names.push_back(r.name);
  return names;
}

}  // namespace arnoldweb
