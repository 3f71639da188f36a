// arnoldweb scene layer: THE KEY TABLE. One row per scene key: its name, type,
// allowed values, default (what to_toml writes for Scene{}), meaning, the
// phrase of its error messages, how its value is read into the Scene and how
// it is written back. Reading (read_values), --set, `arnoldweb keys`,
// to_toml(), the JSON echo in summary.json and the key list of docs/scenes.md
// (generated: `arnoldweb keys --markdown`) all come from here.
// Adding a key: a field in Scene (scene.hpp) and a row here; an output's
// boolean switch and its table keys are declared by its row of the output
// table instead.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "arnoldweb/methods.hpp"
#include "output_table/output_table.hpp"
#include "physics/model_table.hpp"
#include "scene/reader.hpp"

namespace arnoldweb::scene_detail {
namespace {

// ------------------------------------------------------------- words
std::string quoted_list(const std::vector<std::string>& names, const char* last_sep) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i) s += i + 1 == names.size() ? last_sep : ", ";
    s += "\"" + names[i] + "\"";
  }
  return s;
}

// "one of "a", "b", "c"" (or just "a" when there is one).
std::string one_of(const std::vector<std::string>& names) {
  if (names.size() == 1) return "\"" + names[0] + "\"";
  return "one of " + quoted_list(names, ", ");
}

std::vector<std::string> method_name_list() {
  std::vector<std::string> n;
  for (const Method& m : methods()) n.push_back(m.name);
  return n;
}

// "auto" -> -1, "off" -> 0, "<number> <unit>" -> seconds; 0.5 (never a valid result) if malformed.
double wall_seconds(const std::string& w) {
  if (w == "auto") return -1;
  if (w == "off") return 0;
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(w, &used);
  } catch (const std::exception&) {
    return 0.5;
  }
  std::string unit = w.substr(used);
  unit.erase(0, unit.find_first_not_of(' '));
  double scale = 0;
  if (unit == "s" || unit == "sec" || unit == "second" || unit == "seconds") scale = 1;
  else if (unit == "min" || unit == "minute" || unit == "minutes") scale = 60;
  else if (unit == "h" || unit == "hour" || unit == "hours") scale = 3600;
  if (!scale || !std::isfinite(v) || !(v > 0) || v * scale < 1) return 0.5;
  return v * scale;
}

bool is_power_of_two(std::int64_t v) { return v > 0 && (v & (v - 1)) == 0; }

// ------------------------------------------------------------- literals
std::string boolean(bool b) { return b ? "true" : "false"; }
std::string pair(const std::array<double, 2>& v) { return "[" + toml_double(v[0]) + ", " + toml_double(v[1]) + "]"; }
// a pair of whole numbers (held as doubles), written as TOML integers: [64, 64]
std::string integer_pair(const std::array<double, 2>& v) {
  return "[" + std::to_string(static_cast<long long>(v[0])) + ", " + std::to_string(static_cast<long long>(v[1])) + "]";
}
std::string list(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + toml_double(v[i]);
  return s + "]";
}

template <class T>
Literal integer_of(T Scene::*f) {
  return [f](const Scene& s) { return std::to_string(s.*f); };
}
Literal real_of(double Scene::*f) {
  return [f](const Scene& s) { return toml_double(s.*f); };
}
Literal bool_of(bool Scene::*f) {
  return [f](const Scene& s) { return boolean(s.*f); };
}
Literal pair_of(std::array<double, 2> Scene::*f) {
  return [f](const Scene& s) { return pair(s.*f); };
}
Literal integer_pair_of(std::array<double, 2> Scene::*f) {
  return [f](const Scene& s) { return integer_pair(s.*f); };
}
Literal text_of(std::string Scene::*f) {
  return [f](const Scene& s) { return toml_string(s.*f); };
}

// ------------------------------------------------------------- readers
Read real_into(double Scene::*f, std::function<bool(double)> ok) {
  return [f, ok](Reader& r, const std::string& key, const toml::node& n, Scene& s) { r.real(key, n, s.*f, ok); };
}
template <class T>
Read integer_into(T Scene::*f, std::function<bool(std::int64_t)> ok) {
  return [f, ok](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
    std::int64_t v = 0;
    if (r.integer(key, n, v, ok)) s.*f = static_cast<T>(v);
  };
}
Read bool_into(bool Scene::*f) {
  return [f](Reader& r, const std::string& key, const toml::node& n, Scene& s) { r.boolean(key, n, s.*f); };
}
Read pair_into(std::array<double, 2> Scene::*f, std::function<bool(double, double)> ok) {
  return [f, ok](Reader& r, const std::string& key, const toml::node& n, Scene& s) { r.pair(key, n, s.*f, ok); };
}
Read choice_into(std::string Scene::*f, std::function<std::vector<std::string>()> names) {
  return [f, names](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
    r.choice(key, n, s.*f, names());
  };
}
template <class Table, class E>
Read enum_into(E Scene::*f, const Table& (*table)()) {
  return [f, table](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
    std::string word;
    if (r.choice(key, n, word, names_of(table())))
      for (const auto& e : table())
        if (word == e.name) s.*f = e.value;
  };
}
// A table of sub-keys that is always on (its sub-keys are rows of their own).
Read table_only() {
  return [](Reader& r, const std::string& key, const toml::node& n, Scene&) {
    if (!n.is_table()) r.bad(key, n, false);
  };
}
// A table that may be switched off with false (and on with true, if allowed).
Read switch_into(bool Scene::*f, bool true_allowed) {
  return [f, true_allowed](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
    r.switch_table(key, n, s.*f, true_allowed);
  };
}

