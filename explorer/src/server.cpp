// arnoldweb serve: the explorer's page and the runs it was given, over HTTP (cpp-httplib).
// The server knows runs, not paths: a page names a run by its id, and every answer comes from
// the embedded page files or from a run read through the library's checked readers when it
// was registered. Requests are bounded in size; a bad one is answered 4xx with a message and
// changes nothing. Zooms run through RunQueue.
#include <httplib.h>
#include <sys/socket.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <thread>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/explorer.hpp"
#include "run_queue.hpp"
#include "run_view.hpp"
#include "web_files.hpp"
#include "zoom_scene.hpp"

namespace arnoldweb::explorer {
namespace {

namespace fs = std::filesystem;

void reply(httplib::Response& res, int status, const nlohmann::json& body) {
  res.status = status;
  res.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), "application/json");
}
void refuse(httplib::Response& res, int status, const std::string& why) { reply(res, status, {{"error", why}}); }

// The runs a server shows, by id: those it was given, the scene it ran, its zooms.
class Runs {
 public:
  void add(std::shared_ptr<const RunView> r) {
    std::lock_guard<std::mutex> lock(mutex_);
    order_.push_back(r->id);
    by_id_[r->id] = std::move(r);
  }
  std::shared_ptr<const RunView> find(const std::string& id) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = by_id_.find(id);
    return it == by_id_.end() ? nullptr : it->second;
  }
  // the runs a page opens with: those given and the scene's, not the zooms
  nlohmann::json main_metas() const {
    std::lock_guard<std::mutex> lock(mutex_);
    nlohmann::json a = nlohmann::json::array();
    for (const auto& id : order_)
      if (id[0] == 'r') a.push_back(by_id_.at(id)->meta);
    return a;
  }

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> order_;
  std::map<std::string, std::shared_ptr<const RunView>> by_id_;
};

std::string first_free(const fs::path& root, const std::string& stem, int* counter) {
  for (;;) {
    const std::string name = stem + std::to_string(++*counter);
    std::error_code ec;
    bool taken = fs::exists(fs::symlink_status(root / name, ec));
    for (const auto& e : fs::directory_iterator(root, ec))  // nor a checkpoint of an earlier server
      taken = taken || e.path().filename().string().rfind(name + ".", 0) == 0;
    if (!taken) return (root / name).string();
  }
}

}  // namespace

