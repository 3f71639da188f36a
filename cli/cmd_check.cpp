// arnoldweb check SCENE: validate a scene as `run` would (the scene, its
// panels, the output directory) and print its plan; computes nothing.
#include <iostream>

#include "arnoldweb/device.hpp"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/plan.hpp"
#include "command.hpp"
#include "plan_report.hpp"

namespace arnoldweb::cli {

void add_check_command(CLI::App& app, Action& action) {
  struct Flags {
    SceneArgs scene;
    bool force = false;
  };
  auto f = std::make_shared<Flags>();
  auto* c = app.add_subcommand("check", "Validate a scene as `run` would and print the plan: effects compiled in, "
                                        "schedule, work, outputs");
  add_scene_options(c, f->scene);
  c->add_flag("--force,-f", f->force, "Check as `run --force` would (replacing an earlier output directory)");
  c->callback([&action, f] {
    action = [f] {
      std::string device_warning;
      const PreparedJob p = prepare_job(f->scene, f->force, &device_warning);
      const Plan& plan = p.job.main();
      std::string dev = plan.scene.device;
      if (dev == "auto" || dev == "all") {
        std::string ids;
        try {
          for (const std::string& id : device_ids(dev)) ids += (ids.empty() ? "" : ",") + id;
        } catch (const Error&) {
          ids = "?";  // the warning below says why
        }
        dev = ids + " (" + dev + ")";
      }
      print_plan(std::cout, plan, dev);
      for (std::size_t k = 1; k < p.job.parts.size(); ++k)
        std::cout << "panel        " << p.job.parts[k].name << ": " << short_number(p.job.parts[k].plan.trajectory_steps)
                  << " trajectory-steps (" << p.job.parts[k].title << ")\n";
      const MemoryEstimate m = estimate_memory(plan);
      std::cout << "memory       about " << short_number(m.device_bytes / 1048576.0) << " MiB on the device, "
                << short_number(m.host_bytes / 1048576.0) << " MiB in this process (largest launch "
                << m.max_chunk << " trajectories)\n";
      if (!device_warning.empty()) std::cout << "warning      " << device_warning << "\n";
      std::cout << "outputs      " << printable(p.out_dir) << " (about " << short_number(p.output.expected_bytes / 1e6)
                << " MB at most)\n";
      return 0;
    };
  });
}

}  // namespace arnoldweb::cli
