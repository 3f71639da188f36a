// arnoldweb serve [OUT ... | SCENE]: the explorer's page over HTTP for saved runs, or for a
// scene it runs first; zooms on demand run on --device (explorer/; docs/viewer.md). Ctrl-C
// (SIGINT, SIGTERM, SIGHUP) stops the server; a zoom running then is checkpointed.
#include <iostream>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/explorer.hpp"
#include "command.hpp"
#include "stop_signals.hpp"

namespace arnoldweb::cli {
namespace {

struct ServeArgs {
  std::vector<std::string> what;
  explorer::ServeOptions options;
};

bool is_scene(const std::string& path) { return path.size() > 5 && path.compare(path.size() - 5, 5, ".toml") == 0; }

int serve(ServeArgs a) {
  explorer::ServeOptions& o = a.options;
  if (a.what.size() == 1 && is_scene(a.what.front())) {
    o.scene = a.what.front();
  } else {
    for (const auto& w : a.what)
      if (is_scene(w)) throw SceneError(w, 0, 0, "", "serve takes one scene, or output directories, not both");
    if (!o.sets.empty()) throw SceneError("--set", 0, 0, "", "--set applies to a scene; serve was given output directories");
    o.runs = a.what;
  }
  if (o.host != "127.0.0.1" && o.host != "localhost" && o.host != "::1")
    std::cerr << "arnoldweb: warning: serving on " << o.host
              << ", not only this machine: anyone who reaches it can see these runs and start zooms on "
              << (o.device.empty() ? "this machine's device" : o.device) << "\n";
  StopSignals signals;
  const int rc = explorer::serve(o, signals.flag(), [](const std::string& url) {
    std::cout << "serving      " << url << "  (Ctrl-C stops)" << std::endl;
  });
  return rc;  // 130 when a running zoom was checkpointed
}

}  // namespace

void add_serve_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<ServeArgs>();
  explorer::ServeOptions& o = args->options;
  auto* c = app.add_subcommand("serve", "Serve the explorer for saved runs or a scene it runs first; zooms on demand "
                                        "(docs/viewer.md)");
  c->add_option("runs_or_scene", args->what, "Output directories of runs, or one scene file (.toml) to run first")->required();
  c->add_option("--port,-p", o.port, "Port (0: any free one)")->capture_default_str()->check(CLI::Range(0, 65535));
  c->add_option("--host", o.host, "Address to listen on (anything but the loopback address is warned about)")
      ->capture_default_str();
  c->add_option("--device,-d", o.device, "Where the scene and the zooms run (default: the scene's run.device)");
  c->add_option("--set", o.sets, "Override a key of the scene, as with run: key=value");
  c->add_option("--max-trajectories", o.max_trajectories, "The most trajectories a page may ask a zoom for")
      ->capture_default_str()->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 40));
  c->add_option("--zooms", o.zoom_dir, "Where zooms are written (default: <first run>.zooms)");
  c->callback([&action, args] { action = [args] { return serve(*args); }; });
}

}  // namespace arnoldweb::cli
