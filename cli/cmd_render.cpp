// arnoldweb render DIR: draw the pictures of a run written earlier (e.g. on a
// GPU node built without cairo), its panels and figure.png. What is read is
// checked first (saved_run.hpp): a missing or damaged summary.json or map.h5
// is exit 2, as for compare; a picture that cannot be written is exit 3.
#include <iostream>

#include "arnoldweb/output.hpp"
#include "command.hpp"

namespace arnoldweb::cli {

void add_render_command(CLI::App& app, Action& action) {
  auto dir = std::make_shared<std::string>();
  auto* c = app.add_subcommand("render", "Draw the pictures of an output directory from its summary.json and map.h5");
  c->add_option("dir", *dir, "Output directory of an earlier run")->required();
  c->callback([&action, dir] {
    action = [dir] {
      for (const auto& f : render_saved(*dir)) {
        if (f.rfind("note: ", 0) == 0) std::cerr << "arnoldweb: " << f << "\n";
        else std::cout << "wrote " << f << "\n";
      }
      return 0;
    };
  });
}

}  // namespace arnoldweb::cli
