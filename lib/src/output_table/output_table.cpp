// arnoldweb: the output table (output_table.hpp).
#include "output_table/output_table.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "aw_params.h"

namespace arnoldweb::detail {
namespace {

// observe.trajectories: picked records, each of every id at every sample, at most
constexpr std::uint64_t kMaxPickedRecords = 1u << 20;

bool positive(const std::vector<double>& v) { return v[0] > 0; }

// The ids observe.trajectories picks, increasing: `ids`, or 0 .. count - 1 (both: the planner refuses it).
std::vector<std::int64_t> picked_ids(const KeyTable& t, const KeyValues& v) {
  std::vector<std::int64_t> ids;
  for (double d : t.value(v, "ids")) ids.push_back(static_cast<std::int64_t>(d));
  const std::vector<double> count = t.value(v, "count");
  for (std::int64_t k = 0; !count.empty() && k < static_cast<std::int64_t>(count[0]); ++k) ids.push_back(k);
  std::sort(ids.begin(), ids.end());
  return ids;
}

KeyProblem check_trajectories(const KeyTable& t, const KeyValues& v, const KeyPlan& p) {
  const std::string ids_key = t.sub(t.written(v, "ids") ? "ids" : "count"), every_key = t.sub("every");
  if (t.written(v, "ids") && t.written(v, "count"))
    return {t.sub("count"), "give observe.trajectories.ids or .count, not both"};
  const std::vector<std::int64_t> ids = picked_ids(t, v);
  if (static_cast<std::uint64_t>(ids.back()) >= p.trajectories)
    return {ids_key, "trajectory " + p.count(static_cast<std::uint64_t>(ids.back())) + " is not in the ensemble (" +
                         "ensemble.trajectories = " + p.count(p.trajectories) + ": ids 0 to " +
                         p.count(p.trajectories - 1) + ")"};
  const double every = t.value(v, "every")[0];
  const std::int64_t samples = p.ratio(p.duration, every);
  if (samples == 0)
    return {every_key, p.number(every) + " T does not divide run.duration = " + p.number(p.duration) + " T"};
  if (p.ratio(every, p.interval) == 0)
    return {every_key, p.number(every) + " T is not a multiple of the shortest sample interval, " +
                           p.number(p.interval) +
                           " T (observe.energy_error.every, observe.frequencies.every, observe.diffusion.every or "
                           "run.average)"};
  const std::uint64_t records = ids.size() * static_cast<std::uint64_t>(samples + 1);
  if (records > kMaxPickedRecords)
    return {every_key, p.count(ids.size()) + " trajectories x " + p.count(static_cast<std::uint64_t>(samples + 1)) +
                           " samples = " + p.count(records) + " states; at most " + p.count(kMaxPickedRecords) +
                           " are kept: choose a longer interval or fewer trajectories"};
  return {};
}

void fill_trajectories(const KeyTable& t, const KeyValues& v, const KeyPlan& p, IntParams& ip) {
  ip.pick_stride = 1;
  if (!t.on(v)) return;
  const std::vector<std::int64_t> ids = picked_ids(t, v);
  const double every = t.value(v, "every")[0];
  ip.pick_count = static_cast<std::int64_t>(ids.size());
  std::copy(ids.begin(), ids.end(), ip.pick_ids);
  ip.pick_samples = p.ratio(p.duration, every);
  ip.pick_stride = p.ratio(every, p.interval);
}

// which trajectories, when
std::vector<KeyData> trajectory_data(const KeyTable& t, const KeyValues& v, const KeyPlan& p, const IntParams& ip) {
  const double every = t.value(v, "every")[0];
  std::vector<double> time(static_cast<std::size_t>(ip.pick_samples) + 1);
  for (std::size_t q = 0; q < time.size(); ++q) time[q] = p.start_time + static_cast<double>(q) * every;
  return {{"ids", true, {}, picked_ids(t, v), "the trajectory (index in the ensemble) of each row"},
          {"time", true, time, {}, "the time of each sample, in T"},
          {"every", false, {every}}};
}

const KeyTable trajectory_keys = {
    "observe.trajectories", AW_F_TRAJECTORIES, 0,
    "{ ids = [i, j, ...], every = T }, { count = n, every = T } or false",
    "a table { ids = [i, j, ...], every = <T> } or { count = n, every = <T> }, or false",
    "The orbits of chosen trajectories: the position (in turns, with the winding counts, and unwrapped), the "
    "momentum and the energy error E(t) - E(0) of each at t = 0, every, 2 every, ... up to run.duration: "
    "trajectories.h5. Memory goes with the chosen trajectories, not the ensemble.",
    {{"ids", TableSubKey::Kind::Integers, "1 to 1024 different ids from 0 to ensemble.trajectories - 1",
      "an array of 1 to 1024 different integers >= 0 (trajectory ids)",
      [](const std::vector<double>& x) {
        if (x.empty() || x.size() > AW_MAX_PICKS) return false;
        std::set<double> seen;
        for (double d : x)
          if (!(d >= 0 && d < 9e15 && d == std::floor(d)) || !seen.insert(d).second) return false;
        return true;
      },
      "The trajectories to record, by index (trajectory i of the ensemble; the same bits as in a run of the whole "
      "ensemble)."},
     {"count", TableSubKey::Kind::Integer, "1 to 1024, at most ensemble.trajectories", "an integer from 1 to 1024",
      [](const std::vector<double>& x) { return x[0] >= 1 && x[0] <= AW_MAX_PICKS; },
      "Record trajectories 0 .. count - 1 (instead of ids)."},
     {"every", TableSubKey::Kind::Real, "> 0, divides run.duration, a multiple of the shortest sample interval",
      "a finite float greater than 0 (in units of T)", positive,
      "Sample interval, in T: a multiple of the shortest sample interval (observe.energy_error.every, or "
      "run.average without it; see observe.frequencies.every).",
      {1.0}}},
    check_trajectories,
    fill_trajectories,
    trajectory_data};

// a table key's value of one number (as written, else its default)
double real_value(const KeyTable& t, const KeyValues& v, const std::string& name) { return t.value(v, name)[0]; }
std::int64_t integer_value(const KeyTable& t, const KeyValues& v, const std::string& name) {
  return static_cast<std::int64_t>(real_value(t, v, name));
}

// observe.frequencies: the leading frequency of every angle over two windows of `samples` samples
// `every` T apart, Laskar's window of order `window` (docs/frequencies.md)

KeyProblem check_frequencies(const KeyTable& t, const KeyValues& v, const KeyPlan& p) {
  const std::int64_t samples = integer_value(t, v, "samples");
  const double every = real_value(t, v, "every");
  if (static_cast<double>(p.segments / p.stride(t.sub("every"))) < 2.0 * static_cast<double>(samples))
    return {t.sub("samples"), "two windows of " + p.count(static_cast<std::uint64_t>(samples)) + " samples every " +
                                  p.number(every) + " T take " + p.number(2.0 * static_cast<double>(samples) * every) +
                                  " T, and run.duration is " + p.number(p.duration) +
                                  " T: choose fewer samples, a shorter interval or a longer run"};
  if (p.slices > 1)
    return {"run.slice",
            "the frequency analysis keeps a window's samples on the device between time slices, which slices "
            "do not carry: run observe.frequencies without run.slice"};
  return {};
}

void fill_frequencies(const KeyTable& t, const KeyValues& v, const KeyPlan& p, IntParams& ip) {
  ip.frequency_stride = p.stride(t.sub("every"));
  if (!t.on(v)) return;
  ip.frequency_samples = integer_value(t, v, "samples");
  ip.frequency_order = integer_value(t, v, "window");
  ip.series_reals = AW_FREQ_SERIES_REALS(ip.frequency_samples);  // both windows, the rates, a flag
}

void fill_frequency_reals(const KeyTable& t, const KeyValues& v, const KeyPlan&, RealParams& rp) {
  rp.frequency_every = real_value(t, v, "every");
}

// the windows, attributes of frequencies.h5
std::vector<KeyData> frequency_data(const KeyTable& t, const KeyValues& v, const KeyPlan&, const IntParams&) {
  return {{"samples", false, {}, {integer_value(t, v, "samples")}},
          {"every", false, {real_value(t, v, "every")}},
          {"window_order", false, {}, {integer_value(t, v, "window")}}};
}

const KeyTable frequency_keys = {
    "observe.frequencies", AW_F_FREQUENCIES, 0, "{ samples = n, every = T, window = p }, true or false",
    "a table { samples = n, every = <T>, window = p }, true (the defaults) or false",
    "Frequency map analysis (NAFF, docs/frequencies.md): the frequency of the largest term of every angle of "
    "every trajectory over two consecutive windows of `samples` samples `every` T apart, from t = every on, and "
    "the diffusion index (log10 of the norm of abs(nu(2)) - abs(nu(1))): frequencies.h5, frequency_map.png, "
    "diffusion_index.png.",
    {{"samples", TableSubKey::Kind::Integer, "16 to 65536", "an integer from 16 to 65536",
      [](const std::vector<double>& x) { return x[0] >= 16 && x[0] <= 65536; },
      "Samples per window (the two windows take 2 samples every T).", {512}},
     {"every", TableSubKey::Kind::Real, "> 0, a multiple of integrator.step",
      "a finite float greater than 0 (in units of T)", positive,
      "Sample interval, in T. The shortest of the sample intervals (observe.energy_error.every, "
      "observe.frequencies.every, observe.diffusion.every, observe.diffusion.average_every) divides run.average "
      "and is a multiple of integrator.step; every other is a multiple of it.",
      {0.1}, true},
     {"window", TableSubKey::Kind::Integer, "0 to 4", "an integer from 0 to 4",
      [](const std::vector<double>& x) { return x[0] >= 0 && x[0] <= 4; },
      "Order p of Laskar's window chi_p (1: Hanning, frequency error ~ 1/T^4; 2: ~ 1/T^6; 0: none).", {1}}},
    check_frequencies,
    fill_frequencies,
    frequency_data,
    true,
    fill_frequency_reals};

// observe.diffusion: the actions every `every` T (each the mean over the last `average` T where it is > 0)
KeyProblem check_diffusion(const KeyTable& t, const KeyValues& v, const KeyPlan& p) {
  const double every = real_value(t, v, "every"), average = real_value(t, v, "average");
  const double average_every = real_value(t, v, "average_every"), fit_from = real_value(t, v, "fit_from");
  if (p.ratio(p.duration, every) == 0)
    return {t.sub("every"), p.number(every) + " T does not divide run.duration = " + p.number(p.duration) + " T"};
  const std::vector<double> a = t.value(v, "along"), c = t.value(v, "across");
  const double dot = a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
  const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  const double nc = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  if (std::fabs(dot) > (1 - 1e-9) * na * nc)
    return {t.sub("across"), "is parallel to observe.diffusion.along: choose a direction across it"};
  if (average > 0) {
    if (p.ratio(average, average_every) == 0)
      return {t.sub("average_every"), p.number(average_every) + " T does not divide observe.diffusion.average = " +
                                          p.number(average) + " T"};
    if (average > every)
      return {t.sub("average"), p.number(average) + " T is longer than the sample interval observe.diffusion.every = " +
                                    p.number(every) + " T: the spans of two samples would overlap"};
    if (p.slices > 1 && p.slice_segments % p.stride(t.sub("every")) != 0)
      return {"run.slice", "with observe.diffusion.average a time slice ends at a sample time: run.slice = " +
                               p.number(p.slice) + " T must be a multiple of observe.diffusion.every = " +
                               p.number(every) + " T"};
  }
  if (!(fit_from < p.duration))
    return {t.sub("fit_from"), p.number(fit_from) + " T is not before the end of the run (run.duration = " +
                                   p.number(p.duration) + " T)"};
  return {};
}

void fill_diffusion(const KeyTable& t, const KeyValues& v, const KeyPlan& p, IntParams& ip) {
  ip.diffusion_stride = p.stride(t.sub("every"));
  ip.diffusion_average_stride = p.stride(t.sub("average_every"));
  ip.diffusion_average_points = 0;
  if (!t.on(v)) return;
  ip.diffusion_samples = p.ratio(p.duration, real_value(t, v, "every"));
  if (const double average = real_value(t, v, "average"); average > 0)
    ip.diffusion_average_points = p.ratio(average, real_value(t, v, "average_every"));
}

void fill_diffusion_reals(const KeyTable& t, const KeyValues& v, const KeyPlan& p, RealParams& rp) {
  if (const double average = real_value(t, v, "average"); average > 0)
    rp.diffusion_average_weight = 1.0 / static_cast<double>(p.ratio(average, real_value(t, v, "average_every")));
}

// the sample interval, an attribute of diffusion.h5
std::vector<KeyData> diffusion_data(const KeyTable& t, const KeyValues& v, const KeyPlan&, const IntParams&) {
  return {{"every", false, {real_value(t, v, "every")}}};
}

const KeyTable diffusion_keys = {
    "observe.diffusion", AW_F_DIFFUSION, 0,
    "{ every = T, along = [..], across = [..], fit_from = T, average = T, average_every = T }, true or false",
    "a table { every = <T>, along = [a, b, c], across = [a, b, c], fit_from = <T>, average = <T>, "
    "average_every = <T> }, true or false",
    "Arnold diffusion (docs/frequencies.md): the actions (momenta) of every trajectory every `every` T, the "
    "moments of their displacement along and across a resonance, and the diffusion coefficient from the "
    "growth of the variance with a bootstrap error bar and the growth's linearity (a warning where it is not "
    "diffusive): diffusion.h5, diffusion.csv, diffusion.png.",
    {{"every", TableSubKey::Kind::Real, "> 0, divides run.duration, a multiple of the shortest sample interval",
      "a finite float greater than 0 (in units of T)", positive,
      "Sample interval of the actions, in T; it may be shorter than observe.energy_error.every (the rule of "
      "observe.frequencies.every).",
      {10.0}, true},
     {"along", TableSubKey::Kind::Direction, kDirectionRange,
      std::string("an array [a, b, c] of floats, ") + kDirectionRange, nullptr,
      "The resonance's direction in action space (normalised).", {1, 1, 0}},
     {"across", TableSubKey::Kind::Direction, std::string(kDirectionRange) + ", not along",
      std::string("an array [a, b, c] of floats, ") + kDirectionRange, nullptr,
      "A direction across the resonance (made orthogonal to `along`, normalised).", {1, -1, 0}},
     {"fit_from", TableSubKey::Kind::Real, ">= 0", "a finite float >= 0 (in units of T)",
      [](const std::vector<double>& x) { return x[0] >= 0; },
      "The fit of the variance's growth starts at this time, in T (after the first fast oscillations).", {0.0}},
     {"average", TableSubKey::Kind::Real, ">= 0, at most observe.diffusion.every", "a finite float >= 0 (in units of T)",
      [](const std::vector<double>& x) { return x[0] >= 0; },
      "Each sample after t = 0 is the mean of the actions over the last `average` T, taken every "
      "observe.diffusion.average_every T: the fast oscillations and the libration in the resonance average out, "
      "and D is fitted to the spreading of the means (0: the actions at the sample times).",
      {0.0}, false, "average"},
     {"average_every", TableSubKey::Kind::Real, "> 0, divides observe.diffusion.average",
      "a finite float greater than 0 (in units of T)", positive,
      "Interval between the actions averaged into a sample, in T (a multiple of integrator.step).", {1.0}, true,
      "average"}},
    check_diffusion,
    fill_diffusion,
    diffusion_data,
    true,
    fill_diffusion_reals};

}  // namespace

bool KeyTable::on(const KeyValues& v) const {
  if (true_switches_on && v.count(key)) return true;
  for (const TableSubKey& k : keys)
    if (k.default_value.empty() && written(v, k.name)) return true;
  return false;
}

bool KeyTable::taken(const KeyValues& v, const TableSubKey& k) const {
  return k.only_with.empty() || value(v, k.only_with).at(0) != 0;
}

std::vector<double> KeyTable::value(const KeyValues& v, const std::string& name) const {
  if (const auto it = v.find(sub(name)); it != v.end()) return it->second;
  for (const TableSubKey& k : keys)
    if (k.name == name) return k.default_value;
  return {};
}

const std::vector<RecordOutput>& record_outputs() {
  static const std::vector<RecordOutput> rows = {
      {"initial_states", AW_OUT_INITIAL_STATE, AW_F_INITIAL_STATES, fixed(AW_STATE_REALS), fixed(0), "states.h5", "initial",
       false,
       {{"position_turns", false, 0, 3, ""}, {"momentum", false, 3, 3, ""}},
       "the initial state of every trajectory: position in turns (wrapped to [-1/2, 1/2]) and momentum",
       {"time_start"}},
      {"final_states", AW_OUT_FINAL_STATE, AW_F_FINAL_STATES, fixed(AW_STATE_REALS), fixed(AW_STATE_INTS), "states.h5", "final",
       false,
       {{"position_turns", false, 0, 3, ""},
        {"winding", true, 0, 3, ""},
        {"momentum", false, 3, 3, ""},
        {"status", true, 3, 1,
         "0 ok, 1 non-finite, 2 energy error above the limit, 3 no initial state, 4 left the confinement region"},
        {"position", false, 0, 3, "2 pi (winding + position_turns): unwrapped, in radians", 0, true}},
       "the final state of every trajectory: position in turns with its winding counts, momentum, status",
       {"time_end"}},
      {"energy_errors", AW_OUT_ENERGY_ERRORS, AW_F_ENERGY_ERRORS, fixed(1), fixed(0), "energy_errors.h5", "", true,
       {{"max_energy_error", false, 0, 1,
         "max over the energy samples (observe.energy_error.every) of |E(t) - E(0)|, every trajectory, flagged "
         "ones included (NaN where the state became non-finite)"},
        {"log10_max_energy_error", false, 0, 1, "log10 of max_energy_error (0: -inf)", 0, false, true, 0,
         "energy_error.png", "log10 max|E(t) - E(0)|"}},
       "the largest energy error of every trajectory: where the integration loses accuracy",
       {"duration"},
       {{"observe.energy_errors", AW_F_ENERGY_ERRORS, AW_F_ENERGY,
         "The largest energy error of every trajectory, the maximum over the energy samples of abs(E(t) - E(0)), "
         "into energy_errors.h5 (over a grid of initial conditions, energy_error.png): where the method's step loses "
         "accuracy."}}},
      {"indicators", AW_OUT_INDICATORS, AW_F_TANGENT, fixed(AW_IND_REALS), fixed(0), "indicators.h5", "", true,
       {{"fli", false, AW_IND_FLI, 1, "max over the run of log|w(t)|, |w(0)| = 1 (natural log); NaN: trajectory flagged",
         AW_F_FLI, false, false, 0, "fli.png", "FLI = max log|w|"},
        {"megno", false, AW_IND_MEGNO, 1,
         "mean MEGNO <Y>(t) at the end of the run (2: regular); NaN: trajectory flagged", AW_F_MEGNO, false, false, 0,
         "megno.png", "mean MEGNO <Y>"},
        {"megno_lyapunov", false, AW_IND_MEGNO_LYAPUNOV, 1,
         "slope of Y(t) against t (Y ~ lambda t): Lyapunov exponent, 1/T; NaN: trajectory flagged", AW_F_MEGNO},
        {"lyapunov", false, AW_IND_LYAPUNOV, 1,
         "log|w(t)| / t at the end of the run: finite-time Lyapunov exponent, 1/T; NaN: trajectory flagged",
         AW_F_LYAPUNOV}},
       "the chaos indicators of every trajectory (FLI, MEGNO, Lyapunov exponents; docs/indicators.md)",
       {"duration"},
       {{"observe.fli", AW_F_FLI, AW_F_TANGENT,
         "Fast Lyapunov indicator of every trajectory: max over the run of the log of the norm of the tangent vector w "
         "(norm 1 at the start)."},
        {"observe.lyapunov", AW_F_LYAPUNOV, AW_F_TANGENT,
         "Finite-time maximal Lyapunov exponent, log(norm of w(t)) / t, of every trajectory, in 1/T."},
        {"observe.megno", AW_F_MEGNO, AW_F_TANGENT,
         "Mean MEGNO <Y> of every trajectory (2 on regular orbits, growing as lambda t / 2 on chaotic ones) and the "
         "Lyapunov exponent from its slope."}},
       {},
       nullptr,
       {"map_and_fli"},
       {{"observe.tangent_initial", 6, {0.3, -0.7, 0.5, 0.2, 0.6, -0.1},
         "Initial tangent vector (dX in radians, dP) of the indicators, normalised to 1. The default has no symmetry "
         "between coordinates (a symmetric one stays in symmetric planes and hides resonances such as I1 = I2).",
         [](const std::vector<double>& v, RealParams& rp) {
           double n2 = 0;
           for (double w : v) n2 += w * w;
           const double norm = std::sqrt(n2);
           for (std::size_t i = 0; i < 6; ++i) rp.tangent_w0[i] = v[i] / norm;
         }}}},
      {"frequencies", AW_OUT_FREQUENCIES, AW_F_FREQUENCIES, fixed(AW_FREQ_REALS), fixed(0), "frequencies.h5", "", true,
       {{"nu_first", false, 0, 3, "the frequency of the largest term of each angle (x, y, z) over the first window, turns per T; "
                                  "NaN: trajectory flagged, or no maximum found"},
        {"nu_second", false, 3, 3, "the same over the second window"},
        {"diffusion_index", false, 6, 1, "log10 || |nu_second| - |nu_first| || (Laskar's diffusion index; -inf: no change)", 0,
         false, true}},
       "the leading frequency of every angle over two consecutive windows and the diffusion index "
       "(observe.frequencies, NAFF; docs/frequencies.md)",
       {"duration"},
       {},
       {frequency_keys},
       nullptr,
       {"frequency_map", "diffusion_index"}},
      {"actions", AW_OUT_ACTIONS, AW_F_DIFFUSION,
       [](const IntParams& ip) { return static_cast<int>(3 * (ip.diffusion_samples + 1)); }, fixed(1), "diffusion.h5", "",
       false,
       {{"momentum", false, 0, -1, "the actions (momenta) at t_k = k every, k = 0 .. K: shape (n, K + 1, 3)", 0, false,
         false, 3},
        {"status", true, 0, 1, "the trajectory's status at the end (0 ok: a flagged one is left out of the moments)"}},
       "the actions of every trajectory at every sample time (observe.diffusion; the moments and D: diffusion.csv, "
       "summary.json)",
       {},
       {},
       {diffusion_keys},
       nullptr,
       {"diffusion"}},
      {"trajectories", AW_OUT_TRAJECTORIES, AW_F_TRAJECTORIES, fixed(AW_PICK_REALS), fixed(AW_PICK_INTS),
       "trajectories.h5", "", false,
       {{"position_turns", false, 0, 3, "position in turns (wrapped to [-1/2, 1/2]): shape (ids, samples, 3)"},
        {"winding", true, 0, 3, "winding counts of the position: shape (ids, samples, 3)"},
        {"position", false, 0, 3, "2 pi (winding + position_turns): unwrapped, in radians", 0, true},
        {"momentum", false, 3, 3, "momentum P: shape (ids, samples, 3)"},
        {"energy_error", false, 6, 1, "E(t) - E(0): shape (ids, samples)"}},
       "the state and energy error of chosen trajectories (observe.trajectories ids) at t = 0, every, 2 every, ...",
       {},
       {},
       {trajectory_keys},
       [](const IntParams& ip) {
         return std::vector<std::uint64_t>{static_cast<std::uint64_t>(ip.pick_count),
                                           static_cast<std::uint64_t>(ip.pick_samples + 1)};
       },
       {"orbits"}},
      // internal (no file): the state between two launches (open runs), in checkpoints only
      {"carry", AW_OUT_CARRY, AW_F_CARRY, fixed(AW_CARRY_REALS), fixed(AW_CARRY_INTS), "", "", false, {},
       "a trajectory's whole state between two time slices, or the state it starts from (ensemble.initial = "
       "\"file\")"},
  };
  return rows;
}

std::vector<const OutputSwitch*> output_switches() {
  std::vector<const OutputSwitch*> all;
  for (const RecordOutput& r : record_outputs())
    for (const OutputSwitch& w : r.switches) all.push_back(&w);
  return all;
}

std::vector<const KeyTable*> key_tables() {
  std::vector<const KeyTable*> all;
  for (const RecordOutput& r : record_outputs())
    for (const KeyTable& t : r.tables) all.push_back(&t);
  return all;
}

std::vector<const DirectionKey*> direction_keys() {
  std::vector<const DirectionKey*> all;
  for (const RecordOutput& r : record_outputs())
    for (const DirectionKey& k : r.directions) all.push_back(&k);
  return all;
}

const DirectionKey* find_direction_key(const std::string& key) {
  for (const DirectionKey* k : direction_keys())
    if (k->key == key) return k;
  return nullptr;
}

const std::vector<double>& DirectionKey::value(const KeyValues& v) const {
  const auto it = v.find(key);
  return it == v.end() ? default_value : it->second;
}

std::uint32_t switch_features(const std::set<std::string>& on, const KeyValues& values) {
  std::uint32_t f = 0;
  for (const OutputSwitch* w : output_switches())
    if (on.count(w->key)) f |= w->bit | w->needs;
  for (const KeyTable* t : key_tables())
    if (t->on(values)) f |= t->bit | t->needs;
  return f;
}

std::vector<std::pair<std::string, double>> sample_intervals(const KeyValues& values) {
  std::vector<std::pair<std::string, double>> all;
  for (const KeyTable* t : key_tables())
    if (t->on(values))
      for (const TableSubKey& k : t->keys)
        if (k.interval && t->taken(values, k)) all.emplace_back(t->sub(k.name), t->value(values, k.name).at(0));
  return all;
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
    if (r->picked) continue;
    ip.rec_col_r[r->slot] = ip.rec_reals;
    ip.rec_col_i[r->slot] = ip.rec_ints;
    ip.rec_width_r[r->slot] = r->reals(ip);
    ip.rec_width_i[r->slot] = r->ints(ip);
    ip.rec_reals += ip.rec_width_r[r->slot];
    ip.rec_ints += ip.rec_width_i[r->slot];
  }
}

std::uint64_t picked_records(const RecordOutput& row, const IntParams& ip) {
  std::uint64_t n = 1;
  for (std::uint64_t d : row.picked(ip)) n *= d;
  return n;
}

std::uint64_t lay_out_picked(std::uint32_t features, std::uint64_t hist_words, IntParams& ip) {
  ip.pick_base = static_cast<std::int64_t>((hist_words + 1) / 2 * 2);
  std::uint64_t end = hist_words;
  for (const RecordOutput* r : records_written(features))
    if (r->picked)  // two words a value
      end = static_cast<std::uint64_t>(ip.pick_base) +
            2 * picked_records(*r, ip) * static_cast<std::uint64_t>(r->reals(ip) + r->ints(ip));
  return end;
}

}  // namespace arnoldweb::detail
