// Scenes: read and validated by the library's reader (the CLI's messages),
// planned into jobs; check() describes the plan without computing anything.
#include "bindings.hpp"

#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

namespace awpy {

arnoldweb::Job plan_scene(const arnoldweb::Scene& scene, std::shared_ptr<const arnoldweb::StateSet> states) {
  nb::gil_scoped_release unlocked;
  return arnoldweb::plan_job(scene, arnoldweb::read_plan_inputs(scene, std::move(states)), arnoldweb::cpu_pilot());
}

namespace {

nb::dict plan_dict(const arnoldweb::Plan& p) {
  nb::dict r;
  r["method"] = p.method.name;
  r["stages"] = p.method.stages;
  r["step"] = p.step;
  r["steps_per_segment"] = p.steps_per_segment;
  r["segments_per_window"] = p.segments_per_window;
  r["windows"] = p.windows;
  r["steps_per_trajectory"] = p.steps_per_trajectory;
  r["trajectories"] = p.scene.trajectories;
  r["trajectory_steps"] = p.trajectory_steps;
  r["force_evaluations"] = p.force_evaluations;
  r["nside"] = p.scene.velocity_map ? p.scene.nside : 0;
  r["npix"] = p.npix;
  r["frames"] = p.frames;
  r["zoom_resolution"] = p.zoom_resolution;
  r["effects"] = p.effects();
  r["kernel_defines"] = p.kernel.defines();
  r["warnings"] = p.warning_lines();
  nb::dict guard;
  guard["value"] = p.guard.value;
  guard["limit"] = p.guard.limit;
  guard["advised"] = p.guard.advised;
  guard["safe_step"] = p.guard.safe_step;
  r["step_guard"] = guard;
  const arnoldweb::MemoryEstimate m = arnoldweb::estimate_memory(p);
  nb::dict mem;
  mem["largest_launch"] = m.max_chunk;
  mem["device_bytes"] = m.device_bytes;
  mem["host_bytes"] = m.host_bytes;
  r["memory"] = mem;
  r["device"] = p.scene.device;
  r["output_dir"] = p.scene.output_dir;
  r["scene"] = json_loads(p.scene.to_json());
  return r;
}

// The plan of the scene and its panels, as `arnoldweb check` reports it.
nb::dict check(const arnoldweb::Scene& scene) {
  const arnoldweb::Job job = plan_scene(scene);
  nb::dict r = plan_dict(job.main());
  nb::list panels;
  for (std::size_t k = 1; k < job.parts.size(); ++k) {
    nb::dict part = plan_dict(job.parts[k].plan);
    part["name"] = job.parts[k].name;
    part["title"] = job.parts[k].title;
    panels.append(part);
  }
  r["panels"] = panels;
  r["output_bytes"] = arnoldweb::estimate_output_bytes(job);
  return r;
}

}  // namespace

void bind_scene(nb::module_& m) {
  using arnoldweb::Scene;
  nb::class_<Scene>(m, "_Scene", "A validated scene (arnoldweb::Scene); arnoldweb.Scene wraps it.")
      .def_static("load", &arnoldweb::load_scene, nb::arg("path"), nb::arg("overrides") = std::vector<std::string>{},
                  nb::arg("labels") = std::vector<std::string>{},
                  "Reads and validates a scene file with key=value overrides; raises SceneError.")
      .def_static("parse", &arnoldweb::parse_scene, nb::arg("text"), nb::arg("file"),
                  nb::arg("overrides") = std::vector<std::string>{}, nb::arg("labels") = std::vector<std::string>{},
                  "Reads and validates scene text (`file` names it in messages); raises SceneError.")
      .def("to_toml", &Scene::to_toml, "The scene as run, as TOML (every key, defaults included).")
      .def("to_json", &Scene::to_json, "The scene as JSON: the echo in summary.json.")
      .def("origin", &Scene::origin, nb::arg("key"), "Where a key's value came from, for messages.")
      .def_ro("file", &Scene::file, "The path it was read from (\"<string>\" and the like when none).")
      .def_ro("text", &Scene::text, "The TOML text it was read from.")
      .def_ro("overrides", &Scene::overrides, "key=value overrides applied on top, in order.")
      .def_ro("override_labels", &Scene::override_labels, "How each override was given, for messages.")
      .def_ro("device", &Scene::device, "run.device")
      .def_ro("output_dir", &Scene::output_dir, "output.dir")
      .def("check", &check,
           "Validates the scene as a whole and plans it and its panels (resolving an \"auto\" step with "
           "a pilot on the cpu backend); returns the plan as a dict. Computes nothing else.");
}

}  // namespace awpy
