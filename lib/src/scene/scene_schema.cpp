// arnoldweb scene layer: the key table. One row per key: its documentation,
// the phrase its error messages use, and how to_toml() writes its value.
// Adding a key: a row here, a read in scene_read.cpp, a field in Scene.
#include <algorithm>
#include <cctype>

#include "arnoldweb/methods.hpp"
#include "scene/scene_internal.hpp"

namespace arnoldweb::scene_detail {
namespace {

std::string quoted_list(const std::vector<std::string>& names, const char* last_sep) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i) s += i + 1 == names.size() ? last_sep : ", ";
    s += "\"" + names[i] + "\"";
  }
  return s;
}

std::vector<std::string> method_name_list() {
  std::vector<std::string> n;
  for (const Method& m : methods()) n.push_back(m.name);
  return n;
}

// "one of "a", "b", "c"" (or just "a" when there is one).
std::string one_of(const std::vector<std::string>& names) {
  if (names.size() == 1) return "\"" + names[0] + "\"";
  return "one of " + quoted_list(names, ", ");
}

std::string boolean(bool b) { return b ? "true" : "false"; }

std::string pair(const std::array<double, 2>& v) {
  return "[" + toml_double(v[0]) + ", " + toml_double(v[1]) + "]";
}

std::string list(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + toml_double(v[i]);
  return s + "]";
}

