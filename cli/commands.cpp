#include "commands.hpp"

#include <csignal>
#include <cstdio>
#include <iostream>

#include "arnoldweb/arnoldweb.hpp"
#include "progress.hpp"

namespace arnoldweb::cli {
namespace {

std::atomic<bool> g_stop{false};
extern "C" void on_sigint(int) { g_stop.store(true); }

Scene scene_from(const RunArgs& a) {
  std::vector<std::string> sets = a.sets;
  if (!a.out.empty()) sets.push_back("output.dir=" + a.out);
  if (!a.device.empty()) sets.push_back("run.device=" + a.device);
  return load_scene(a.scene, sets);
}

std::string human(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

void print_plan(const Plan& p, const std::string& device) {
  const Scene& s = p.scene;
  std::cout << "scene        " << s.file << "\n"
            << "device       " << device << "\n"
            << "model        E = " << s.energy << "  (eps_eff = 2/E = " << human(2 / s.energy)
            << ", accessible torus " << human(100 * p.accessible_fraction) << "%)\n"
            << "ensemble     " << s.trajectories << " trajectories, " << s.initial << ", seed " << s.seed
            << "\n"
            << "integrator   " << p.method.name << " (order " << p.method.order << ", "
            << p.method.stages << " force evaluations/step), h = " << p.step << " T, "
            << to_string(s.precision) << ", " << to_string(s.math) << " math\n"
            << "schedule     " << p.windows << " window(s) of " << s.average << " T = "
            << p.segments_per_window << " x " << p.steps_per_segment << " steps; "
            << p.steps_per_trajectory << " steps per trajectory\n"
            << "step guard   h k |p|max = " << human(p.guard.value) << " (refuse >= pi, advise <= pi/2)\n"
            << "effects      ";
  const auto eff = p.effects();
  for (std::size_t i = 0; i < eff.size(); ++i) std::cout << (i ? ", " : "") << eff[i];
  std::cout << (eff.empty() ? "(none)" : "") << "\n"
            << "kernel       " << p.kernel.defines() << "\n"
            << "work         " << human(p.trajectory_steps) << " trajectory-steps, "
            << human(p.force_evaluations) << " force evaluations\n";
  if (s.velocity_map)
    std::cout << "velocity map HEALPix nside " << s.nside << " (" << p.npix << " pixels, RING)\n";
  for (const auto& w : p.warnings) std::cout << "warning      " << w << "\n";
}

}  // namespace

int cmd_devices(bool json) {
  const auto devs = list_devices();
  if (json) {
    std::cout << "[";
    for (std::size_t i = 0; i < devs.size(); ++i) {
      const auto& d = devs[i];
      std::cout << (i ? ",\n " : "") << "{\"id\": \"" << d.id << "\", \"name\": \"" << d.name
                << "\", \"vendor\": \"" << d.vendor << "\", \"fp64\": " << (d.fp64 ? "true" : "false")
                << ", \"compute_units\": " << d.compute_units << ", \"memory\": " << d.memory
                << ", \"cpu\": " << (d.is_cpu ? "true" : "false") << "}";
    }
    std::cout << "]\n";
    return 0;
  }
  std::printf("%-10s %-44s %-30s %-5s %5s %10s\n", "id", "name", "vendor", "fp64", "units", "memory");
  for (const auto& d : devs)
    std::printf("%-10s %-44.44s %-30.30s %-5s %5u %7.1f GiB\n", d.id.c_str(), d.name.c_str(),
                d.vendor.c_str(), d.fp64 ? "yes" : "no", d.compute_units,
                static_cast<double>(d.memory) / (1024.0 * 1024 * 1024));
  for (const auto& p : backend_problems()) std::printf("note: %s\n", p.c_str());
  std::printf("default: %s\n", default_device_id().c_str());
  return 0;
}

int cmd_methods() {
  std::printf("%-14s %5s %12s %10s  %s\n", "method", "order", "forces/step", "stability", "name");
  for (const auto& m : methods())
    std::printf("%-14s %5d %12d %10.3f  %s\n", m.name.c_str(), m.order, m.stages, m.stability,
                m.title.c_str());
  std::printf("stability: linear stability limit h*omega of the method on a harmonic oscillator\n");
  return 0;
}

int cmd_check(const RunArgs& a) {
  const Scene scene = scene_from(a);
  const Plan plan = make_plan(scene);
  std::string device = scene.device == "auto" ? default_device_id() + " (auto)" : scene.device;
  print_plan(plan, device);
  return 0;
}

int cmd_run(const RunArgs& a) {
  const Scene scene = scene_from(a);
  const Plan plan = make_plan(scene);
  check_output_dir(scene.output_dir, a.force);
  auto backend = open_backend(scene.device);
  if (!a.quiet) {
    print_plan(plan, backend->info().id + " (" + backend->info().name + ")");
    std::cout.flush();
  }
  ConsoleProgress progress(static_cast<double>(plan.steps_per_trajectory), a.quiet);
  RunOptions options;
  options.progress = &progress;
  options.stop = &g_stop;
  std::signal(SIGINT, on_sigint);
  const Result result = run(plan, *backend, options);
  std::signal(SIGINT, SIG_DFL);
  const auto files = write_outputs(plan, result, scene.output_dir, a.force);
  if (!a.quiet) {
    std::cout << "done         " << result.completed << " trajectories in " << human(result.wall_seconds)
              << " s (" << human(result.rate()) << " trajectory-steps/s)\n"
              << "binned       " << result.binned << ", flagged " << result.flagged() << "\n";
    if (result.energy.tracked)
      std::cout << "energy error max " << human(result.energy.max) << ", mean "
                << human(result.energy.mean) << "\n";
    std::cout << "map digest   " << digest_map(result) << "\n";
    for (const auto& f : files) std::cout << "wrote        " << f << "\n";
  }
  if (result.interrupted) {
    std::cerr << "arnoldweb: interrupted after " << result.completed << " of " << result.trajectories
              << " trajectories; the partial result was written\n";
    return 130;
  }
  return 0;
}

}  // namespace arnoldweb::cli
