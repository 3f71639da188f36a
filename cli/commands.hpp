// arnoldweb CLI: one function per subcommand; each returns the exit code.
#pragma once

#include <string>
#include <vector>

namespace arnoldweb::cli {

struct RunArgs {
  std::string scene;
  std::string device;  // empty: the scene's run.device
  std::string out;     // empty: the scene's output.dir
  std::vector<std::string> sets;
  bool force = false;
  bool quiet = false;
};

int cmd_devices(bool json);
int cmd_methods();
int cmd_check(const RunArgs& args);
int cmd_run(const RunArgs& args);

}  // namespace arnoldweb::cli
