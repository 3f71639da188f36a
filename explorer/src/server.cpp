// arnoldweb serve: the explorer's page and the runs it was given, over HTTP (the transport is
// http_server.hpp, on Boost.Beast; the routing router.hpp). The server knows runs, not paths: a
// page names a run by its id, and every answer comes from the embedded page files or from a run
// read through the library's checked readers when it was registered. Requests are bounded in
// size; a bad one is answered 4xx with a message and changes nothing. Zooms run through RunQueue.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <thread>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/explorer.hpp"
#include "http_server.hpp"
#include "router.hpp"
#include "run_queue.hpp"
#include "run_view.hpp"
#include "web_files.hpp"
#include "zoom_scene.hpp"

namespace arnoldweb::explorer {
namespace {

namespace fs = std::filesystem;

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

  auto reply = [](const nlohmann::json& j) { return json_answer(200, j); };
  Router api;
  // the page: the embedded files, by exact name
  api.get("/:name", [](const Router::Args& a, const HttpRequest&) {
    const std::string name = a[0].empty() ? "index.html" : a[0];
    const auto f = web_file(name);
    if (!f) return refusal(404, "no such page file: " + shown(name));
    return HttpAnswer{200, content_type(name), *f, nullptr};
  });
  api.get("/api/server", [&](const Router::Args&, const HttpRequest&) {
    nlohmann::json j = {{"zoom", {{"max_trajectories", o.max_trajectories},
                                  {"device", device.empty() ? std::string("the scene's run.device") : device}}}};
    j["scene_run"] = queue.status("s0");
    return reply(j);
  });
  api.get("/api/runs", [&](const Router::Args&, const HttpRequest&) { return reply({{"runs", runs.main_metas()}}); });
  api.get("/api/runs/:id", [&](const Router::Args& a, const HttpRequest&) {
    const auto r = runs.find(a[0]);
    return r ? reply(r->meta) : refusal(404, "no run " + a[0]);
  });
  api.get("/api/runs/:id/map", [&](const Router::Args& a, const HttpRequest&) {
    const auto r = runs.find(a[0]);
    if (!r) return refusal(404, "no run " + a[0]);
    if (r->map_bytes.empty()) return refusal(404, "run " + r->id + " has no velocity map");
    return HttpAnswer{200, "application/octet-stream", r->map_bytes, r};  // the run's bytes, not a copy
  });
  api.get("/api/runs/:id/fields", [&](const Router::Args& a, const HttpRequest&) {
    const auto r = runs.find(a[0]);
    return r ? reply(r->fields) : refusal(404, "no run " + a[0]);
  });
  api.get("/api/compare/:id/:id", [&](const Router::Args& a, const HttpRequest&) {
    const auto x = runs.find(a[0]), y = runs.find(a[1]);
    if (!x || !y) return refusal(404, "no run " + (x ? a[1] : a[0]));
    try {
      return reply(compare_json(*x, *y));
    } catch (const Error& e) {
      return refusal(400, e.what());
    }
  });
  api.get("/api/zooms", [&](const Router::Args&, const HttpRequest&) {
    nlohmann::json all = queue.list(), zooms = nlohmann::json::array();
    for (auto& z : all)
      if (z["id"] != "s0") zooms.push_back(z);
    return reply({{"zooms", zooms}});
  });
  api.get("/api/zooms/:id", [&](const Router::Args& a, const HttpRequest&) {
    const nlohmann::json s = queue.status(a[0]);
    return s.is_null() ? refusal(404, "no zoom " + a[0]) : reply(s);
  });
  api.post("/api/zooms/:id/cancel", [&](const Router::Args& a, const HttpRequest&) {
    if (queue.status(a[0]).is_null()) return refusal(404, "no zoom " + a[0]);
    if (!queue.cancel(a[0])) return refusal(409, "zoom " + a[0] + " has finished");
    return json_answer(202, queue.status(a[0]));
  });
  api.post("/api/zooms", [&](const Router::Args&, const HttpRequest& req) {
    nlohmann::json body;
    try {
      body = nlohmann::json::parse(req.body);
    } catch (const std::exception&) {
      return refusal(400, "the body is not JSON: {source, region, trajectories}");
    }
    try {
      if (!body.is_object()) throw BadRequest("the body must be a JSON object {source, region, trajectories}");
      if (!body.contains("source") || !body["source"].is_string()) throw BadRequest("source must be a run id");
      const auto source = runs.find(body["source"].get<std::string>());
      if (!source) return refusal(404, "no run " + shown(body["source"].get<std::string>()));
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
      if (ec) return refusal(500, "cannot make " + zoom_root + ": " + ec.message());
      const std::string dir = first_free(zoom_root, "zoom-", &zoom_counter);
      const std::string id = "z" + std::to_string(zoom_counter);
      PreparedRun run = prepare_run(zoom_scene(source->scene, body["region"], n, nside, dir), device);
      queue.submit(id, std::move(run), {{"kind", "zoom"}, {"source", source->id}, {"region", body["region"]},
                                        {"run", id}, {"dir", dir}});
      return json_answer(202, queue.status(id));
    } catch (const BadRequest& e) {
      return refusal(400, e.what());
    } catch (const Error& e) {  // the scene reader's or the output place's refusal
      return refusal(e.exit_code() == 2 ? 400 : 409, e.what());
    }
  });

  HttpLimits limits;
  limits.max_body = o.max_body;
  HttpServer server(o.host, o.port, limits,
                    {{"X-Content-Type-Options", "nosniff"},
                     {"Cache-Control", "no-store"},
                     {"Content-Security-Policy", "default-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:"}},
                    std::cref(api));
  server.start();
  if (ready) ready("http://" + (o.host.find(':') != std::string::npos ? "[" + o.host + "]" : o.host) + ":" +
                   std::to_string(server.port()) + "/");
  while (!stop.load()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  server.stop();
  const std::string note = queue.shutdown();
  if (!note.empty()) std::cerr << "arnoldweb: " << note << "\n";
  return note.empty() ? 0 : 130;
}

}  // namespace arnoldweb::explorer