// ------------------------------------------------------------- the rows
class Rows {
 public:
  explicit Rows(std::vector<KeySpec>& k) : k_(k) {}
  // type and allowed: as the docs show them; must: completes "must be ...".
  void operator()(std::string key, std::string type, std::string allowed, std::string must, Literal literal,
                  Read read, std::string meaning, Shape shape = Shape::Value) {
    KeySpec s;
    s.doc.key = std::move(key);
    s.doc.type = std::move(type);
    s.doc.allowed = std::move(allowed);
    s.doc.meaning = std::move(meaning);
    s.must = std::move(must);
    s.literal = std::move(literal);
    s.read = std::move(read);
    s.shape = shape;
    const std::string d = s.literal(Scene{});
    s.doc.default_value = d.empty() ? "(not set)" : d;
    k_.push_back(std::move(s));
  }

 private:
  std::vector<KeySpec>& k_;
};

const auto direction_ok = [](double, double lat) { return lat >= -90 && lat <= 90; };
const auto positive = [](double v) { return v > 0; };
const auto width_ok = [](double w) { return w > 0 && w < 120; };
const auto at_least_0 = [](std::int64_t v) { return v >= 0; };

// model.kind and the parameters of the models, one row per key their
// descriptors declare (lib/src/physics/models/<name>.cpp; docs/models.md).
std::vector<std::string> model_name_list() {
  std::vector<std::string> n;
  for (const detail::ModelDescriptor& m : detail::models()) n.push_back(m.name);
  return n;
}

// A model parameter's values as the echo writes them: a number, an array, or
// an array of rows (integer columns without a fraction).
std::string parameter_literal(const detail::ModelParameter& p, const std::vector<double>& v) {
  auto number = [&](std::size_t i) {
    return static_cast<int>(i % static_cast<std::size_t>(p.width)) < p.integer_columns
               ? std::to_string(static_cast<long long>(v[i]))
               : toml_double(v[i]);
  };
  if (p.is_number()) return v.empty() ? std::string() : number(0);
  std::string t = "[";
  for (std::size_t i = 0; i < v.size(); ++i) {
    const bool row_start = i % static_cast<std::size_t>(p.width) == 0;
    if (p.max_rows && row_start) t += i ? "], [" : "[";
    else if (i) t += ", ";
    t += number(i);
  }
  return t + (p.max_rows && !v.empty() ? "]]" : "]");
}

// Reads a model parameter: a number, an array of `width`, or 1 to max_rows
// arrays of `width`; every value finite and within [lo, hi]; then its own checks.
void read_parameter(const detail::ModelParameter& p, Reader& r, const std::string& key, const toml::node& n,
                    Scene& s) {
  auto in_range = [&](double x) { return x >= p.lo && x <= p.hi; };
  std::vector<double> v;
  if (p.is_number()) {
    double x = 0;
    if (!r.real(key, n, x, in_range)) return;
    v = {x};
  } else if (!p.max_rows) {
    if (!r.reals(key, n, v, static_cast<std::size_t>(p.width), [&](const std::vector<double>& x) {
          return std::all_of(x.begin(), x.end(), in_range);
        }))
      return;
  } else {
    const toml::array* rows = n.as_array();
    if (!rows) return r.bad(key, n, false);
    if (rows->empty() || rows->size() > static_cast<std::size_t>(p.max_rows))
      return r.bad(key, n, true, " (" + std::to_string(rows->size()) + " rows)");
    for (std::size_t j = 0; j < rows->size(); ++j) {
      const std::string where = " (row " + std::to_string(j + 1) + ")";
      const toml::array* row = (*rows)[j].as_array();
      if (!row || row->size() != static_cast<std::size_t>(p.width))
        return r.bad(key, n, true, where + ": each row has " + std::to_string(p.width) + " numbers");
      for (const toml::node& e : *row) {
        double x = 0;
        if (auto f = e.as_floating_point()) x = f->get();
        else if (auto i = e.as_integer()) x = static_cast<double>(i->get());
        else return r.bad(key, n, true, where + ": an element is not a number");
        if (!std::isfinite(x) || !in_range(x)) return r.bad(key, n, true, where + ": out of range");
        v.push_back(x);
      }
    }
  }
  if (p.check) {
    const std::string why = p.check(v);
    if (!why.empty()) return r.bad(key, n, true, why);
  }
  s.model_values[key] = v;
}

void model_kind_keys(Rows& add) {
  std::string kinds;
  for (const detail::ModelDescriptor& m : detail::models())
    kinds += (kinds.empty() ? "" : ", ") + ("\"" + m.name + "\" (" + m.title + ")");
  add("model.kind", "string", quoted_list(model_name_list(), " or "), one_of(model_name_list()),
      text_of(&Scene::model_kind), choice_into(&Scene::model_kind, model_name_list),
      "The Hamiltonian H = T(P) + V(X) (`arnoldweb models` lists them, docs/models.md): " + kinds + ".");
  // one row per key, in the order the models declare them; a key several models share says so
  std::vector<std::string> done;
  for (const detail::ModelDescriptor& m : detail::models())
    for (const detail::ModelParameter& p : m.parameters) {
      if (std::find(done.begin(), done.end(), p.key) != done.end()) continue;
      done.push_back(p.key);
      std::string owners;
      for (const detail::ModelDescriptor& o : detail::models())
        if (o.parameter(p.key)) owners += (owners.empty() ? "" : " and ") + o.name;
      const detail::ModelParameter param = p;
      add(p.key, p.type, p.allowed, p.must,
          [param](const Scene& s) {
            const auto it = s.model_values.find(param.key);
            return parameter_literal(param, it != s.model_values.end() ? it->second : param.default_value);
          },
          [param](Reader& r, const std::string& key, const toml::node& n, Scene& s) { read_parameter(param, r, key, n, s); },
          owners + ": " + p.help);
    }
}

