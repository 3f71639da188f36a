// arnoldweb explorer: the HTTP transport of `serve` on Boost.Beast (http_server.hpp). One
// Session per connection, on a strand of an io_context that several threads run: read one
// request with the parser's limits under a deadline, hand it to the handler, write the answer a
// piece at a time (each piece under a deadline), then read the next or close. Written against
// Boost 1.74 (Debian 12) and 1.83 (Ubuntu 24.04).
#include "http_server.hpp"

#include <boost/asio/dispatch.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <algorithm>
#include <atomic>
#include <iostream>
#include <optional>
#include <thread>

#include "arnoldweb/errors.hpp"

namespace arnoldweb::explorer {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
using tcp = net::ip::tcp;

HttpAnswer json_answer(int status, const nlohmann::json& body) {
  auto text = std::make_shared<const std::string>(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  const std::string_view view = *text;
  return {status, "application/json", view, std::move(text)};
}

HttpAnswer refusal(int status, const std::string& why) { return json_answer(status, {{"error", why}}); }

struct HttpServer::State {
  State(HttpLimits l, std::vector<std::pair<std::string, std::string>> h, Handler f)
      : limits(l), headers(std::move(h)), handler(std::move(f)) {}
  void accept();

  const HttpLimits limits;
  const std::vector<std::pair<std::string, std::string>> headers;
  const Handler handler;
  std::atomic<std::size_t> connections{0};
  // the io_context after what its pending handlers (the sessions) use, so that it is destroyed first
  net::io_context ioc;
  tcp::acceptor acceptor{ioc};
  net::steady_timer retry{ioc};
  std::vector<std::thread> threads;
};

namespace {

using Answer = http::response<http::span_body<const char>>;

class Session : public std::enable_shared_from_this<Session> {
 public:
  Session(tcp::socket&& socket, HttpServer::State& server) : stream_(std::move(socket)), server_(server) {}
  ~Session() { --server_.connections; }

  void start() {
    net::dispatch(stream_.get_executor(), [self = shared_from_this()] { self->read(); });
  }

 private:
  const HttpLimits& limits() const { return server_.limits; }

  void read() {
    parser_.emplace();
    parser_->header_limit(static_cast<std::uint32_t>(limits().max_header));
    parser_->body_limit(static_cast<std::uint64_t>(limits().max_body));
    stream_.expires_after(limits().request_time);
    http::async_read(stream_, buffer_, *parser_,
                     [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_read(ec); });
  }

  void on_read(beast::error_code ec) {
    if (ec == http::error::header_limit) {
      if (request_line_too_long())
        return refuse(414, "the request line is above " + std::to_string(limits().max_request_line) + " bytes");
      return refuse(431, "the request's header is above " + std::to_string(limits().max_header) + " bytes");
    }
    if (ec == http::error::body_limit)
      return refuse(413, "the request's body is above " + std::to_string(limits().max_body) + " bytes");
    // a client that went away, or was too slow (the deadline closed the socket): nobody to answer
    const bool malformed = ec.category() == http::make_error_code(http::error::bad_method).category() &&
                           ec != http::error::end_of_stream && ec != http::error::partial_message;
    if (ec && !malformed) return close();
    if (ec) return refuse(400, "malformed HTTP request: " + ec.message());
    const auto& req = parser_->get();
    if (req.version() != 10 && req.version() != 11) return refuse(400, "HTTP/1.0 and HTTP/1.1 only");
    if (req.target().size() > limits().max_request_line)
      return refuse(414, "the request's target is above " + std::to_string(limits().max_request_line) + " bytes");

    HttpRequest request{std::string(req.method_string().data(), req.method_string().size()),
                        std::string(req.target().data(), req.target().size()), std::move(parser_->get().body())};
    HttpAnswer answer;
    try {
      answer = server_.handler(request);
    } catch (const std::exception& e) {
      answer = refusal(500, std::string("internal error: ") + e.what());
    } catch (...) {
      answer = refusal(500, "internal error");
    }
    write(std::move(answer), req.method() == http::verb::head, req.keep_alive(), req.version());
  }

  // Did the header go over its limit before its request line ended? (The parser takes the
  // request line as soon as it is complete, and the fields after it.)
  bool request_line_too_long() const { return parser_->get().target().empty(); }

  // answers, then closes: the rest of the request is not read
  void refuse(int status, const std::string& why) { write(refusal(status, why), false, false, 11); }

  void write(HttpAnswer answer, bool head_only, bool keep_alive, unsigned version) {
    answer_ = std::move(answer);
    keep_alive_ = keep_alive;
    response_.emplace();
    Answer& res = *response_;
    res.version(version);
    res.result(static_cast<unsigned>(answer_.status));
    for (const auto& [name, value] : server_.headers) res.set(name, value);
    res.set(http::field::content_type, answer_.content_type);
    res.keep_alive(keep_alive);
    res.body() = {answer_.body.data(), answer_.body.size()};
    res.prepare_payload();              // Content-Length of the body
    if (head_only) res.body() = {answer_.body.data(), 0};  // HEAD: the length, not the body
    serializer_.emplace(res);
    write_some();
  }

  void write_some() {
    stream_.expires_after(limits().answer_stall);
    http::async_write_some(stream_, *serializer_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->close();
      if (!self->serializer_->is_done()) return self->write_some();
      self->serializer_.reset();
      self->response_.reset();
      self->answer_ = {};
      if (!self->keep_alive_) return self->linger();
      self->read();
    });
  }

  // Closes our side for sending, then reads and drops what the client still sends (the body of
  // a refused request) for a moment: closing with unread bytes would reset the connection and
  // the client could lose the answer.
  void linger() {
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
    stream_.expires_after(limits().linger);
    drain();
  }
  void drain() {
    buffer_.consume(buffer_.size());
    stream_.async_read_some(buffer_.prepare(16 * 1024), [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->close();
      self->drain();
    });
  }

  void close() {
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_both, ignored);
    stream_.close();
  }

  beast::tcp_stream stream_;
  HttpServer::State& server_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  HttpAnswer answer_;  // what response_'s body points into
  std::optional<Answer> response_;
  std::optional<http::response_serializer<http::span_body<const char>>> serializer_;
  bool keep_alive_ = false;
};

}  // namespace

