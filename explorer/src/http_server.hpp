// arnoldweb explorer: the HTTP transport of `serve` (Boost.Beast over Boost.Asio; plain
// HTTP/1.0 and 1.1, no TLS). It hands each complete request, within its bounds, to one function
// and writes that function's answer; what the requests mean is server.cpp's. It bounds what a
// client can make it hold: the request line (414), the whole header (431), the body (413; the
// connection is then closed without reading the body), the time to send a request and the time
// without progress while taking an answer (the connection is closed: a slow client holds no
// thread), the connections open at once (further ones are closed at once). Malformed HTTP is
// answered 400 and the connection closed. Several threads run it, so a slow answer (a zoom being
// planned) holds up no other connection. Beast stays inside http_server.cpp.
#pragma once

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace arnoldweb::explorer {

struct HttpRequest {
  std::string method;  // as sent: "GET", "HEAD", "POST", ...
  std::string target;  // as sent, not decoded: "/api/runs/r0"
  std::string body;
};

struct HttpAnswer {
  int status = 200;
  std::string content_type;
  std::string_view body;              // into `owner`, or into static storage (the embedded page)
  std::shared_ptr<const void> owner;  // keeps `body` alive while it is written
};
HttpAnswer json_answer(int status, const nlohmann::json& body);
// {"error": why}: every refusal, the transport's and the routes'
HttpAnswer refusal(int status, const std::string& why);

struct HttpLimits {
  std::size_t max_body = 64 * 1024;          // 413 above
  std::size_t max_request_line = 8 * 1024;   // 414 above
  std::size_t max_header = 16 * 1024;        // request line and fields together; 431 above
  std::chrono::seconds request_time{5};      // to send a whole request, from when the server waits for it
  std::chrono::seconds answer_stall{30};     // without progress while an answer is taken
  std::chrono::seconds linger{2};            // after a refusal, to let the client finish sending and read it
  std::size_t max_connections = 256;         // open at once; further ones are closed at once
  unsigned threads = 0;                      // 0: max(8, cores), at most 16 (handlers may block)
};

class HttpServer {
 public:
  using Handler = std::function<HttpAnswer(const HttpRequest&)>;
  // Binds host:port (port 0: any free one) and listens with the system's largest backlog
  // (SO_REUSEADDR); OutputError naming host:port if it cannot. `headers` go on every answer.
  HttpServer(const std::string& host, int port, HttpLimits limits,
             std::vector<std::pair<std::string, std::string>> headers, Handler handler);
  ~HttpServer();  // stop()
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  int port() const;
  void start();  // the threads that serve
  void stop();   // stops listening, drops every connection; returns when the threads have ended

  struct State;

 private:
  std::unique_ptr<State> state_;
};

}  // namespace arnoldweb::explorer