// model.kind = "expression": the potential and its parameters (docs/models.md)
void expression_model_keys(Rows& add) {
  add("model.potential", "string", "an expression in x, y, z (docs/models.md)",
      "a non-empty string: the potential V(x, y, z), e.g. \"eps*cos(x)*cos(y)\"",
      [](const Scene& s) { return s.model_potential.empty() ? std::string() : toml_string(s.model_potential); },
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        r.text(key, n, s.model_potential, [](const std::string& v) { return !v.empty(); });
      },
      "For model.kind = \"expression\": the potential V over x, y, z (radians) and the names in "
      "model.parameters, with + - * / ^ (integer powers), sin, cos, exp, sqrt, pi and parentheses; "
      "2 pi-periodic in each coordinate. Differentiated symbolically and compiled for OpenCL and CUDA "
      "(docs/models.md).");
  add("model.parameters", "table", "{ name = float, ... }", "a table of names and finite floats, e.g. { eps = 0.01 }",
      [](const Scene& s) {
        if (s.model_parameters.empty()) return std::string();
        std::string t = "{ ";
        for (std::size_t i = 0; i < s.model_parameters.size(); ++i)
          t += (i ? ", " : "") + s.model_parameters[i].first + " = " + toml_double(s.model_parameters[i].second);
        return t + " }";
      },
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        const toml::table* t = n.as_table();
        if (!t) return r.bad(key, n, false);
        std::vector<std::pair<std::string, double>> v;
        for (auto&& [name, value] : *t) {
          double x = 0;
          if (auto f = value.as_floating_point()) x = f->get();
          else if (auto i = value.as_integer()) x = static_cast<double>(i->get());
          else return r.bad(key, n, true, " (" + std::string(name.str()) + " is not a number)");
          if (!std::isfinite(x)) return r.bad(key, n, true, " (" + std::string(name.str()) + " is not finite)");
          v.emplace_back(std::string(name.str()), x);
        }
        s.model_parameters = v;
      },
      "For model.kind = \"expression\": the named parameters of model.potential, e.g. { eps = 0.01 } "
      "(names: letters, digits and _, not x, y, z, pi or a function name).");
}

void model_keys(Rows& add) {
  add("model.energy", "float", ">= -1e6 and <= 1e6",
      "a float from -1e6 to 1e6 (the model must leave phase space at that energy: the planner checks)",
      real_of(&Scene::energy),
      real_into(&Scene::energy, [](double e) { return e >= -kMaxEnergy && e <= kMaxEnergy; }),
      "Total energy E of every trajectory (the paper's model: the effective perturbation is 2/E; an energy "
      "that leaves no phase space to a model is refused when the scene is planned).");
  model_kind_keys(add);
  expression_model_keys(add);
}

void ensemble_keys(Rows& add) {
  add("ensemble.trajectories", "integer", "1 to 1e13", "an integer from 1 to 1e13", integer_of(&Scene::trajectories),
      integer_into(&Scene::trajectories, [](std::int64_t v) { return v >= 1 && v <= kMaxTrajectories; }),
      "Number of trajectories in the ensemble.");
  add("ensemble.seed", "integer", ">= 0", "an integer >= 0", integer_of(&Scene::seed),
      integer_into(&Scene::seed, at_least_0),
      "Seed of the counter-based random numbers: trajectory i starts from a state that depends "
      "only on (seed, i), whatever the device or chunking.");
  add("ensemble.initial", "string", quoted_list(initial_kinds(), " or "), one_of(initial_kinds()),
      text_of(&Scene::initial), choice_into(&Scene::initial, initial_kinds),
      "How initial states are drawn; X is uniform on the accessible part of the torus. "
      "\"shell\": direction of P uniform on the sphere, speed sqrt(2 (E - V(X))). \"cap\", "
      "\"box\": direction uniform in ensemble.cap or ensemble.box. \"gaussian\": see "
      "ensemble.gaussian. \"grid\": the points of ensemble.grid, in order. \"file\": the states of "
      "ensemble.file, one trajectory per state (docs/outputs.md, \"State files\").");
  add("ensemble.file", "string", "an existing file", "a string naming an existing file (HDF5, docs/outputs.md)",
      [](const Scene& s) { return s.initial_file.empty() ? std::string() : toml_string(s.initial_file); },
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        std::string path;
        if (!r.text(key, n, path, [](const std::string& p) { return !p.empty(); })) return;
        std::error_code ec;
        const auto status = std::filesystem::status(path, ec);
        if (!std::filesystem::exists(status))
          r.bad(key, n, true, " (no such file)");
        else if (!std::filesystem::is_regular_file(status))
          r.bad(key, n, true, std::filesystem::is_directory(status) ? " (it is a directory)" : " (not a regular file)");
        else
          s.initial_file = path;
      },
      "For ensemble.initial = \"file\": the HDF5 file of the initial states (positions, momenta, "
      "optional winding counts and time; or the /final group of a states.h5), relative to the current "
      "directory. Read and checked when the scene is planned (docs/outputs.md, \"State files\").");
  add("ensemble.chunk", "integer", ">= 0 (0 = automatic)", "an integer >= 0 (0 = automatic)",
      integer_of(&Scene::chunk), integer_into(&Scene::chunk, at_least_0),
      "Trajectories per kernel launch; 0 lets the runner choose. Does not change the results.");
  add("ensemble.cap", "table", "{ center = [lon, lat], radius = deg }",
      "a table { center = [lon, lat], radius = <degrees> }",
      [](const Scene& s) {
        return "{ center = " + pair(s.cap_center) + ", radius = " + toml_double(s.cap_radius) + " }";
      },
      table_only(), "The spherical cap of momentum directions for ensemble.initial = \"cap\".", Shape::Composite);
  add("ensemble.cap.center", "array of 2 floats", "[lon, lat] in degrees, lat in [-90, 90]",
      "an array [longitude, latitude] in degrees, latitude from -90 to 90", pair_of(&Scene::cap_center),
      pair_into(&Scene::cap_center, direction_ok),
      "Centre of the cap: longitude and latitude of the momentum direction, in degrees "
      "(P along (cos lat cos lon, cos lat sin lon, sin lat)).");
  add("ensemble.cap.radius", "float", "> 0 and <= 180", "a float greater than 0 and at most 180 (degrees)",
      real_of(&Scene::cap_radius), real_into(&Scene::cap_radius, [](double v) { return v > 0 && v <= 180; }),
      "Angular radius of the cap, degrees.");
  add("ensemble.box", "table", "{ lon = [a, b], lat = [c, d] }", "a table { lon = [from, to], lat = [from, to] } in degrees",
      [](const Scene& s) { return "{ lon = " + pair(s.box_lon) + ", lat = " + pair(s.box_lat) + " }"; }, table_only(),
      "The longitude/latitude box of momentum directions for ensemble.initial = \"box\" (uniform in area).",
      Shape::Composite);
  add("ensemble.box.lon", "array of 2 floats", "[from, to], from < to <= from + 360",
      "an array [from, to] of longitudes in degrees with from < to <= from + 360", pair_of(&Scene::box_lon),
      pair_into(&Scene::box_lon, [](double a, double b) { return a < b && b <= a + 360; }),
      "Longitude range of the box, degrees.");
  add("ensemble.box.lat", "array of 2 floats", "[from, to], -90 <= from < to <= 90",
      "an array [from, to] of latitudes in degrees with -90 <= from < to <= 90", pair_of(&Scene::box_lat),
      pair_into(&Scene::box_lat, [](double a, double b) { return a >= -90 && a < b && b <= 90; }),
      "Latitude range of the box, degrees.");
  add("ensemble.gaussian", "table", "{ mean = [p_x, p_y], sigma = [s_x, s_y] }",
      "a table { mean = [p_x, p_y], sigma = [s_x, s_y] }",
      [](const Scene& s) { return "{ mean = " + pair(s.gaussian_mean) + ", sigma = " + pair(s.gaussian_sigma) + " }"; },
      table_only(),
      "Gaussian initial momenta for ensemble.initial = \"gaussian\": p_x, p_y normal, p_z from "
      "the energy with a random sign (the paper's Figure 4: mean = [sqrt(E), sqrt(E)], sigma = "
      "[0.01, 0.01]).",
      Shape::Composite);
  add("ensemble.gaussian.mean", "array of 2 floats", "finite", "an array [p_x, p_y] of finite floats",
      pair_of(&Scene::gaussian_mean), pair_into(&Scene::gaussian_mean, [](double, double) { return true; }),
      "Mean of p_x and p_y.");
  add("ensemble.gaussian.sigma", "array of 2 floats", "> 0", "an array [s_x, s_y] of floats greater than 0",
      pair_of(&Scene::gaussian_sigma), pair_into(&Scene::gaussian_sigma, [](double a, double b) { return a > 0 && b > 0; }),
      "Standard deviations of p_x and p_y.");
}

