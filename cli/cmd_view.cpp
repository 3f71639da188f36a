// arnoldweb view OUT [OUT ...]: the explorer's page for saved runs, written to open from file://
// (explorer/; docs/viewer.md).
#include <filesystem>
#include <iostream>

#include "arnoldweb/explorer.hpp"
#include "command.hpp"

namespace arnoldweb::cli {
namespace {

struct ViewArgs {
  std::vector<std::string> dirs;
  std::string to;
};

int view(const ViewArgs& a) {
  const std::string page = explorer::write_view(a.dirs, a.to);
  std::cout << "wrote        " << page << "\n"
            << "open         file://" << std::filesystem::absolute(page).lexically_normal().string() << "\n";
  return 0;
}

}  // namespace

void add_view_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<ViewArgs>();
  auto* c = app.add_subcommand("view", "Write an explorer page of saved runs that opens from file:// (docs/viewer.md)");
  c->add_option("runs", args->dirs, "Output directories of runs; two of one resolution are also compared")
      ->required();
  c->add_option("--to", args->to, "Where to write view.html and its data (default: <first OUT>.view)");
  c->callback([&action, args] { action = [args] { return view(*args); }; });
}

}  // namespace arnoldweb::cli
