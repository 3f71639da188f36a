// arnoldweb scene layer: reading one TOML value into a field of a Scene,
// with its type and range checked. A problem is recorded (Problems) with the
// key, where it was written and the key's "must be ..." phrase from the key
// table; reading then goes on, so the first problem in file order is thrown.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene_internal.hpp"

namespace arnoldweb::scene_detail {

const char* type_name(toml::node_type t);
// A value as it would be written in TOML ("-5", "\"fast\"", "[1, 2]").
std::string show(const toml::node& n);

class Reader {
 public:
  Reader(const toml::table& root, const Origins& origins, Problems& problems, Scene& scene)
      : root_(root), origins_(origins), problems_(problems), scene_(scene) {}

  // The node of a dotted key, or nullptr if absent; records its position.
  const toml::node* node(const std::string& dotted);

  // "must be <spec phrase>, got <value>"; the value's type is named when it
  // is not one the key accepts.
  void bad(const std::string& key, const toml::node& n, bool accepted_type, const std::string& extra = "");

  // Each reads `n` into `out` if it has the right type and `ok` accepts it;
  // returns whether it did (a problem is recorded otherwise).
  template <class Ok>
  bool real(const std::string& key, const toml::node& n, double& out, Ok ok) {
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
  bool integer(const std::string& key, const toml::node& n, std::int64_t& out, Ok ok) {
    if (auto i = n.as_integer()) {
      if (!ok(i->get())) {
        bad(key, n, true);
        return false;
      }
      out = i->get();
      return true;
    }
    std::string hint;
    if (auto f = n.as_floating_point()) {
      const double v = f->get();
      if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9e15 && ok(static_cast<std::int64_t>(v)))
        hint = " (write it as an integer: " + std::to_string(static_cast<std::int64_t>(v)) + "; TOML allows 1_000_000)";
    }
    bad(key, n, false, hint);
    return false;
  }

  // An array of numbers (integers accepted as floats); count > 0: exactly that many.
  template <class Ok>
  bool reals(const std::string& key, const toml::node& n, std::vector<double>& out, std::size_t count, Ok ok) {
    const toml::array* a = n.as_array();
    if (!a) {
      bad(key, n, false);
      return false;
    }
    std::vector<double> v;
    for (const toml::node& e : *a) {
      if (auto f = e.as_floating_point()) v.push_back(f->get());
      else if (auto i = e.as_integer()) v.push_back(static_cast<double>(i->get()));
      else {
        bad(key, n, true, " (an element is a " + std::string(type_name(e.type())) + ")");
        return false;
      }
      if (!std::isfinite(v.back())) {
        bad(key, n, true);
        return false;
      }
    }
    if ((count && v.size() != count) || !ok(v)) {
      bad(key, n, true, " (" + std::to_string(v.size()) + " values)");
      return false;
    }
    out = v;
    return true;
  }

  template <class Ok>
  bool pair(const std::string& key, const toml::node& n, std::array<double, 2>& out, Ok ok) {
    std::vector<double> v;
    if (!reals(key, n, v, 2, [&](const std::vector<double>& x) { return ok(x[0], x[1]); })) return false;
    out = {v[0], v[1]};
    return true;
  }

  bool boolean(const std::string& key, const toml::node& n, bool& out);

  template <class Ok>
  bool text(const std::string& key, const toml::node& n, std::string& out, Ok ok,
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

  bool choice(const std::string& key, const toml::node& n, std::string& out, const std::vector<std::string>& allowed);

  // A switchable table: false (off), true (on, defaults) if `true_allowed`,
  // or a table of sub-keys (on). Returns whether it read a value.
  bool switch_table(const std::string& key, const toml::node& n, bool& on, bool true_allowed);

  Problems& problems() { return problems_; }

 private:
  const toml::table& root_;
  const Origins& origins_;
  Problems& problems_;
  Scene& scene_;
};

}  // namespace arnoldweb::scene_detail