void integrator_keys(Rows& add) {
  add("integrator.method", "string", quoted_list(method_name_list(), " or "), one_of(method_name_list()),
      text_of(&Scene::method), choice_into(&Scene::method, method_name_list),
      "Symplectic integration method (`arnoldweb methods` lists order and cost).");
  add("integrator.step", "float or \"auto\"", "> 0 and <= 1, or \"auto\"",
      "a float greater than 0 and at most 1 (the step in units of T = 2 pi) or \"auto\"",
      [](const Scene& s) { return s.step_auto ? std::string("\"auto\"") : toml_double(s.step); },
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        std::string word;
        if (n.is_string()) {
          if (r.text(key, n, word, [](const std::string& v) { return v == "auto"; }, {"auto"})) s.step_auto = true;
        } else if (r.real(key, n, s.step, [](double h) { return h > 0 && h <= kMaxStep; })) {
          s.step_auto = false;
        }
      },
      "Integration step h in units of T = 2 pi. \"auto\": choose a step that meets integrator.tolerance.");
  add("integrator.tolerance", "float", "> 0 and < 1", "a float greater than 0 and less than 1",
      real_of(&Scene::tolerance), real_into(&Scene::tolerance, [](double t) { return t > 0 && t < 1; }),
      "Target largest energy error over the ensemble, used with integrator.step = \"auto\".");
  add("integrator.precision", "string", quoted_list(names_of(precision_names()), " or "),
      one_of(names_of(precision_names())), [](const Scene& s) { return toml_string(to_string(s.precision)); },
      enum_into(&Scene::precision, precision_names), "Floating-point type of the integration.");
  add("integrator.math", "string", quoted_list(names_of(math_names()), " or "), one_of(names_of(math_names())),
      [](const Scene& s) { return toml_string(to_string(s.math)); }, enum_into(&Scene::math, math_names),
      "\"portable\": the same bits on every backend (own sin/cos, no contraction). \"native\": "
      "vendor functions where faster; results then differ between backends.");
  add("integrator.allow_unsafe_step", "boolean", "true or false", "true or false", bool_of(&Scene::allow_unsafe_step),
      bool_into(&Scene::allow_unsafe_step),
      "Run even when the step-size guard refuses the step (h k p_max >= pi).");
}

