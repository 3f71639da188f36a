// arnoldweb keys: every scene key with its type, allowed values, default and
// meaning (the table of docs/scenes.md).
#include <cstdio>

#include "arnoldweb/scene.hpp"
#include "command.hpp"

namespace arnoldweb::cli {

void add_keys_command(CLI::App& app, Action& action) {
  auto* c = app.add_subcommand("keys", "List every scene key: type, allowed values, default, meaning");
  auto markdown = std::make_shared<bool>(false);
  c->add_flag("--markdown", *markdown, "Print the Markdown table of docs/scenes.md");
  c->callback([&action, markdown] {
    action = [markdown] {
      if (*markdown) {
        std::fputs(scene_keys_markdown().c_str(), stdout);
        return 0;
      }
      for (const auto& k : scene_keys())
        std::printf("%-30s %-18s default %s\n    allowed: %s\n    %s\n", k.key.c_str(), k.type.c_str(),
                    k.default_value.c_str(), k.allowed.c_str(), k.meaning.c_str());
      return 0;
    };
  });
}

}  // namespace arnoldweb::cli
