// arnoldweb scene layer: from a TOML table to a Scene. Checks that every
// section and key is known, then reads and range-checks every value,
// recording where each key was written.
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/methods.hpp"
#include "scene/scene_internal.hpp"

namespace arnoldweb::scene_detail {
namespace {

const char* type_name(toml::node_type t) {
  switch (t) {
    case toml::node_type::table: return "table";
    case toml::node_type::array: return "array";
    case toml::node_type::string: return "string";
    case toml::node_type::integer: return "integer";
    case toml::node_type::floating_point: return "float";
    case toml::node_type::boolean: return "boolean";
    case toml::node_type::date: return "date";
    case toml::node_type::time: return "time";
    case toml::node_type::date_time: return "date-time";
    default: return "nothing";
  }
}

// A value as it would be written in TOML ("-5", "\"fast\"", "1e+06").
std::string show(const toml::node& n) {
  if (auto v = n.as_string()) return toml_string(v->get());
  if (auto v = n.as_integer()) return std::to_string(v->get());
  if (auto v = n.as_floating_point()) return show_double(v->get());
  if (auto v = n.as_boolean()) return v->get() ? "true" : "false";
  if (auto a = n.as_array()) {  // [1, 2, 3], long ones shortened
    std::string s = "[";
    for (std::size_t i = 0; i < a->size(); ++i) {
      if (i == 8) {
        s += ", ...";
        break;
      }
      s += (i ? ", " : "") + show(*a->get(i));
    }
    return s + "]";
  }
  if (n.is_table()) return "";
  std::ostringstream o;
  n.visit([&o](const auto& x) { o << x; });
  return o.str();
}

std::string join(const std::string& prefix, std::string_view key) {
  return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
}

std::string suggestion(const std::string& dotted) {
  const std::string near = closest_key(dotted);
  return near.empty() ? std::string(" ") : "; did you mean '" + near + "'? ";
}

void check_table(const toml::table& t, const std::string& prefix, Problems& problems) {
  std::string section_list;
  for (const std::string& s : sections()) section_list += (section_list.empty() ? "" : ", ") + s;
  for (auto&& [k, v] : t) {
    const std::string dotted = join(prefix, k.str());
    if (prefix.empty() && dotted == "panel") {
      // [[panel]]: an array of tables with the keys panel.*
      const toml::array* panels = v.as_array();
      if (!panels || !panels->is_array_of_tables()) {
        problems.at(dotted, v.source(), "must be written as [[panel]] tables (an array of tables)");
        continue;
      }
      for (const toml::node& panel : *panels) check_table(*panel.as_table(), "panel", problems);
      continue;
    }
    if (prefix.empty()) {
      if (!is_section(dotted)) {
        problems.at(dotted, k.source(),
                    v.is_table() ? "unknown section" + suggestion(dotted) + "(sections: " +
                                       section_list + ")"
                                 : "unknown key" + suggestion(dotted) +
                                       "(every key belongs to a section: " + section_list + ")");
      } else if (!v.is_table()) {
        problems.at(dotted, v.source(),
                    std::string("must be a table (the section [") + dotted + "]), got " +
                        type_name(v.type()) + " " + show(v));
      } else {
        check_table(*v.as_table(), dotted, problems);
      }
      continue;
    }
    const KeySpec* spec = find_spec(dotted);
    if (!spec) {
      const bool in_section = is_section(prefix);
      problems.at(dotted, k.source(),
                  "unknown key" + suggestion(dotted) + "(keys of " +
                      (in_section ? "[" + prefix + "]" : prefix) + ": " + keys_of(prefix) + ")");
    } else if (spec->shape == Shape::Composite && v.is_table()) {
      check_table(*v.as_table(), dotted, problems);
    }
  }
}

bool is_power_of_two(std::int64_t v) { return v > 0 && (v & (v - 1)) == 0; }

// Reads values of the merged table, each checked against its key's spec.
class Reader {
 public:
  Reader(const toml::table& root, const Origins& origins, Problems& problems, Scene& scene)
      : root_(root), origins_(origins), problems_(problems), scene_(scene) {}

  // The node of a dotted key, or nullptr if absent; records its position.
  const toml::node* node(const std::string& dotted) {
    const toml::table* t = &root_;
    std::size_t start = 0;
    while (true) {
      const std::size_t dot = dotted.find('.', start);
      const std::string part = dotted.substr(start, dot == std::string::npos ? dot : dot - start);
      auto it = t->find(part);
      if (it == t->end()) return nullptr;
      if (dot == std::string::npos) {
        SourcePos p;
        if (const int set = origins_.set_for(dotted)) {
          p.set_index = set;
        } else {
          p.line = static_cast<int>(it->first.source().begin.line);
          p.column = static_cast<int>(it->first.source().begin.column);
        }
        scene_.where[dotted] = p;
        return &it->second;
      }
      t = it->second.as_table();
      if (!t) return nullptr;  // reported by check_structure
      start = dot + 1;
    }
  }