void HttpServer::State::accept() {
  acceptor.async_accept(net::make_strand(ioc), [this](beast::error_code ec, tcp::socket socket) {
    if (ec == net::error::operation_aborted) return;
    if (ec) {  // out of file descriptors, ...: the listening socket stays; try again shortly
      retry.expires_after(std::chrono::milliseconds(50));
      return retry.async_wait([this](beast::error_code e) {
        if (!e) accept();
      });
    }
    if (connections.load() < limits.max_connections) {
      ++connections;
      std::make_shared<Session>(std::move(socket), *this)->start();
    }  // else the socket closes here
    accept();
  });
}

HttpServer::HttpServer(const std::string& host, int port, HttpLimits limits,
                       std::vector<std::pair<std::string, std::string>> headers, Handler handler)
    : state_(std::make_unique<State>(limits, std::move(headers), std::move(handler))) {
  const std::string where = host + ":" + std::to_string(port);
  tcp::acceptor& a = state_->acceptor;
  beast::error_code ec;
  tcp::resolver resolver(state_->ioc);
  const auto found = resolver.resolve(host, std::to_string(port),
                                      tcp::resolver::passive | tcp::resolver::numeric_service, ec);
  if (ec) throw OutputError(where, "cannot listen there: " + ec.message());
  for (const auto& entry : found) {
    ec = {};
    a.open(entry.endpoint().protocol(), ec);
    if (!ec) a.set_option(net::socket_base::reuse_address(true), ec);
    if (!ec) a.bind(entry.endpoint(), ec);
    if (!ec) a.listen(net::socket_base::max_listen_connections, ec);
    if (!ec) return;
    beast::error_code ignored;
    a.close(ignored);
  }
  throw OutputError(where, "cannot listen there (in use, or not an address of this machine)" +
                               (ec ? ": " + ec.message() : std::string()));
}

HttpServer::~HttpServer() { stop(); }

int HttpServer::port() const { return state_->acceptor.local_endpoint().port(); }

void HttpServer::start() {
  state_->accept();
  unsigned n = state_->limits.threads;
  if (n == 0) n = std::clamp(std::thread::hardware_concurrency(), 8u, 16u);
  for (unsigned i = 0; i < n; ++i)
    state_->threads.emplace_back([s = state_.get()] {
      for (;;) {
        try {
          s->ioc.run();
          return;
        } catch (const std::exception& e) {  // a session's failure ends that session, not the server
          std::cerr << "arnoldweb: serve: " << e.what() << "\n";
        }
      }
    });
}

void HttpServer::stop() {
  state_->ioc.stop();
  for (auto& t : state_->threads) t.join();
  state_->threads.clear();
  beast::error_code ignored;
  state_->acceptor.close(ignored);
}

}  // namespace arnoldweb::explorer