void run_keys(Rows& add) {
  add("run.average", "float", "> 0", "a finite float greater than 0 (in units of T)", real_of(&Scene::average),
      real_into(&Scene::average, positive), "Averaging window dt of the velocity, in T; a multiple of integrator.step.");
  add("run.duration", "float", "> 0", "a finite float greater than 0 (in units of T)", real_of(&Scene::duration),
      real_into(&Scene::duration, positive), "Propagation time t_p, in T; a multiple of run.average.");
  add("run.slice", "float", ">= 0", "a finite float >= 0 (in units of T; 0: no slices)", real_of(&Scene::slice),
      real_into(&Scene::slice, [](double v) { return v >= 0; }),
      "Time slices of long trajectories, in T (0: none): each slice advances every trajectory of the run by this "
      "much, and a checkpoint between slices holds their whole state (docs/cluster.md, \"Long trajectories\"); a "
      "multiple of the shortest sample interval (of run.average when nothing is sampled).");
  const std::string forms = "\"auto\", \"all\", \"cpu\", \"opencl:N\", \"cuda:N\" or a list \"cuda:0,cuda:1\"";
  add("run.device", "string", forms,
      forms + " (N = 0, 1, ...: the index in `arnoldweb devices`; a list names each device once)",
      text_of(&Scene::device),
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        std::string device;
        if (!r.text(key, n, device, valid_device)) return;
        if (const std::string twice = repeated_device(device); !twice.empty()) {
          r.bad(key, n, true, " (" + twice + " is listed twice)");
          return;
        }
        s.device = device;
      },
      "Where to run. \"auto\" picks the default device; a list of ids (\"cuda:0,cuda:1\") runs on "
      "every device listed, from one process (under mpirun, each rank drives its entry); \"all\" "
      "is every GPU of the machine (the CUDA devices, else the OpenCL GPUs; without a GPU, the "
      "default device). Whether the devices exist is checked when the run starts (docs/cluster.md).");
  // run.checkpoint_every (checkpoints, issue 15): "auto", "off", seconds or "<number> <unit>"
  add("run.checkpoint_every", "float or string", "\"auto\", \"off\", seconds > 0, or \"N s\", \"N min\", \"N h\"",
      "\"auto\", \"off\", a number of seconds greater than 0, or a string such as \"10 min\" "
      "(units s, min, h)",
      [](const Scene& s) {
        return s.checkpoint_every < 0 ? toml_string("auto")
               : s.checkpoint_every == 0 ? toml_string("off")
                                         : toml_double(s.checkpoint_every);
      },
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        if (n.as_string()) {
          std::string word;
          if (r.text(key, n, word, [](const std::string& w) { return wall_seconds(w) != 0.5; }, {"auto", "off"}))
            s.checkpoint_every = wall_seconds(word);
          return;
        }
        r.real(key, n, s.checkpoint_every, positive);
      },
      "Wall-clock time between checkpoints of the run, written into its staging directory "
      "(`arnoldweb resume` continues from the last; docs/cluster.md). \"auto\": every 10 min "
      "once a run is estimated to take more than an hour; \"off\": none, and a stopped run "
      "writes what it computed instead.");
}

void observe_keys(Rows& add) {
  add("observe.velocity_map", "table or boolean", "{ nside = N }, true or false",
      "a table { nside = N }, true (nside 64) or false",
      [](const Scene& s) { return s.velocity_map ? "{ nside = " + std::to_string(s.nside) + " }" : boolean(false); },
      switch_into(&Scene::velocity_map, true),
      "HEALPix map of the directions of the averaged velocities; false: no map. true: the default nside.",
      Shape::Composite);
  add("observe.velocity_map.nside", "integer", "power of two, 1 to 8192", "a power of two from 1 to 8192",
      integer_of(&Scene::nside),
      integer_into(&Scene::nside, [](std::int64_t v) { return v <= kMaxNside && is_power_of_two(v); }),
      "HEALPix resolution of the velocity map: 12 nside^2 pixels.");
  add("observe.energy_error", "boolean or table", "true, false or { every = dt }",
      "true, false or a table { every = <sample interval in T> }",
      [](const Scene& s) { return s.energy_error ? "{ every = " + toml_double(s.energy_every) + " }" : boolean(false); },
      switch_into(&Scene::energy_error, true),
      "Track the energy error dE of every trajectory. A table sets the sample interval; true samples every 1 T.",
      Shape::Composite);
  add("observe.energy_error.every", "float", "> 0", "a finite float greater than 0 (sample interval in T)",
      real_of(&Scene::energy_every), real_into(&Scene::energy_every, positive),
      "Interval between energy-error samples, in T; divides run.average.");
  add("observe.max_energy_error", "float", "> 0, or absent", "a finite float greater than 0",
      [](const Scene& s) { return s.max_energy_error ? toml_double(*s.max_energy_error) : std::string(); },
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        double limit = 0;
        if (r.real(key, n, limit, positive)) s.max_energy_error = limit;
      },
      "Flag trajectories whose energy error abs(dE) exceeds this value (they are counted in "
      "the result); implies energy tracking. Absent: no limit.");
  add("observe.initial_states", "boolean", "true or false", "true or false", bool_of(&Scene::initial_states),
      bool_into(&Scene::initial_states), "Write the initial state of every trajectory.");
  add("observe.final_states", "boolean", "true or false", "true or false", bool_of(&Scene::final_states),
      bool_into(&Scene::final_states), "Write the final state of every trajectory.");
  add("observe.zoom", "table or false", "{ center = [lon, lat], width = deg, resolution = R } or false",
      "a table { center = [lon, lat], width = <degrees>, resolution = R } or false",
      [](const Scene& s) {
        return s.zoom ? "{ center = " + pair(s.zoom_center) + ", width = " + toml_double(s.zoom_width) +
                            ", resolution = " + std::to_string(s.zoom_resolution) + " }"
                      : boolean(false);
      },
      switch_into(&Scene::zoom, false),
      "A high-resolution R x R histogram of the averaged velocities in a square region, in "
      "gnomonic projection about its centre (zoom panels).",
      Shape::Composite);
  add("observe.zoom.center", "array of 2 floats", "[lon, lat] in degrees, lat in [-90, 90]",
      "an array [longitude, latitude] in degrees, latitude from -90 to 90", pair_of(&Scene::zoom_center),
      pair_into(&Scene::zoom_center, direction_ok), "Centre of the zoom region, degrees.");
  add("observe.zoom.width", "float", "> 0 and < 120", "a float greater than 0 and less than 120 (degrees)",
      real_of(&Scene::zoom_width), real_into(&Scene::zoom_width, width_ok), "Full angular width of the zoom square, degrees.");
  add("observe.zoom.resolution", "integer", "16 to 8192", "an integer from 16 to 8192",
      integer_of(&Scene::zoom_resolution),
      integer_into(&Scene::zoom_resolution, [](std::int64_t v) { return v >= 16 && v <= 8192; }),
      "Bins per side of the zoom histogram.");
  add("observe.confine", "table or false", "{ center = [lon, lat], width = deg } or false",
      "a table { center = [lon, lat], width = <degrees> } or false",
      [](const Scene& s) {
        return s.confine ? "{ center = " + pair(s.confine_center) + ", width = " + toml_double(s.confine_width) + " }"
                         : boolean(false);
      },
      switch_into(&Scene::confine, false),
      "Region confinement: only trajectories whose momentum direction stays inside this square "
      "(gnomonic, checked at every energy sample) are binned; the others are counted as left_region.",
      Shape::Composite);
  add("observe.confine.center", "array of 2 floats", "[lon, lat] in degrees, lat in [-90, 90]",
      "an array [longitude, latitude] in degrees, latitude from -90 to 90", pair_of(&Scene::confine_center),
      pair_into(&Scene::confine_center, direction_ok), "Centre of the confinement square, degrees.");
  add("observe.confine.width", "float", "> 0 and < 120", "a float greater than 0 and less than 120 (degrees)",
      real_of(&Scene::confine_width), real_into(&Scene::confine_width, width_ok),
      "Full angular width of the square, degrees.");
  add("observe.frames", "table or false", "{ times = [t0, t1, ...] } or false",
      "a table { times = [t0, t1, ...] } (in T) or false",
      [](const Scene& s) { return s.frame_times.empty() ? boolean(false) : "{ times = " + list(s.frame_times) + " }"; },
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        bool on = false;
        if (r.switch_table(key, n, on, false) && !on) s.frame_times.clear();
      },
      "Time series: frame k is the velocity map of the windows starting in [t_k, t_k+1) (a diffusion movie).",
      Shape::Composite);
  add("observe.frames.times", "array of floats", "2 to 65 increasing times >= 0, multiples of run.average",
      "an array of 2 to 65 increasing times >= 0 (in T)",
      [](const Scene& s) { return s.frame_times.empty() ? std::string() : list(s.frame_times); },
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        r.reals(key, n, s.frame_times, 0, [](const std::vector<double>& t) {
          if (t.size() < 2 || t.size() > 65 || t[0] < 0) return false;
          for (std::size_t k = 1; k < t.size(); ++k)
            if (!(t[k] > t[k - 1])) return false;
          return true;
        });
      },
      "Frame boundaries, in T.");
}

