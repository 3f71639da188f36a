// arnoldweb explorer: the API of `serve` by method and path, and the refusals of what it does
// not know (404, 405, query parameters 400, methods other than GET, HEAD and POST 405). A
// pattern's segments are literal, ":id" (a run's or a zoom's id, [a-z][0-9]{1,6}) or ":name"
// (any one segment: a page file's name, looked up exactly by its route). The target is matched
// as sent, not decoded: no name the server knows has a '%', a '.' segment or a '/'.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "http_server.hpp"

namespace arnoldweb::explorer {

class Router {
 public:
  using Args = std::vector<std::string>;  // what the pattern's ":" segments matched, in order
  using Answer = std::function<HttpAnswer(const Args&, const HttpRequest&)>;

  void get(const std::string& pattern, Answer a);  // answers HEAD too (the transport drops the body)
  void post(const std::string& pattern, Answer a);
  HttpAnswer operator()(const HttpRequest& req) const;

 private:
  struct Route {
    std::string method;
    std::vector<std::string> pattern;
    Answer answer;
  };
  std::vector<Route> routes_;
};

// What an answer may quote back of a request: at most 100 characters of it.
std::string shown(const std::string& text);

}  // namespace arnoldweb::explorer
