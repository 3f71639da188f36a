// arnoldweb scene layer: reading values (reader.hpp), where they came from
// (Origins) and the problems found (Problems).
#include "scene/reader.hpp"

#include <algorithm>
#include <sstream>
#include <tuple>

#include "arnoldweb/errors.hpp"

namespace arnoldweb::scene_detail {

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

const toml::node* Reader::node(const std::string& dotted) {
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

void Reader::bad(const std::string& key, const toml::node& n, bool accepted_type, const std::string& extra) {
  std::string got = show(n);
  if (!accepted_type) got = std::string(type_name(n.type())) + (got.empty() ? "" : " " + got);
  problems_.at(key, n.source(), "must be " + find_spec(key)->must + ", got " + got + extra);
}

bool Reader::boolean(const std::string& key, const toml::node& n, bool& out) {
  if (auto b = n.as_boolean()) {
    out = b->get();
    return true;
  }
  bad(key, n, false);
  return false;
}

bool Reader::choice(const std::string& key, const toml::node& n, std::string& out,
                    const std::vector<std::string>& allowed) {
  return text(
      key, n, out, [&](const std::string& v) { return std::find(allowed.begin(), allowed.end(), v) != allowed.end(); },
      allowed);
}

bool Reader::switch_table(const std::string& key, const toml::node& n, bool& on, bool true_allowed) {
  if (auto b = n.as_boolean()) {
    if (b->get() && !true_allowed) {
      bad(key, n, true, " (true is not enough: give the table)");
      return false;
    }
    on = b->get();
    return true;
  }
  if (n.is_table()) {
    on = true;
    return true;
  }
  bad(key, n, false);
  return false;
}

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

}  // namespace arnoldweb::scene_detail