// A direction (observe.tangent_initial, a TableSubKey::Kind::Direction: observe.diffusion.along) is
// normalised by its length: its largest absolute component must lie where the sum of the
// squares neither overflows nor underflows ([1e200, 1e200, 0] squared is inf,
// [1e-170, 1e-170, 0] squared is 0). Reads `count` floats into `out`.
bool read_direction(Reader& r, const std::string& key, const toml::node& n, std::size_t count,
                    std::vector<double>& out) {
  std::vector<double> v;
  if (!r.reals(key, n, v, count, [](const std::vector<double>&) { return true; })) return false;
  double largest = 0;
  for (double x : v) largest = std::max(largest, std::fabs(x));
  if (!(largest >= 1e-150 && largest <= 1e150)) {
    r.bad(key, n, true, largest == 0 ? " (the zero vector has no direction)"
                                     : " (its length cannot be computed in double precision: scale it)");
    return false;
  }
  out = v;
  return true;
}
using detail::kDirectionRange;

// The table keys of the output table's rows (lib/src/output_table/, KeyTable),
// kept in Scene::output_values: the table key (false, or a table of its
// sub-keys) and one row per sub-key.
std::string sub_key_literal(const detail::TableSubKey& k, const std::vector<double>& v) {
  using Kind = detail::TableSubKey::Kind;
  const auto number = [&](double x) {
    return k.kind == Kind::Integer || k.kind == Kind::Integers ? std::to_string(static_cast<long long>(x))
                                                               : toml_double(x);
  };
  if (k.kind == Kind::Integer || k.kind == Kind::Real) return number(v[0]);
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + number(v[i]);
  return s + "]";
}
void read_sub_key(const detail::TableSubKey& k, Reader& r, const std::string& key, const toml::node& n, Scene& s) {
  std::vector<double> v(1);
  bool read = false;
  switch (k.kind) {
    case detail::TableSubKey::Kind::Integer: {
      std::int64_t x = 0;
      read = r.integer(key, n, x, [&](std::int64_t i) { return k.ok({static_cast<double>(i)}); });
      v[0] = static_cast<double>(x);
      break;
    }
    case detail::TableSubKey::Kind::Real:
      read = r.real(key, n, v[0], [&](double x) { return k.ok({x}); });
      break;
    case detail::TableSubKey::Kind::Integers:
      read = r.reals(key, n, v, 0, k.ok);
      break;
    case detail::TableSubKey::Kind::Direction:
      read = read_direction(r, key, n, 3, v);
      break;
  }
  if (read) s.output_values[key] = v;
}
void output_table_keys(Rows& add) {
  for (const detail::KeyTable* t : detail::key_tables()) {
    const detail::KeyTable& table = *t;  // a row of the static output table
    add(table.key, table.true_switches_on ? "table or boolean" : "table or false", table.allowed, table.must,
        [&table](const Scene& s) {
          if (!table.on(s.output_values)) return boolean(false);
          std::string text;
          for (const detail::TableSubKey& k : table.keys) {
            const std::vector<double> v = table.value(s.output_values, k.name);
            if (!v.empty() && table.taken(s.output_values, k))
              text += (text.empty() ? "" : ", ") + k.name + " = " + sub_key_literal(k, v);
          }
          return "{ " + text + " }";
        },
        [&table](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
          bool on = false;
          if (!r.switch_table(key, n, on, table.true_switches_on)) return;
          if (on && table.true_switches_on) s.output_values[key] = {1};
          if (on) return;
          s.output_values.erase(key);
          for (const detail::TableSubKey& k : table.keys) s.output_values.erase(table.sub(k.name));
        },
        table.meaning, Shape::Composite);
    for (const detail::TableSubKey& k : table.keys) {
      const char* type = k.kind == detail::TableSubKey::Kind::Integers    ? "array of integers"
                         : k.kind == detail::TableSubKey::Kind::Integer   ? "integer"
                         : k.kind == detail::TableSubKey::Kind::Direction ? "array of 3 floats"
                                                                          : "float";
      add(table.sub(k.name), type, k.allowed, k.must,
          [&table, &k](const Scene& s) {
            const std::vector<double> v = table.value(s.output_values, k.name);
            return v.empty() ? std::string() : sub_key_literal(k, v);
          },
          [&k](Reader& r, const std::string& key, const toml::node& n, Scene& s) { read_sub_key(k, r, key, n, s); },
          k.meaning);
    }
  }
}