  // "must be <spec phrase>, got <value>"; the value's type is named when it
  // is not one the key accepts.
  void bad(const std::string& key, const toml::node& n, bool accepted_type,
           const std::string& extra = "") {
    std::string got = show(n);
    if (!accepted_type) got = std::string(type_name(n.type())) + (got.empty() ? "" : " " + got);
    problems_.at(key, n.source(), "must be " + find_spec(key)->must + ", got " + got + extra);
  }

  template <class Ok>
  bool real_at(const std::string& key, const toml::node& n, double& out, Ok ok) {
    double v;
    if (auto f = n.as_floating_point()) {
      v = f->get();
    } else if (auto i = n.as_integer()) {
      v = static_cast<double>(i->get());
    } else {
      bad(key, n, false);
      return false;
    }
    if (!std::isfinite(v) || !ok(v)) {
      bad(key, n, true);
      return false;
    }
    out = v;
    return true;
  }

  template <class Ok>
  bool real(const std::string& key, double& out, Ok ok) {
    const toml::node* n = node(key);
    return n && real_at(key, *n, out, ok);
  }

  template <class Ok>
  bool integer(const std::string& key, std::int64_t& out, Ok ok) {
    const toml::node* n = node(key);
    if (!n) return false;
    if (auto i = n->as_integer()) {
      if (!ok(i->get())) {
        bad(key, *n, true);
        return false;
      }
      out = i->get();
      return true;
    }
    std::string hint;
    if (auto f = n->as_floating_point()) {
      const double v = f->get();
      if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9e15 &&
          ok(static_cast<std::int64_t>(v)))
        hint = " (write it as an integer: " + std::to_string(static_cast<std::int64_t>(v)) +
               "; TOML allows 1_000_000)";
    }
    bad(key, *n, false, hint);
    return false;
  }

  // An array of numbers (ints accepted as floats); n > 0: exactly n of them.
  template <class Ok>
  bool reals(const std::string& key, std::vector<double>& out, std::size_t n, Ok ok) {
    const toml::node* node_ = node(key);
    if (!node_) return false;
    const toml::array* a = node_->as_array();
    if (!a) {
      bad(key, *node_, false);
      return false;
    }
    std::vector<double> v;
    for (const toml::node& e : *a) {
      if (auto f = e.as_floating_point()) v.push_back(f->get());
      else if (auto i = e.as_integer()) v.push_back(static_cast<double>(i->get()));
      else {
        bad(key, *node_, true, " (an element is a " + std::string(type_name(e.type())) + ")");
        return false;
      }
      if (!std::isfinite(v.back())) {
        bad(key, *node_, true);
        return false;
      }
    }
    if ((n && v.size() != n) || !ok(v)) {
      bad(key, *node_, true, " (" + std::to_string(v.size()) + " values)");
      return false;
    }
    out = v;
    return true;
  }

  template <class Ok>
  bool pair(const std::string& key, std::array<double, 2>& out, Ok ok) {
    std::vector<double> v;
    if (!reals(key, v, 2, [&](const std::vector<double>& x) { return ok(x[0], x[1]); })) return false;
    out = {v[0], v[1]};
    return true;
  }

  // A composite key: false (off), or a table of sub-keys (on).
  bool table_or_false(const std::string& key, bool& on) {
    const toml::node* n = node(key);
    if (!n) return false;
    if (auto b = n->as_boolean()) {
      if (b->get()) {
        bad(key, *n, true, " (true is not enough: give the table)");
        return false;
      }
      on = false;
      return false;
    }
    if (n->is_table()) {
      on = true;
      return true;
    }
    bad(key, *n, false);
    return false;
  }

  bool boolean(const std::string& key, bool& out) {
    const toml::node* n = node(key);
    if (!n) return false;
    if (auto b = n->as_boolean()) {
      out = b->get();
      return true;
    }
    bad(key, *n, false);
    return false;
  }

  template <class Ok>
  bool text_at(const std::string& key, const toml::node& n, std::string& out, Ok ok,
               const std::vector<std::string>& near_misses = {}) {
    auto s = n.as_string();
    if (!s) {
      bad(key, n, false);
      return false;
    }
    if (!ok(s->get())) {
      const std::string near = closest_word(s->get(), near_misses);
      bad(key, n, true, near.empty() ? "" : "; did you mean \"" + near + "\"?");
      return false;
    }
    out = s->get();
    return true;
  }

