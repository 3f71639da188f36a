// arnoldweb explorer: the API of `serve` by method and path (router.hpp).
#include "router.hpp"

#include <algorithm>

namespace arnoldweb::explorer {
namespace {

// "/api/runs/r0" -> {api, runs, r0}; "/" -> {""}
std::vector<std::string> split(const std::string& path) {
  std::vector<std::string> out;
  std::size_t from = 1;
  for (std::size_t slash; (slash = path.find('/', from)) != std::string::npos; from = slash + 1)
    out.push_back(path.substr(from, slash - from));
  out.push_back(path.substr(from));
  return out;
}

bool is_id(const std::string& s) {
  if (s.size() < 2 || s.size() > 7 || s[0] < 'a' || s[0] > 'z') return false;
  return std::all_of(s.begin() + 1, s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool matches(const std::vector<std::string>& pattern, const std::vector<std::string>& segments, Router::Args* args) {
  if (pattern.size() != segments.size()) return false;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] == ":name" || (pattern[i] == ":id" && is_id(segments[i])))
      args->push_back(segments[i]);
    else if (pattern[i] != segments[i])
      return false;
  }
  return true;
}

}  // namespace

std::string shown(const std::string& text) { return text.size() <= 100 ? text : text.substr(0, 100) + "..."; }

void Router::get(const std::string& pattern, Answer a) { routes_.push_back({"GET", split(pattern), std::move(a)}); }
void Router::post(const std::string& pattern, Answer a) { routes_.push_back({"POST", split(pattern), std::move(a)}); }

HttpAnswer Router::operator()(const HttpRequest& req) const {
  if (req.method != "GET" && req.method != "HEAD" && req.method != "POST")
    return refusal(405, "method " + shown(req.method) + " is not served (GET, HEAD and POST only)");
  if (req.target.find('?') != std::string::npos)  // everything a page asks is in the path or the body
    return refusal(400, "this server takes no query parameters");
  if (req.target.empty() || req.target[0] != '/') return refusal(404, "no such page or run: " + shown(req.target));
  const std::vector<std::string> segments = split(req.target);
  const std::string method = req.method == "HEAD" ? "GET" : req.method;
  bool other_method = false;
  for (const auto& r : routes_) {
    Args args;
    if (!matches(r.pattern, segments, &args)) continue;
    if (r.method == method) return r.answer(args, req);
    other_method = true;
  }
  if (other_method) return refusal(405, req.method + " is not served at " + shown(req.target));
  return refusal(404, "no such page or run: " + shown(req.target));
}

}  // namespace arnoldweb::explorer
