// arnoldweb models: the built-in Hamiltonians, their formulas and parameters.
#include <cstdio>

#include <nlohmann/json.hpp>

#include "arnoldweb/models.hpp"
#include "command.hpp"

namespace arnoldweb::cli {

void add_models_command(CLI::App& app, Action& action) {
  auto* c = app.add_subcommand("models", "List the built-in models (model.kind): formula and parameters");
  static bool json = false;
  c->add_flag("--json", json, "Print the list as JSON");
  c->callback([&action] {
    action = [] {
      if (json) {
        nlohmann::json j = nlohmann::json::array();
        for (const ModelInfo& m : model_list())
          j.push_back({{"name", m.name}, {"title", m.title}, {"formula", m.formula}, {"parameters", m.parameters},
                       {"keys", m.keys}});
        std::printf("%s\n", j.dump(2).c_str());
        return 0;
      }
      for (const ModelInfo& m : model_list()) {
        std::printf("%s\n  %s\n  %s\n  parameters: %s\n", m.name.c_str(), m.title.c_str(), m.formula.c_str(),
                    m.parameters.c_str());
      }
      std::printf("Every model also reads model.energy = E, the energy of every trajectory (docs/models.md).\n");
      return 0;
    };
  });
}

}  // namespace arnoldweb::cli
