// arnoldweb explorer: the Arnold web in a browser (docs/viewer.md). A layer above the
// outputs, beside the CLI and Python: it reads runs through the library's checked readers of
// saved runs (output.hpp) and starts runs through the same public API as the CLI; nothing below
// it knows it exists.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace arnoldweb::explorer {

// Writes a self-contained viewer of the runs in `dirs` (output directories; several: side by
// side, and two of one resolution also their difference and chi-square test) into the
// directory `to` ("" : <dirs[0]>.view): view.html, the page's scripts and one data script per
// run, so that it opens from file:// with no server and no network. Everything is read and
// checked before anything is written; `to` may be new or a directory this function wrote
// (anything else inside it is refused). OutputError / SavedRunError otherwise. Returns the path
// of view.html.
std::string write_view(const std::vector<std::string>& dirs, const std::string& to = "");

// The directory write_view writes into when `to` is not given.
std::string default_view_dir(const std::string& first_dir);

struct ServeOptions {
  std::vector<std::string> runs;  // output directories to serve
  std::string scene;              // or a scene file: run it first (its output.dir), then serve it
  std::vector<std::string> sets;  // --set overrides of the scene
  std::string host = "127.0.0.1";
  int port = 8000;                // 0: any free port
  std::string device;             // where zooms (and the scene) run; "" : the scene's run.device
  std::uint64_t max_trajectories = 1000000;  // the most a page may ask a zoom for
  std::string zoom_dir;           // where zooms are written ("" : <first run>.zooms)
  std::size_t max_body = 64 * 1024;          // request bodies above this are refused (413)
};

// Serves the explorer's page and the given runs on host:port until `stop` is set (the CLI sets
// it from SIGINT, SIGTERM, SIGHUP). A zoom that is running then is stopped after its chunk and
// checkpointed beside its output directory (`arnoldweb resume` continues it). `ready` is called
// with the URL once the server listens. Returns 0, or throws arnoldweb::Error (bad input, a port
// in use: OutputError).
int serve(const ServeOptions& options, const std::atomic<bool>& stop,
          const std::function<void(const std::string& url)>& ready = {});

}  // namespace arnoldweb::explorer