void output_keys(Rows& add) {
  add("output.dir", "string", "non-empty path without NUL", "a non-empty string without NUL characters (a directory path)",
      text_of(&Scene::output_dir),
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        // a NUL would end the path where the system reads it ("x\u0000y" is "x")
        r.text(key, n, s.output_dir, [](const std::string& d) { return !d.empty() && d.find('\0') == std::string::npos; });
      },
      "Directory the outputs are written to.");
  add("output.images", "boolean", "true or false", "true or false", bool_of(&Scene::images),
      bool_into(&Scene::images), "Write images of the maps.");
  add("output.formats", "array of strings", "\"hdf5\" (always), \"fits\"",
      "an array of the map's formats that holds \"hdf5\": [\"hdf5\"] or [\"hdf5\", \"fits\"]",
      [](const Scene& s) { return "[" + quoted_list(s.formats, ", ") + "]"; },
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        const toml::array* a = n.as_array();
        if (!a) return r.bad(key, n, false);
        std::vector<std::string> v;
        for (const toml::node& e : *a) {
          const auto f = e.as_string();
          if (!f) return r.bad(key, n, true, " (an element is a " + std::string(type_name(e.type())) + ")");
          if (std::find(v.begin(), v.end(), f->get()) != v.end())
            return r.bad(key, n, true, " (\"" + f->get() + "\" twice)");
          v.push_back(f->get());
        }
        for (const std::string& f : v)
          if (f != "hdf5" && f != "fits") return r.bad(key, n, true, " (\"" + f + "\" is no format of the map)");
#if !ARNOLDWEB_HAVE_CFITSIO
        if (std::find(v.begin(), v.end(), "fits") != v.end())
          return r.bad(key, n, true, " (\"fits\": this build has no CFITSIO, found when it was configured; Debian: libcfitsio-dev)");
#endif
        if (std::find(v.begin(), v.end(), "hdf5") == v.end())
          return r.bad(key, n, true, " (map.h5 is what arnoldweb reads back: render, compare, resume, Python's load)");
        s.formats = v;
      },
      "The map's files: \"hdf5\", map.h5, always (arnoldweb reads it back); \"fits\" adds map.fits, the same counts "
      "as a HEALPix FITS binary table (RING, NSIDE) for healpy.read_map and other FITS tools (docs/outputs.md).");
}

// Grids of initial conditions (docs/indicators.md).
void indicator_keys(Rows& add) {
  const auto whole = [](double v) { return v >= 1 && v <= 65536 && v == static_cast<double>(static_cast<long>(v)); };
  add("ensemble.grid", "table", "{ kind, nside, resolution, range1, range2, axes, fixed, position }",
      "a table { kind = ..., nside = N, resolution = [n1, n2], range1 = [a, b], range2 = [a, b], axes = [i, j], "
      "fixed = p, position = [x, y, z] }",
      [](const Scene& s) {
        return "{ kind = " + toml_string(s.grid_kind) + ", nside = " + std::to_string(s.grid_nside) +
               ", resolution = " + integer_pair(s.grid_resolution) + ", range1 = " + pair(s.grid_range1) +
               ", range2 = " + pair(s.grid_range2) + ", axes = " + integer_pair(s.grid_axes) +
               ", fixed = " + toml_double(s.grid_fixed) + ", position = " + list(s.grid_position) + " }";
      },
      table_only(),
      "The grid of initial conditions for ensemble.initial = \"grid\": trajectory i is grid point i "
      "(ensemble.trajectories is the number of points); docs/indicators.md gives the ordering.",
      Shape::Composite);
  add("ensemble.grid.kind", "string", "\"healpix\", \"lonlat\" or \"plane\"",
      "one of \"healpix\", \"lonlat\", \"plane\"", text_of(&Scene::grid_kind),
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        r.choice(key, n, s.grid_kind, {"healpix", "lonlat", "plane"});
      },
      "\"healpix\": momentum directions at the HEALPix pixel centres (RING order) of ensemble.grid.nside; "
      "\"lonlat\": directions at the cell centres of a resolution[0] x resolution[1] grid over ensemble.box "
      "(uniform in longitude and latitude); the speed from the energy at the fixed position. \"plane\": momenta "
      "axes[0], axes[1] on a grid over range1 x range2, the third momentum = fixed.");
  add("ensemble.grid.nside", "integer", "power of two, 1 to 1024", "a power of two from 1 to 1024",
      integer_of(&Scene::grid_nside),
      integer_into(&Scene::grid_nside, [](std::int64_t v) { return v <= 1024 && is_power_of_two(v); }),
      "HEALPix resolution of a \"healpix\" grid: 12 nside^2 initial conditions.");
  add("ensemble.grid.resolution", "array of 2 integers", "1 to 65536 each", "an array [n1, n2] of integers from 1 to 65536",
      integer_pair_of(&Scene::grid_resolution),
      pair_into(&Scene::grid_resolution, [whole](double a, double b) { return whole(a) && whole(b); }),
      "Points along the two gridded coordinates of a \"lonlat\" or \"plane\" grid (n1 x n2 initial conditions).");
  add("ensemble.grid.range1", "array of 2 floats", "[from, to], from < to", "an array [from, to] with from < to",
      pair_of(&Scene::grid_range1), pair_into(&Scene::grid_range1, [](double a, double b) { return a < b; }),
      "Range of the first gridded momentum of a \"plane\" grid.");
  add("ensemble.grid.range2", "array of 2 floats", "[from, to], from < to", "an array [from, to] with from < to",
      pair_of(&Scene::grid_range2), pair_into(&Scene::grid_range2, [](double a, double b) { return a < b; }),
      "Range of the second gridded momentum of a \"plane\" grid.");
  add("ensemble.grid.axes", "array of 2 integers", "two different of 0, 1, 2", "an array [i, j] of two different integers 0, 1 or 2",
      integer_pair_of(&Scene::grid_axes), pair_into(&Scene::grid_axes, [](double a, double b) {
        auto axis = [](double v) { return v == 0 || v == 1 || v == 2; };
        return axis(a) && axis(b) && a != b;
      }),
      "Which momenta a \"plane\" grid sets (0 = p_1/p_x, 1 = p_2/p_y, 2 = p_3/p_z); the third is ensemble.grid.fixed.");
  add("ensemble.grid.fixed", "float", "finite", "a finite float", real_of(&Scene::grid_fixed),
      real_into(&Scene::grid_fixed, [](double) { return true; }), "The momentum a \"plane\" grid does not set.");
  add("ensemble.grid.position", "array of 3 floats", "finite, radians", "an array [x, y, z] of 3 finite floats (radians)",
      [](const Scene& s) { return list(s.grid_position); },
      [](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
        r.reals(key, n, s.grid_position, 3, [](const std::vector<double>&) { return true; });
      },
      "The position X (angles, radians) of every grid point.");
}

