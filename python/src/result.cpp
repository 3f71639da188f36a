// What a run produced, part by part (0: the main run, then the panels), as
// numpy arrays. The map, zoom and state records are views of the library's
// own vectors (zero-copy, read-only); they keep the run alive. Writing goes
// through the library's output code (write_job): staging, --force rules and
// the same files as `arnoldweb run`.
#include "bindings.hpp"

#include <nanobind/ndarray.h>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <cmath>
#include <cstring>
#include <type_traits>

#include "aw_params.h"

namespace awpy {
namespace {

using arnoldweb::Result;
using Record = RunRecord;
using Self = nb::pointer_and_handle<RunRecord>;

const Result& part(const RunRecord& r, std::size_t k) {
  if (k >= r.result.results.size()) throw nb::index_error("no such part of the run");
  return r.result.results[k];
}
const arnoldweb::Plan& plan(const RunRecord& r, std::size_t k) {
  if (k >= r.job.parts.size()) throw nb::index_error("no such part of the job");
  return r.job.parts[k].plan;
}

// A read-only view of the library's vector, keeping `owner` (the run) alive; None when empty.
template <class T>
nb::object view(nb::handle owner, const std::vector<T>& v, std::initializer_list<std::size_t> shape) {
  if (v.empty()) return nb::none();
  return nb::cast(nb::ndarray<nb::numpy, const T>(v.data(), shape, owner));
}

nb::dict counts(const RunRecord& r, std::size_t k) {
  const Result& x = part(r, k);
  nb::dict d;
  d["trajectories"] = x.trajectories;
  d["completed"] = x.completed;
  d["binned"] = x.binned;
  d["flagged_nonfinite"] = x.flagged_nonfinite;
  d["flagged_energy"] = x.flagged_energy;
  d["flagged_initial"] = x.flagged_initial;
  d["left_region"] = x.left_region;
  return d;
}

nb::dict energy(const RunRecord& r, std::size_t k) {
  const Result& x = part(r, k);
  nb::dict d;
  d["tracked"] = x.energy.tracked;
  if (x.energy.tracked) {
    d["max"] = x.energy.max;
    d["mean"] = x.energy.mean;
    d["median_upper_bound"] = x.energy.quantile(0.5);
    d["p99_upper_bound"] = x.energy.quantile(0.99);
    d["log_hist"] = owned(x.energy.log_hist, {x.energy.log_hist.size()});
  }
  return d;
}

nb::dict device(const RunRecord& r, std::size_t k) {
  const arnoldweb::DeviceInfo& d = part(r, k).device;
  nb::dict out;
  out["id"] = d.id;
  out["backend"] = d.backend;
  out["name"] = d.name;
  out["vendor"] = d.vendor;
  out["version"] = d.version;
  return out;
}

nb::object frames(const RunRecord& r, std::size_t k) {
  const Result& x = part(r, k);
  if (x.frames.empty()) return nb::none();
  const std::size_t npix = x.frames.front().size();
  std::vector<std::uint64_t> all(x.frames.size() * npix);
  for (std::size_t f = 0; f < x.frames.size(); ++f)
    std::memcpy(all.data() + f * npix, x.frames[f].data(), npix * sizeof(std::uint64_t));
  return owned(std::move(all), {x.frames.size(), npix});
}

// The shape of the indicators' grid, as indicators.h5 has it (healpix: 12
// nside^2 in RING order; lonlat and plane: [n2][n1]), and the grid's kind.
// Which indicators a part holds: Result.outputs["indicators"] (the output table).
nb::dict indicator_layout(const RunRecord& r, std::size_t k) {
  const arnoldweb::Scene& s = plan(r, k).scene;
  const std::size_t n = part(r, k).reals("indicators").size() / AW_IND_REALS;
  nb::dict d;
  const auto n1 = static_cast<std::size_t>(s.grid_resolution[0]), n2 = static_cast<std::size_t>(s.grid_resolution[1]);
  if (s.initial == "grid" && s.grid_kind != "healpix" && n == n1 * n2)
    d["shape"] = nb::make_tuple(n2, n1);
  else
    d["shape"] = nb::make_tuple(n);
  d["grid"] = s.initial == "grid" ? s.grid_kind : std::string();
  return d;
}

// The records of an output (reals or integers, one row per trajectory) as a zero-copy view; None if absent.
nb::object records_view(Self s, std::size_t k, const std::string& name, bool integers) {
  const arnoldweb::Records* rec = part(*s.p, k).records_of(name);
  if (!rec) return nb::none();
  if (integers) return view(s.h, rec->ints, {rec->count(), rec->ints_per});
  return view(s.h, rec->reals, {rec->count(), rec->reals_per});
}

// Every per-trajectory output as its files hold it: {output: {dataset: array}} (copies).
nb::dict output_datasets(const RunRecord& r, std::size_t k) {
  nb::dict out;
  for (arnoldweb::OutputDataset& d : arnoldweb::output_datasets(plan(r, k), part(r, k))) {
    if (!out.contains(d.output.c_str())) out[d.output.c_str()] = nb::dict();
    nb::dict group = nb::borrow<nb::dict>(out[d.output.c_str()]);
    std::vector<std::size_t> shape(d.shape.begin(), d.shape.end());
    auto make = [&](auto&& values) {
      using T = typename std::decay_t<decltype(values)>::value_type;
      auto* data = new std::vector<T>(std::move(values));
      nb::capsule owner(data, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
      return nb::cast(nb::ndarray<nb::numpy, T>(data->data(), shape.size(), shape.data(), owner));
    };
    group[d.name.c_str()] = d.integers ? make(std::move(d.ints)) : make(std::move(d.reals));
  }
  return out;
}

// Writes the job's outputs into `dir` as `arnoldweb run --out dir` would.
std::vector<std::string> write(RunRecord& r, const std::string& dir, bool force, const std::string& scene_file) {
  if (r.result.results.empty()) throw arnoldweb::OutputError(dir, "nothing was computed: there is nothing to write");
  arnoldweb::Job job = r.job;
  job.parts.front().plan.scene.output_dir = dir;
  std::vector<std::string> files;
  {
    nb::gil_scoped_release unlocked;
    arnoldweb::OutputOptions o;
    o.force = force;
    o.scene_file = scene_file;
    o.expected_bytes = arnoldweb::estimate_output_bytes(job);
    const std::string normalised = arnoldweb::check_output_dir(dir, o);
    job.parts.front().plan.scene.output_dir = normalised;
    files = arnoldweb::write_job(job, r.result, o);
    r.written_dir = normalised;
  }
  r.files = files;
  return files;
}

// The bin edges of EnergyStats::log_hist (AW_EHIST_* layout, result.hpp): 0, then the lower
// edge of every quarter-octave bin from 2^-64 to 2^16, then inf.
nb::object energy_hist_edges() {
  std::vector<double> edges{0.0};
  for (int b = 1; b < AW_EHIST_BINS; ++b) {
    const int octave = (b - 1) / AW_EHIST_BINS_PER_OCTAVE, quarter = (b - 1) % AW_EHIST_BINS_PER_OCTAVE;
    edges.push_back(std::ldexp(1.0 + static_cast<double>(quarter) / AW_EHIST_BINS_PER_OCTAVE, AW_EHIST_MIN_EXP + octave));
  }
  edges.push_back(INFINITY);
  return owned(std::move(edges), {static_cast<std::size_t>(AW_EHIST_BINS + 1)});
}

}  // namespace

void bind_result(nb::module_& m) {
  m.def("_energy_hist_edges", &energy_hist_edges, "The bin edges of the energy error histogram (log_hist).");
  nb::class_<RunRecord>(m, "_Run", "A run of a job (its plan and results); arnoldweb.Result views one part.")
      .def_prop_ro("parts_run", [](const RunRecord& r) { return r.result.results.size(); })
      .def_prop_ro("parts_planned", [](const RunRecord& r) { return r.job.parts.size(); })
      .def_prop_ro("interrupted", [](const RunRecord& r) { return r.result.interrupted; })
      .def("take_stop_exception",
           [](RunRecord& r) {
             nb::object e = r.stop_exception;
             r.stop_exception = nb::none();  // the exception will hold the result: no cycle through C++
             return e;
           },
           "What stopped the run early (KeyboardInterrupt, ...), or None; only once.")
      .def_prop_ro("written_dir", [](const RunRecord& r) { return r.written_dir; })
      .def_prop_ro("files", [](const RunRecord& r) { return r.files; })
      .def("raise_write_error",
           [](const RunRecord& r) {
             if (r.write_error) std::rethrow_exception(r.write_error);
           },
           "Raises the error that writing the outputs met, if any.")
      .def("name", [](const RunRecord& r, std::size_t k) { return r.job.parts.at(k).name; })
      .def("title", [](const RunRecord& r, std::size_t k) { return r.job.parts.at(k).title; })
      .def("scene_file", [](const RunRecord& r) { return r.job.main().scene.file; })
      .def("map", [](Self s, std::size_t k) { const auto& v = part(*s.p, k).map; return view(s.h, v, {v.size()}); })
      .def("zoom", [](Self s, std::size_t k) {
             const auto& v = part(*s.p, k).zoom;
             const auto res = static_cast<std::size_t>(plan(*s.p, k).zoom_resolution);
             return view(s.h, v, {res, res});
           })
      .def("records", &records_view, nb::arg("part"), nb::arg("name"), nb::arg("integers"),
           "The reals (or integers) of a per-trajectory output, one row per trajectory (zero-copy), or None.")
      .def("output_datasets", &output_datasets,
           "Every per-trajectory output as its files hold it: {output: {dataset: array}}.")
      .def("indicator_layout", &indicator_layout,
           "The shape of the indicators' grid as in indicators.h5, and the grid's kind.")
      .def("frames", &frames)
      .def("nside", [](const RunRecord& r, std::size_t k) { return part(r, k).nside; })
      .def("counts", &counts)
      .def("energy", &energy)
      .def("device", &device)
      .def("interrupted_part", [](const RunRecord& r, std::size_t k) { return part(r, k).interrupted; })
      .def("wall_seconds", [](const RunRecord& r, std::size_t k) { return part(r, k).wall_seconds; })
      .def("rate", [](const RunRecord& r, std::size_t k) { return part(r, k).rate(); })
      .def("chunks", [](const RunRecord& r, std::size_t k) { return part(r, k).chunks; })
      .def("kernel", [](const RunRecord& r, std::size_t k) { return part(r, k).kernel; })
      .def("digests", [](const RunRecord& r, std::size_t k) {
             const Result& x = part(r, k);
             nb::dict d;
             d["map"] = arnoldweb::digest_map(x);
             for (const auto& rec : arnoldweb::output_names()) d[rec.c_str()] = arnoldweb::digest_records(x, rec);
             return d;
           })
      .def("summary_json", [](const RunRecord& r, std::size_t k) {
             return arnoldweb::summary_json(plan(r, k), part(r, k), {});
           }, "summary.json of a part as the library writes it (without the list of files).")
      .def("write", &write, nb::arg("dir"), nb::arg("force"), nb::arg("scene_file"),
           "Writes the outputs into dir with the library's output code (staging, force rules); returns the paths.");
}

}  // namespace awpy