int serve(const ServeOptions& o, const std::atomic<bool>& stop, const std::function<void(const std::string&)>& ready) {
  Runs runs;
  // every run is read and checked before the server listens
  for (std::size_t i = 0; i < o.runs.size(); ++i)
    runs.add(std::make_shared<const RunView>(read_run_view(o.runs[i], "r" + std::to_string(i))));
  std::optional<PreparedRun> scene_run;
  std::string first_dir = o.runs.empty() ? "" : o.runs.front();
  if (!o.scene.empty()) {
    Scene s = load_scene(o.scene, o.sets);
    if (!o.device.empty()) s.device = o.device;
    scene_run = prepare_run(s, o.device);
    first_dir = scene_run->out_dir;
  }
  if (first_dir.empty()) throw OutputError("", "nothing to serve: give output directories or a scene");
  std::string zoom_root = o.zoom_dir;
  if (zoom_root.empty()) {
    zoom_root = fs::path(first_dir).lexically_normal().string();
    while (zoom_root.size() > 1 && zoom_root.back() == '/') zoom_root.pop_back();
    zoom_root += ".zooms";
  }
  const std::string device = o.device;
  std::mutex zoom_mutex;  // zoom numbering and the zoom directory
  int zoom_counter = 0;

  RunQueue queue(device, [&runs](const std::string& id, const std::string& dir) {
    // a finished run joins the runs: the scene's as r<n>, a zoom under its own id
    runs.add(std::make_shared<const RunView>(read_run_view(dir, id == "s0" ? "r" + std::to_string(0) : id)));
  });
  if (scene_run) queue.submit("s0", std::move(*scene_run), {{"kind", "scene"}, {"run", "r0"}});

  httplib::Server svr;
  svr.set_payload_max_length(o.max_body);
  svr.set_read_timeout(5, 0);
  svr.set_write_timeout(30, 0);
  svr.set_keep_alive_timeout(2);
  svr.set_default_headers({{"X-Content-Type-Options", "nosniff"}, {"Cache-Control", "no-store"},
                           {"Content-Security-Policy", "default-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:"}});
  svr.set_pre_routing_handler([](const httplib::Request& req, httplib::Response& res) {
    if (req.method != "GET" && req.method != "POST" && req.method != "HEAD") {
      refuse(res, 405, "method " + req.method + " is not served (GET and POST only)");
      return httplib::Server::HandlerResponse::Handled;
    }
    if (!req.params.empty()) {  // everything a page asks is in the path or the body
      refuse(res, 400, "this server takes no query parameters");
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  svr.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    const std::string why = res.status == 404   ? "no such page or run: " + req.path
                            : res.status == 413 ? "the request is too large"
                                                : "bad request";
    refuse(res, res.status, why);
  });
  svr.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
    try {
      std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      refuse(res, 500, std::string("internal error: ") + e.what());
    } catch (...) {
      refuse(res, 500, "internal error");
    }
  });

  // the page: the embedded files, by exact name
  svr.Get(R"(/([A-Za-z0-9_-]*(\.[a-z]+)?))", [](const httplib::Request& req, httplib::Response& res) {
    const std::string name = req.matches[1].str().empty() ? "index.html" : req.matches[1].str();
    const auto f = web_file(name);
    if (!f) return refuse(res, 404, "no such page file: " + name);
    res.set_content(std::string(*f), content_type(name).c_str());
  });
  svr.Get("/api/server", [&](const httplib::Request&, httplib::Response& res) {
    nlohmann::json j = {{"zoom", {{"max_trajectories", o.max_trajectories},
                                  {"device", device.empty() ? std::string("the scene's run.device") : device}}}};
    j["scene_run"] = queue.status("s0");
    reply(res, 200, j);
  });
  svr.Get("/api/runs", [&](const httplib::Request&, httplib::Response& res) {
    reply(res, 200, {{"runs", runs.main_metas()}});
  });
  static const std::string id_pattern = "([a-z][0-9]{1,6})";
  svr.Get("/api/runs/" + id_pattern, [&](const httplib::Request& req, httplib::Response& res) {
    const auto r = runs.find(req.matches[1]);
    if (!r) return refuse(res, 404, "no run " + req.matches[1].str());
    reply(res, 200, r->meta);
  });
  svr.Get("/api/runs/" + id_pattern + "/map", [&](const httplib::Request& req, httplib::Response& res) {
    const auto r = runs.find(req.matches[1]);
    if (!r) return refuse(res, 404, "no run " + req.matches[1].str());
    if (r->map_bytes.empty()) return refuse(res, 404, "run " + r->id + " has no velocity map");
    res.set_content(r->map_bytes, "application/octet-stream");
  });
  svr.Get("/api/runs/" + id_pattern + "/fields", [&](const httplib::Request& req, httplib::Response& res) {
    const auto r = runs.find(req.matches[1]);
    if (!r) return refuse(res, 404, "no run " + req.matches[1].str());
    reply(res, 200, r->fields);
  });
  svr.Get("/api/compare/" + id_pattern + "/" + id_pattern, [&](const httplib::Request& req, httplib::Response& res) {
    const auto a = runs.find(req.matches[1]), b = runs.find(req.matches[2]);
    if (!a || !b) return refuse(res, 404, "no run " + (a ? req.matches[2].str() : req.matches[1].str()));
    try {
      reply(res, 200, compare_json(*a, *b));
    } catch (const Error& e) {
      refuse(res, 400, e.what());
    }
  });
  svr.Get("/api/zooms", [&](const httplib::Request&, httplib::Response& res) {
    nlohmann::json all = queue.list(), zooms = nlohmann::json::array();
    for (auto& z : all)
      if (z["id"] != "s0") zooms.push_back(z);
    reply(res, 200, {{"zooms", zooms}});
  });
  svr.Get("/api/zooms/([a-z][0-9]{1,6})", [&](const httplib::Request& req, httplib::Response& res) {
    const nlohmann::json s = queue.status(req.matches[1]);
    if (s.is_null()) return refuse(res, 404, "no zoom " + req.matches[1].str());
    reply(res, 200, s);
  });
  svr.Post("/api/zooms/([a-z][0-9]{1,6})/cancel", [&](const httplib::Request& req, httplib::Response& res) {
    if (queue.status(req.matches[1]).is_null()) return refuse(res, 404, "no zoom " + req.matches[1].str());
    if (!queue.cancel(req.matches[1])) return refuse(res, 409, "zoom " + req.matches[1].str() + " has finished");
    reply(res, 202, queue.status(req.matches[1]));
  });
  svr.Post("/api/zooms", [&](const httplib::Request& req, httplib::Response& res) {
    nlohmann::json body;
    try {
      body = nlohmann::json::parse(req.body);
    } catch (const std::exception&) {
      return refuse(res, 400, "the body is not JSON: {source, region, trajectories}");
    }
    try {
      if (!body.is_object()) throw BadRequest("the body must be a JSON object {source, region, trajectories}");
      if (!body.contains("source") || !body["source"].is_string()) throw BadRequest("source must be a run id");
      const auto source = runs.find(body["source"].get<std::string>());
      if (!source) return refuse(res, 404, "no run " + body["source"].get<std::string>());
      if (source->counts.empty()) throw BadRequest("run " + source->id + " has no velocity map to zoom into");
      if (!body.contains("trajectories") || !body["trajectories"].is_number_integer() ||
          body["trajectories"].get<std::int64_t>() < 1)
        throw BadRequest("trajectories must be a positive integer");
      const auto n = body["trajectories"].get<std::uint64_t>();
      if (n > o.max_trajectories)
        throw BadRequest("trajectories " + std::to_string(n) + " is above this server's cap of " +
                         std::to_string(o.max_trajectories) + " (arnoldweb serve --max-trajectories)");
      int nside = 0;
      if (body.contains("nside")) {
        if (!body["nside"].is_number_integer() || body["nside"].get<std::int64_t>() < 1 ||
            body["nside"].get<std::int64_t>() > 8192)
          throw BadRequest("nside must be an integer from 1 to 8192 (a power of two)");
        nside = body["nside"].get<int>();
      }
      if (!body.contains("region")) throw BadRequest("region is missing");
      region_overrides(body["region"]);  // its form, before anything is made
      std::lock_guard<std::mutex> lock(zoom_mutex);
      std::error_code ec;
      fs::create_directories(zoom_root, ec);
      if (ec) return refuse(res, 500, "cannot make " + zoom_root + ": " + ec.message());
      const std::string dir = first_free(zoom_root, "zoom-", &zoom_counter);
      const std::string id = "z" + std::to_string(zoom_counter);
      PreparedRun run = prepare_run(zoom_scene(source->scene, body["region"], n, nside, dir), device);
      queue.submit(id, std::move(run), {{"kind", "zoom"}, {"source", source->id}, {"region", body["region"]},
                                        {"run", id}, {"dir", dir}});
      reply(res, 202, queue.status(id));
    } catch (const BadRequest& e) {
      refuse(res, 400, e.what());
    } catch (const Error& e) {  // the scene reader's or the output place's refusal
      refuse(res, e.exit_code() == 2 ? 400 : 409, e.what());
    }
  });

  // cpp-httplib listens with a backlog of 5, so a burst of connections beyond the accepting
  // thread's pace was dropped and retried by the clients' TCP after seconds: the socket is kept
  // here and listened on again with the system's largest backlog once bound
  socket_t listening = -1;
  svr.set_socket_options([&listening](socket_t fd) {
    int yes = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);  // cpp-httplib's default, which this replaces
    listening = fd;
  });
  const int port = o.port == 0 ? svr.bind_to_any_port(o.host) : svr.bind_to_port(o.host, o.port) ? o.port : -1;
  if (port < 0)
    throw OutputError(o.host + ":" + std::to_string(o.port), "cannot listen there (in use, or not an address of this machine)");
  if (listening >= 0) ::listen(listening, SOMAXCONN);
  std::thread listener([&svr] { svr.listen_after_bind(); });
  while (!svr.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (ready) ready("http://" + (o.host.find(':') != std::string::npos ? "[" + o.host + "]" : o.host) + ":" +
                   std::to_string(port) + "/");
  while (!stop.load()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  svr.stop();
  listener.join();
  const std::string note = queue.shutdown();
  if (!note.empty()) std::cerr << "arnoldweb: " << note << "\n";
  return note.empty() ? 0 : 130;
}

}  // namespace arnoldweb::explorer
