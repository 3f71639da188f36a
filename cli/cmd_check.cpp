// arnoldweb check SCENE: validate a scene and print its plan; runs nothing.
#include <iostream>

#include "arnoldweb/device.hpp"
#include "arnoldweb/plan.hpp"
#include "command.hpp"
#include "plan_report.hpp"

namespace arnoldweb::cli {

void add_check_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<SceneArgs>();
  auto* c = app.add_subcommand("check", "Validate a scene and print the plan: effects compiled in, schedule, work");
  add_scene_options(c, *args);
  c->callback([&action, args] {
    action = [args] {
      const Plan plan = make_plan(load_scene_args(*args));
      const std::string dev = plan.scene.device == "auto" ? default_device_id() + " (auto)" : plan.scene.device;
      print_plan(std::cout, plan, dev);
      return 0;
    };
  });
}

}  // namespace arnoldweb::cli