std::vector<KeySpec> build() {
  const std::string device_forms = "\"auto\", \"cpu\", \"opencl:N\" or \"cuda:N\"";
  std::vector<KeySpec> k;
  auto add = [&k](std::string key, std::string type, std::string allowed, std::string must,
                  std::string (*literal)(const Scene&), std::string meaning,
                  Shape shape = Shape::Value) {
    KeySpec s;
    s.doc.key = std::move(key);
    s.doc.type = std::move(type);
    s.doc.allowed = std::move(allowed);
    s.doc.meaning = std::move(meaning);
    s.must = std::move(must);
    s.literal = literal;
    s.shape = shape;
    const std::string d = literal(Scene{});
    s.doc.default_value = d.empty() ? "(not set)" : d;
    k.push_back(std::move(s));
  };

  // [model]
  add("model.energy", "float", "> -2 and <= 1e6",
      "a float greater than -2 and at most 1e6 (for E <= -2 no phase space is accessible)",
      [](const Scene& s) { return toml_double(s.energy); },
      "Total energy E of every trajectory; the effective perturbation is 2/E.");

  // [ensemble]
  add("ensemble.trajectories", "integer", "1 to 1e13", "an integer from 1 to 1e13",
      [](const Scene& s) { return std::to_string(s.trajectories); },
      "Number of trajectories in the ensemble.");
  add("ensemble.seed", "integer", ">= 0", "an integer >= 0",
      [](const Scene& s) { return std::to_string(s.seed); },
      "Seed of the counter-based random numbers: trajectory i starts from a state that depends "
      "only on (seed, i), whatever the device or chunking.");
  add("ensemble.initial", "string", quoted_list(initial_kinds(), " or "), one_of(initial_kinds()),
      [](const Scene& s) { return toml_string(s.initial); },
      "How initial states are drawn; X is uniform on the accessible part of the torus. "
      "\"shell\": direction of P uniform on the sphere, speed sqrt(2 (E - V(X))). \"cap\", "
      "\"box\": direction uniform in ensemble.cap or ensemble.box. \"gaussian\": see "
      "ensemble.gaussian.");
  add("ensemble.chunk", "integer", ">= 0 (0 = automatic)", "an integer >= 0 (0 = automatic)",
      [](const Scene& s) { return std::to_string(s.chunk); },
      "Trajectories per kernel launch; 0 lets the runner choose. Does not change the results.");
  add("ensemble.cap", "table", "{ center = [lon, lat], radius = deg }",
      "a table { center = [lon, lat], radius = <degrees> }",
      [](const Scene& s) {
        return "{ center = " + pair(s.cap_center) + ", radius = " + toml_double(s.cap_radius) + " }";
      },
      "The spherical cap of momentum directions for ensemble.initial = \"cap\".", Shape::Composite);
  add("ensemble.cap.center", "array of 2 floats", "[lon, lat] in degrees, lat in [-90, 90]",
      "an array [longitude, latitude] in degrees, latitude from -90 to 90",
      [](const Scene& s) { return pair(s.cap_center); },
      "Centre of the cap: longitude and latitude of the momentum direction, in degrees "
      "(P along (cos lat cos lon, cos lat sin lon, sin lat)).");
  add("ensemble.cap.radius", "float", "> 0 and <= 180", "a float greater than 0 and at most 180 (degrees)",
      [](const Scene& s) { return toml_double(s.cap_radius); }, "Angular radius of the cap, degrees.");
  add("ensemble.box", "table", "{ lon = [a, b], lat = [c, d] }",
      "a table { lon = [from, to], lat = [from, to] } in degrees",
      [](const Scene& s) {
        return "{ lon = " + pair(s.box_lon) + ", lat = " + pair(s.box_lat) + " }";
      },
      "The longitude/latitude box of momentum directions for ensemble.initial = \"box\" "
      "(uniform in area).", Shape::Composite);
  add("ensemble.box.lon", "array of 2 floats", "[from, to], from < to <= from + 360",
      "an array [from, to] of longitudes in degrees with from < to <= from + 360",
      [](const Scene& s) { return pair(s.box_lon); }, "Longitude range of the box, degrees.");
  add("ensemble.box.lat", "array of 2 floats", "[from, to], -90 <= from < to <= 90",
      "an array [from, to] of latitudes in degrees with -90 <= from < to <= 90",
      [](const Scene& s) { return pair(s.box_lat); }, "Latitude range of the box, degrees.");
  add("ensemble.gaussian", "table", "{ mean = [p_x, p_y], sigma = [s_x, s_y] }",
      "a table { mean = [p_x, p_y], sigma = [s_x, s_y] }",
      [](const Scene& s) {
        return "{ mean = " + pair(s.gaussian_mean) + ", sigma = " + pair(s.gaussian_sigma) + " }";
      },
      "Gaussian initial momenta for ensemble.initial = \"gaussian\": p_x, p_y normal, p_z from "
      "the energy with a random sign (the paper's Figure 4: mean = [sqrt(E), sqrt(E)], sigma = "
      "[0.01, 0.01]).", Shape::Composite);
  add("ensemble.gaussian.mean", "array of 2 floats", "finite", "an array [p_x, p_y] of finite floats",
      [](const Scene& s) { return pair(s.gaussian_mean); }, "Mean of p_x and p_y.");
  add("ensemble.gaussian.sigma", "array of 2 floats", "> 0", "an array [s_x, s_y] of floats greater than 0",
      [](const Scene& s) { return pair(s.gaussian_sigma); }, "Standard deviations of p_x and p_y.");

  // [integrator]
  add("integrator.method", "string", quoted_list(method_name_list(), " or "),
      one_of(method_name_list()), [](const Scene& s) { return toml_string(s.method); },
      "Symplectic integration method (`arnoldweb methods` lists order and cost).");
  add("integrator.step", "float or \"auto\"", "> 0 and <= 1, or \"auto\"",
      "a float greater than 0 and at most 1 (the step in units of T = 2 pi) or \"auto\"",
      [](const Scene& s) { return s.step_auto ? std::string("\"auto\"") : toml_double(s.step); },
      "Integration step h in units of T = 2 pi. \"auto\": choose a step that meets "
      "integrator.tolerance.");
  add("integrator.tolerance", "float", "> 0 and < 1", "a float greater than 0 and less than 1",
      [](const Scene& s) { return toml_double(s.tolerance); },
      "Target largest energy error over the ensemble, used with integrator.step = \"auto\".");
  add("integrator.precision", "string", quoted_list(names_of(precision_names()), " or "),
      one_of(names_of(precision_names())),
      [](const Scene& s) { return toml_string(to_string(s.precision)); },
      "Floating-point type of the integration.");
  add("integrator.math", "string", quoted_list(names_of(math_names()), " or "),
      one_of(names_of(math_names())), [](const Scene& s) { return toml_string(to_string(s.math)); },
      "\"portable\": the same bits on every backend (own sin/cos, no contraction). \"native\": "
      "vendor functions where faster; results then differ between backends.");
  add("integrator.allow_unsafe_step", "boolean", "true or false", "true or false",
      [](const Scene& s) { return boolean(s.allow_unsafe_step); },
      "Run even when the step-size guard refuses the step (h k p_max >= pi).");

  // [run]
  add("run.average", "float", "> 0", "a finite float greater than 0 (in units of T)",
      [](const Scene& s) { return toml_double(s.average); },
      "Averaging window dt of the velocity, in T; a multiple of integrator.step.");
  add("run.duration", "float", "> 0", "a finite float greater than 0 (in units of T)",
      [](const Scene& s) { return toml_double(s.duration); },
      "Propagation time t_p, in T; a multiple of run.average.");
  add("run.device", "string", device_forms,
      device_forms + " (N = 0, 1, ...: the index in `arnoldweb devices`)",
      [](const Scene& s) { return toml_string(s.device); },
      "Where to run. \"auto\" picks the default device; whether the device exists is checked "
      "when the run starts.");

  // [observe]
  add("observe.velocity_map", "table or boolean", "{ nside = N }, true or false",
      "a table { nside = N }, true (nside 64) or false",
      [](const Scene& s) {
        return s.velocity_map ? "{ nside = " + std::to_string(s.nside) + " }" : boolean(false);
      },
      "HEALPix map of the directions of the averaged velocities; false: no map. true: the "
      "default nside.",
      Shape::Composite);
  add("observe.velocity_map.nside", "integer", "power of two, 1 to 8192",
      "a power of two from 1 to 8192", [](const Scene& s) { return std::to_string(s.nside); },
      "HEALPix resolution of the velocity map: 12 nside^2 pixels.");
  add("observe.energy_error", "boolean or table", "true, false or { every = dt }",
      "true, false or a table { every = <sample interval in T> }",
      [](const Scene& s) {
        return s.energy_error ? "{ every = " + toml_double(s.energy_every) + " }" : boolean(false);
      },
      "Track the energy error dE of every trajectory. A table sets the sample interval; true "
      "samples every 1 T.",
      Shape::Composite);
  add("observe.energy_error.every", "float", "> 0",
      "a finite float greater than 0 (sample interval in T)",
      [](const Scene& s) { return toml_double(s.energy_every); },
      "Interval between energy-error samples, in T; divides run.average.");
  add("observe.max_energy_error", "float", "> 0, or absent", "a finite float greater than 0",
      [](const Scene& s) {
        return s.max_energy_error ? toml_double(*s.max_energy_error) : std::string();
      },
      "Flag trajectories whose energy error abs(dE) exceeds this value (they are counted in "
      "the result); implies energy tracking. Absent: no limit.");
  add("observe.initial_states", "boolean", "true or false", "true or false",
      [](const Scene& s) { return boolean(s.initial_states); },
      "Write the initial state of every trajectory.");
  add("observe.final_states", "boolean", "true or false", "true or false",
      [](const Scene& s) { return boolean(s.final_states); },
      "Write the final state of every trajectory.");
  add("observe.zoom", "table or false", "{ center = [lon, lat], width = deg, resolution = R } or false",
      "a table { center = [lon, lat], width = <degrees>, resolution = R } or false",
      [](const Scene& s) {
        return s.zoom ? "{ center = " + pair(s.zoom_center) + ", width = " + toml_double(s.zoom_width) +
                            ", resolution = " + std::to_string(s.zoom_resolution) + " }"
                      : boolean(false);
      },
      "A high-resolution R x R histogram of the averaged velocities in a square region, in "
      "gnomonic projection about its centre (zoom panels).", Shape::Composite);
  add("observe.zoom.center", "array of 2 floats", "[lon, lat] in degrees, lat in [-90, 90]",
      "an array [longitude, latitude] in degrees, latitude from -90 to 90",
      [](const Scene& s) { return pair(s.zoom_center); }, "Centre of the zoom region, degrees.");
  add("observe.zoom.width", "float", "> 0 and < 120", "a float greater than 0 and less than 120 (degrees)",
      [](const Scene& s) { return toml_double(s.zoom_width); }, "Full angular width of the zoom square, degrees.");
  add("observe.zoom.resolution", "integer", "16 to 8192", "an integer from 16 to 8192",
      [](const Scene& s) { return std::to_string(s.zoom_resolution); }, "Bins per side of the zoom histogram.");
  add("observe.confine", "table or false", "{ center = [lon, lat], width = deg } or false",
      "a table { center = [lon, lat], width = <degrees> } or false",
      [](const Scene& s) {
        return s.confine ? "{ center = " + pair(s.confine_center) + ", width = " +
                               toml_double(s.confine_width) + " }"
                         : boolean(false);
      },
      "Region confinement: only trajectories whose momentum direction stays inside this square "
      "(gnomonic, checked at every energy sample) are binned; the others are counted as "
      "left_region.", Shape::Composite);
  add("observe.confine.center", "array of 2 floats", "[lon, lat] in degrees, lat in [-90, 90]",
      "an array [longitude, latitude] in degrees, latitude from -90 to 90",
      [](const Scene& s) { return pair(s.confine_center); }, "Centre of the confinement square, degrees.");
  add("observe.confine.width", "float", "> 0 and < 120", "a float greater than 0 and less than 120 (degrees)",
      [](const Scene& s) { return toml_double(s.confine_width); }, "Full angular width of the square, degrees.");
  add("observe.frames", "table or false", "{ times = [t0, t1, ...] } or false",
      "a table { times = [t0, t1, ...] } (in T) or false",
      [](const Scene& s) {
        return s.frame_times.empty() ? boolean(false) : "{ times = " + list(s.frame_times) + " }";
      },
      "Time series: frame k is the velocity map of the windows starting in [t_k, t_k+1) (a "
      "diffusion movie).", Shape::Composite);
  add("observe.frames.times", "array of floats", "2 to 65 increasing times >= 0, multiples of run.average",
      "an array of 2 to 65 increasing times >= 0 (in T)",
      [](const Scene& s) { return s.frame_times.empty() ? std::string() : list(s.frame_times); },
      "Frame boundaries, in T.");

  // [output]
  add("output.dir", "string", "non-empty path", "a non-empty string (a directory path)",
      [](const Scene& s) { return toml_string(s.output_dir); },
      "Directory the outputs are written to.");
  add("output.images", "boolean", "true or false", "true or false",
      [](const Scene& s) { return boolean(s.images); }, "Write images of the maps.");

  // [[panel]] (an array of tables; to_toml writes them after the sections)
  add("panel.name", "string", "letters, digits, - and _", "a non-empty string of letters, digits, - and _",
      [](const Scene&) { return std::string(); },
      "Name of a further run of this scene drawn as an inset of the same figure; its outputs go "
      "to <output.dir>/panel-<name>.");
  add("panel.title", "string", "any", "a string", [](const Scene&) { return std::string(); },
      "Caption of the panel.");
  add("panel.set", "array of strings", "key=value overrides", "an array of \"key=value\" strings",
      [](const Scene&) { return std::string(); },
      "Overrides applied to the scene for this panel, written like --set.");
  return k;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string parent_of(const std::string& k) {
  const auto dot = k.rfind('.');
  return dot == std::string::npos ? std::string() : k.substr(0, dot);
}

std::string leaf_of(const std::string& k) {
  const auto dot = k.rfind('.');
  return dot == std::string::npos ? k : k.substr(dot + 1);
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

const std::vector<std::string>& sections() {
  static const std::vector<std::string> s = {"model", "ensemble", "integrator",
                                             "run",   "observe",  "output"};
  return s;
}

bool is_section(const std::string& name) {
  const auto& s = sections();
  return std::find(s.begin(), s.end(), name) != s.end();
}

std::string closest_key(const std::string& unknown) {
  const std::string u = lower(unknown);
  const std::string u_parent = parent_of(u), u_leaf = leaf_of(u);
  // A typo scores its edit distance; the right name in the wrong section
  // scores 2 more than the distance of the last parts.
  std::vector<std::string> candidates;
  if (u_parent.empty()) candidates = sections();
  for (const KeySpec& s : key_specs()) candidates.push_back(s.doc.key);
  std::string best;
  std::size_t best_score = std::max<std::size_t>(2, u_leaf.size() / 2) + 1;
  for (const std::string& c : candidates) {
    std::size_t score = edit_distance(u, c);
    if (parent_of(c) != u_parent)
      score = std::min(score, edit_distance(u_leaf, leaf_of(c)) + 2);
    if (score < best_score) {
      best_score = score;
      best = c;
    }
  }
  return best == unknown ? std::string() : best;
}

std::string closest_word(const std::string& word, const std::vector<std::string>& words) {
  std::string best;
  std::size_t best_score = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string& w : words) {
    const std::size_t score = edit_distance(lower(word), lower(w));
    if (score < best_score) {
      best_score = score;
      best = w;
    }
  }
  return best;
}

std::string keys_of(const std::string& parent) {
  std::string s;
  for (const KeySpec& k : key_specs())
    if (parent_of(k.doc.key) == parent) s += (s.empty() ? "" : ", ") + leaf_of(k.doc.key);
  return s;
}

const std::vector<std::string>& initial_kinds() {
  static const std::vector<std::string> k = {"shell", "cap", "box", "gaussian"};
  return k;
}

const std::vector<PrecisionName>& precision_names() {
  static const std::vector<PrecisionName> n = {{"double", Precision::Double},
                                               {"float", Precision::Float}};
  return n;
}

const std::vector<MathName>& math_names() {
  static const std::vector<MathName> n = {{"portable", MathMode::Portable},
                                          {"native", MathMode::Native}};
  return n;
}

bool valid_device(const std::string& id) {
  if (id == "auto" || id == "cpu") return true;
  for (const char* prefix : {"opencl:", "cuda:"}) {
    const std::string p = prefix;
    if (id.compare(0, p.size(), p) != 0) continue;
    const std::string n = id.substr(p.size());
    return !n.empty() && n.size() <= 9 &&
           std::all_of(n.begin(), n.end(), [](char c) { return c >= '0' && c <= '9'; });
  }
  return false;
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

}  // namespace arnoldweb