  template <class Ok>
  bool text(const std::string& key, std::string& out, Ok ok,
            const std::vector<std::string>& near_misses = {}) {
    const toml::node* n = node(key);
    return n && text_at(key, *n, out, ok, near_misses);
  }

  bool choice(const std::string& key, std::string& out, const std::vector<std::string>& allowed) {
    return text(
        key, out,
        [&](const std::string& v) {
          for (const std::string& a : allowed)
            if (a == v) return true;
          return false;
        },
        allowed);
  }

 private:
  const toml::table& root_;
  const Origins& origins_;
  Problems& problems_;
  Scene& scene_;
};

}  // namespace

int Origins::set_for(const std::string& dotted) const {
  std::string k = dotted;
  while (true) {
    auto it = set_of.find(k);
    if (it != set_of.end()) return it->second;
    const auto dot = k.rfind('.');
    if (dot == std::string::npos) return 0;
    k.resize(dot);
  }
}

std::string Origins::source_name(int set_index) const {
  if (set_index <= 0) return file;
  const auto i = static_cast<std::size_t>(set_index - 1);
  if (i < labels.size() && !labels[i].empty()) return labels[i];
  return "--set " + sets[i];
}

void Problems::at(const std::string& key, const toml::source_region& where, std::string message) {
  Problem p;
  p.key = key;
  p.message = std::move(message);
  p.set_index = origins_.set_for(key);
  if (!p.set_index) {
    p.line = static_cast<int>(where.begin.line);
    p.column = static_cast<int>(where.begin.column);
  }
  add(std::move(p));
}

void Problems::throw_first() const {
  const Problem* first = nullptr;
  for (const Problem& p : list_) {
    auto rank = [](const Problem& q) { return std::make_tuple(q.set_index, q.line, q.column); };
    if (!first || rank(p) < rank(*first)) first = &p;
  }
  throw SceneError(origins_.source_name(first->set_index), first->line, first->column, first->key,
                   first->message);
}

void check_structure(const toml::table& root, Problems& problems) {
  check_table(root, "", problems);
}

