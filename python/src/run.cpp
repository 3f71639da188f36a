// Running a scene: the library's job runner (run_job) with the GIL released
// while devices compute. After every chunk the progress hook takes the GIL
// briefly: it calls the user's callback and PyErr_CheckSignals(), so Ctrl-C
// (or an exception from the callback) stops the run after the current chunk;
// what stopped it is kept and raised by the package with the partial result
// attached. With an output directory, it is checked before anything is
// computed and written at the end (also after a stop), as `arnoldweb run` does.
#include "bindings.hpp"

#include <nanobind/stl/optional.h>

#include <atomic>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>

#include "arnoldweb/cluster.hpp"

namespace awpy {
namespace {

class PythonHook final : public arnoldweb::Progress, public arnoldweb::JobObserver {
 public:
  explicit PythonHook(nb::object callback) : callback_(std::move(callback)) {}

  arnoldweb::Progress* begin_part(const arnoldweb::Job&, std::size_t) override { return this; }
  void update(std::uint64_t done, std::uint64_t total, double seconds) override { report(done, total, seconds, true); }
  void finish(std::uint64_t done, std::uint64_t total, double seconds) override { report(done, total, seconds, false); }

  const std::atomic<bool>& stop() const { return stop_; }
  nb::object exception() const { return exception_; }

 private:
  void report(std::uint64_t done, std::uint64_t total, double seconds, bool check_signals) {
    nb::gil_scoped_acquire locked;
    if (stop_.load()) return;  // already stopping: the first exception is the one raised
    // finish() after an update() that already said done == total: the callback
    // hears of the end of a part once
    const bool repeat = !check_signals && reported_ && done == last_done_ && total == last_total_;
    reported_ = true;
    last_done_ = done;
    last_total_ = total;
    if (repeat) return;
    try {
      if (!callback_.is_none()) callback_(done, total, seconds);
      if (check_signals && PyErr_CheckSignals() != 0) throw nb::python_error();
    } catch (nb::python_error& e) {
      exception_ = nb::borrow(e.value());
      stop_.store(true);
    }
  }

  nb::object callback_;
  bool reported_ = false;
  std::uint64_t last_done_ = 0, last_total_ = 0;
  std::atomic<bool> stop_{false};
  nb::object exception_ = nb::none();
};

// The plans' warnings (a step that will cost accuracy, ...) through Python's
// warnings, as arnoldweb.PlanWarning, before anything is computed: a filter
// that turns them into errors stops the run here. A run that writes no
// directory draws no pictures either: the warnings about output.images are
// left out.
void warn_plans(const arnoldweb::Job& job, bool write) {
  nb::object warn = nb::module_::import_("warnings").attr("warn");
  nb::object category = nb::module_::import_("arnoldweb._errors").attr("PlanWarning");
  for (std::size_t k = 0; k < job.parts.size(); ++k)
    for (const arnoldweb::Plan::Warning& w : job.parts[k].plan.warnings) {
      if (!write && w.key == "output.images") continue;
      const std::string text = k == 0 ? w.text : "panel " + job.parts[k].name + ": " + w.text;
      warn(nb::str(text.data(), text.size()), category, 2);  // stacklevel 2: the caller of arnoldweb.run
    }
}

std::shared_ptr<RunRecord> run_scene(const arnoldweb::Scene& scene, nb::object progress, bool write, bool force,
                                     std::optional<Rows> x, std::optional<Rows> p, const std::string& units,
                                     std::optional<std::uint64_t> only) {
  auto record = std::make_shared<RunRecord>();
  record->stop_exception = nb::none();
  std::shared_ptr<arnoldweb::StateSet> initial;
  arnoldweb::Scene s = scene;
  if (x && p) {  // initial=(X, P): the trajectories start from them
    s.initial = "file";
    s.initial_file.clear();
    initial = states_of(s, *x, *p, units);
  }
  record->job = plan_scene(s, std::move(initial));
  const arnoldweb::Job& job = record->job;
  warn_plans(job, write);
  arnoldweb::OutputOptions output;
  PythonHook hook(std::move(progress));
  {
    nb::gil_scoped_release unlocked;
    // everything is checked before any work: memory, then the output place
    const std::uint64_t host = arnoldweb::available_memory();
    for (const std::string& id : arnoldweb::device_ids(job.main().scene.device)) {
      const arnoldweb::DeviceInfo device = arnoldweb::find_device(id);
      for (const arnoldweb::JobPart& part : job.parts) arnoldweb::check_memory(part.plan, device, host);
    }
    if (write) {
      output.force = force;
      output.scene_file = scene.file;
      output.expected_bytes = arnoldweb::estimate_output_bytes(job);
      record->written_dir = arnoldweb::check_output_dir(job.main().scene.output_dir, output);
    }
    // every device run.device names (a list, "all"): one thread each
    const auto backends = arnoldweb::open_backends(job.main().scene.device);
    std::vector<arnoldweb::Backend*> devices;
    for (const auto& b : backends) devices.push_back(b.get());
    arnoldweb::RunOptions options;
    options.stop = &hook.stop();
    if (only)  // one trajectory of the main scene, with its bits in a run of all (arnoldweb orbit)
      record->result.results.push_back(arnoldweb::run_range(job.main(), *devices.front(), *only, 1, options));
    else
      record->result = arnoldweb::run_job_on(job, devices, options, &hook);
    if (write) {
      // a failed write must not lose what was computed: the error is raised
      // by the package with the result attached
      try {
        record->files = arnoldweb::write_job(job, record->result, output);
      } catch (const arnoldweb::Error&) {
        record->write_error = std::current_exception();
        record->written_dir.clear();
      }
    }
  }
  record->stop_exception = hook.exception();
  return record;
}

}  // namespace

void bind_run(nb::module_& m) {
  m.def("_run", &run_scene, nb::arg("scene"), nb::arg("progress").none(), nb::arg("write"), nb::arg("force"),
        nb::arg("x").none() = nb::none(), nb::arg("p").none() = nb::none(), nb::arg("units") = "radians",
        nb::arg("only").none() = nb::none(),
        "Runs a scene and its panels (only: trajectory `only` of the main scene alone); progress(done, total, "
        "seconds) after every chunk. With write, the scene's output.dir is checked first and written at the end. "
        "Returns the run's record.");
}

}  // namespace awpy