// The switches of the output table's rows (lib/src/output_table/), kept in Scene::switches.
void output_switch_keys(Rows& add) {
  for (const detail::OutputSwitch* w : detail::output_switches()) {
    const std::string key = w->key;
    add(key, "boolean", "true or false", "true or false", [key](const Scene& s) { return boolean(s.observes(key)); },
        [](Reader& r, const std::string& k, const toml::node& n, Scene& s) {
          bool on = false;
          if (!r.boolean(k, n, on)) return;
          if (on)
            s.switches.insert(k);
          else
            s.switches.erase(k);
        },
        w->meaning);
  }
}

// The output table's direction keys (DirectionKey: observe.tangent_initial), kept in
// Scene::output_values under their key when written.
void direction_keys(Rows& add) {
  for (const detail::DirectionKey* d : detail::direction_keys()) {
    const std::string type = "array of " + std::to_string(d->count) + " floats";
    add(d->key, type, kDirectionRange, "an " + type + ", " + kDirectionRange,
        [d](const Scene& s) { return list(d->value(s.output_values)); },
        [d](Reader& r, const std::string& key, const toml::node& n, Scene& s) {
          std::vector<double> v;
          if (read_direction(r, key, n, d->count, v)) s.output_values[key] = v;
        },
        d->meaning);
  }
}

// [[panel]] tables are read as a whole (panels.cpp); these rows document them.
void panel_keys(Rows& add) {
  const Literal none = [](const Scene&) { return std::string(); };
  add("panel.name", "string", "letters, digits, - and _", "a non-empty string of letters, digits, - and _", none, nullptr,
      "Name of a further run of this scene drawn as an inset of the same figure; its outputs go "
      "to <output.dir>/panel-<name>.");
  add("panel.title", "string", "any", "a string", none, nullptr, "Caption of the panel.");
  add("panel.set", "array of strings", "key=value overrides", "an array of \"key=value\" strings", none, nullptr,
      "Overrides applied to the scene for this panel, written like --set.");
}

std::vector<KeySpec> build() {
  std::vector<KeySpec> k;
  Rows rows(k);
  model_keys(rows);
  ensemble_keys(rows);
  integrator_keys(rows);
  run_keys(rows);
  observe_keys(rows);
  indicator_keys(rows);
  output_switch_keys(rows);
  direction_keys(rows);
  output_table_keys(rows);
  output_keys(rows);
  panel_keys(rows);
  return k;
}

}  // namespace

const std::vector<KeySpec>& key_specs() {
  static const std::vector<KeySpec> specs = build();
  return specs;
}

const KeySpec* find_spec(const std::string& dotted) {
  for (const KeySpec& s : key_specs())
    if (s.doc.key == dotted) return &s;
  return nullptr;
}

void read_values(const toml::table& root, const Origins& origins, Problems& problems, Scene& scene) {
  Reader r(root, origins, problems, scene);
  for (const KeySpec& k : key_specs())
    if (k.read)
      if (const toml::node* n = r.node(k.doc.key)) k.read(r, k.doc.key, *n, scene);
  read_panels(root, problems, scene);
}

}  // namespace arnoldweb::scene_detail

namespace arnoldweb {

const std::vector<SceneKey>& scene_keys() {
  static const std::vector<SceneKey> keys = [] {
    std::vector<SceneKey> k;
    for (const auto& s : scene_detail::key_specs()) k.push_back(s.doc);
    return k;
  }();
  return keys;
}

std::string scene_keys_markdown() {
  std::string t = "| Key | Type | Allowed | Default | Meaning |\n|---|---|---|---|---|\n";
  for (const auto& k : scene_keys())
    t += "| `" + k.key + "` | " + k.type + " | " + k.allowed + " | `" + k.default_value + "` | " + k.meaning + " |\n";
  return t;
}

}  // namespace arnoldweb