void read_values(const toml::table& root, const Origins& origins, Problems& problems,
                 Scene& s) {
  Reader r(root, origins, problems, s);
  std::int64_t i = 0;
  const auto at_least_0 = [](std::int64_t v) { return v >= 0; };
  const auto positive = [](double v) { return v > 0; };

  // [model]
  r.real("model.energy", s.energy, [](double e) { return e > kMinEnergy && e <= kMaxEnergy; });

  // [ensemble]
  if (r.integer("ensemble.trajectories", i,
                [](std::int64_t v) { return v >= 1 && v <= kMaxTrajectories; }))
    s.trajectories = static_cast<std::uint64_t>(i);
  if (r.integer("ensemble.seed", i, at_least_0)) s.seed = static_cast<std::uint64_t>(i);
  r.choice("ensemble.initial", s.initial, initial_kinds());
  if (r.integer("ensemble.chunk", i, at_least_0)) s.chunk = static_cast<std::uint64_t>(i);
  const auto direction = [](double, double lat) { return lat >= -90 && lat <= 90; };
  for (const char* table : {"ensemble.cap", "ensemble.box", "ensemble.gaussian"})
    if (const toml::node* n = r.node(table); n && !n->is_table()) r.bad(table, *n, false);
  r.pair("ensemble.cap.center", s.cap_center, direction);
  r.real("ensemble.cap.radius", s.cap_radius, [](double v) { return v > 0 && v <= 180; });
  r.pair("ensemble.box.lon", s.box_lon, [](double a, double b) { return a < b && b <= a + 360; });
  r.pair("ensemble.box.lat", s.box_lat,
         [](double a, double b) { return a >= -90 && a < b && b <= 90; });
  r.pair("ensemble.gaussian.mean", s.gaussian_mean, [](double, double) { return true; });
  r.pair("ensemble.gaussian.sigma", s.gaussian_sigma, [](double a, double b) { return a > 0 && b > 0; });

  // [integrator]
  std::vector<std::string> method_list;
  for (const Method& m : methods()) method_list.push_back(m.name);
  r.choice("integrator.method", s.method, method_list);
  if (const toml::node* n = r.node("integrator.step")) {
    std::string word;
    if (n->is_string()) {
      if (r.text_at("integrator.step", *n, word, [](const std::string& v) { return v == "auto"; },
                    {"auto"}))
        s.step_auto = true;
    } else if (r.real_at("integrator.step", *n, s.step,
                         [](double h) { return h > 0 && h <= kMaxStep; })) {
      s.step_auto = false;
    }
  }
  r.real("integrator.tolerance", s.tolerance, [](double t) { return t > 0 && t < 1; });
  std::string word;
  if (r.choice("integrator.precision", word, names_of(precision_names())))
    for (const auto& p : precision_names())
      if (word == p.name) s.precision = p.value;
  if (r.choice("integrator.math", word, names_of(math_names())))
    for (const auto& m : math_names())
      if (word == m.name) s.math = m.value;
  r.boolean("integrator.allow_unsafe_step", s.allow_unsafe_step);

  // [run]
  r.real("run.average", s.average, positive);
  r.real("run.duration", s.duration, positive);
  r.text("run.device", s.device, valid_device);

  // [observe]
  if (const toml::node* n = r.node("observe.velocity_map")) {
    if (auto b = n->as_boolean()) {
      s.velocity_map = b->get();
    } else if (n->is_table()) {
      s.velocity_map = true;
      if (r.integer("observe.velocity_map.nside", i,
                    [](std::int64_t v) { return v <= kMaxNside && is_power_of_two(v); }))
        s.nside = static_cast<int>(i);
    } else {
      r.bad("observe.velocity_map", *n, false);
    }
  }
  if (const toml::node* n = r.node("observe.energy_error")) {
    if (auto b = n->as_boolean()) {
      s.energy_error = b->get();
    } else if (n->is_table()) {
      s.energy_error = true;
      r.real("observe.energy_error.every", s.energy_every, positive);
    } else {
      r.bad("observe.energy_error", *n, false);
    }
  }
  double limit = 0;
  if (r.real("observe.max_energy_error", limit, positive)) s.max_energy_error = limit;
  r.boolean("observe.initial_states", s.initial_states);
  r.boolean("observe.final_states", s.final_states);
  const auto width = [](double w) { return w > 0 && w < 120; };
  if (r.table_or_false("observe.zoom", s.zoom)) {
    r.pair("observe.zoom.center", s.zoom_center, direction);
    r.real("observe.zoom.width", s.zoom_width, width);
    if (r.integer("observe.zoom.resolution", i, [](std::int64_t v) { return v >= 16 && v <= 8192; }))
      s.zoom_resolution = static_cast<int>(i);
  }
  if (r.table_or_false("observe.confine", s.confine)) {
    r.pair("observe.confine.center", s.confine_center, direction);
    r.real("observe.confine.width", s.confine_width, width);
  }
  bool frames = false;
  if (r.table_or_false("observe.frames", frames))
    r.reals("observe.frames.times", s.frame_times, 0, [](const std::vector<double>& t) {
      if (t.size() < 2 || t.size() > 65 || t[0] < 0) return false;
      for (std::size_t k = 1; k < t.size(); ++k)
        if (!(t[k] > t[k - 1])) return false;
      return true;
    });

  // [output]
  r.text("output.dir", s.output_dir, [](const std::string& d) { return !d.empty(); });
  r.boolean("output.images", s.images);

  // [[panel]]
  if (const toml::node* n = root.get("panel"); n && n->is_array()) {
    for (const toml::node& e : *n->as_array()) {
      const toml::table* t = e.as_table();
      if (!t) continue;  // reported by check_structure
      Scene::Panel panel;
      const toml::node* name = t->get("name");
      if (s.panels.empty())  // positions of the first panel's keys
        for (auto&& [k, v] : *t) {
          SourcePos p;
          p.line = static_cast<int>(k.source().begin.line);
          p.column = static_cast<int>(k.source().begin.column);
          s.where["panel." + std::string(k.str())] = p;
        }
      const std::string at = "panel";
      if (!name || !name->is_string() || name->as_string()->get().empty() ||
          name->as_string()->get().find_first_not_of(
              "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_") != std::string::npos) {
        problems.at("panel.name", name ? name->source() : e.source(),
                    "must be " + find_spec("panel.name")->must);
        continue;
      }
      panel.name = name->as_string()->get();
      for (const Scene::Panel& other : s.panels)
        if (other.name == panel.name) problems.at("panel.name", name->source(), "names panel \"" + panel.name + "\" twice");
      if (const toml::node* title = t->get("title")) {
        if (title->is_string()) panel.title = title->as_string()->get();
        else problems.at("panel.title", title->source(), "must be a string");
      }
      if (const toml::node* set = t->get("set")) {
        const toml::array* a = set->as_array();
        bool good = a != nullptr;
        if (a)
          for (const toml::node& x : *a) {
            if (!x.is_string() || x.as_string()->get().find('=') == std::string::npos) good = false;
            else panel.sets.push_back(x.as_string()->get());
          }
        if (!good) problems.at("panel.set", set->source(), "must be " + find_spec("panel.set")->must);
      }
      s.panels.push_back(std::move(panel));
    }
  }
}

}  // namespace arnoldweb::scene_detail
