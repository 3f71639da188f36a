// An output directory written earlier, read back by the library's reader
// (read_saved_maps: summary.json and map.h5, the same code as `arnoldweb
// compare` and `arnoldweb render`), for arnoldweb.load(). The map's digest is
// computed here as summary.json's is, so the package can check the file; every
// other file (summary.json, states.h5, indicators.h5) comes through the same
// checked reader (read_saved_summary, read_saved_file; HDF5 files also
// through the HDF5 reader's policy: read_saved_hdf5_file).
#include "bindings.hpp"

#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <cstring>

namespace awpy {
namespace {

// None for what the run did not make
nb::object array_of(std::vector<std::uint64_t> values, std::initializer_list<std::size_t> shape) {
  if (values.empty()) return nb::none();
  return owned(std::move(values), shape);
}

nb::dict read_maps(const std::string& dir) {
  arnoldweb::SavedMaps m;
  std::string digest;
  {
    nb::gil_scoped_release unlocked;
    m = arnoldweb::read_saved_maps(dir);
    arnoldweb::Result r;
    r.map = m.map;
    digest = arnoldweb::digest_map(r);
  }
  nb::dict d;
  d["nside"] = m.nside;
  d["map_digest"] = digest;
  const std::size_t npix = m.map.size();
  d["map"] = array_of(std::move(m.map), {npix});
  std::vector<std::uint64_t> frames;
  for (const auto& f : m.frames) frames.insert(frames.end(), f.begin(), f.end());
  d["frames"] = array_of(std::move(frames), {m.frames.size(), npix});
  const auto res = static_cast<std::size_t>(m.zoom_resolution);
  d["zoom"] = array_of(std::move(m.zoom), {res, res});
  return d;
}

// The bytes of a file of an output directory as `read` gives them, read without the GIL.
nb::bytes saved_bytes(std::string (*read)(const std::string&, const std::string&), const std::string& dir,
                      const std::string& name) {
  std::string bytes;
  {
    nb::gil_scoped_release unlocked;
    bytes = read(dir, name);
  }
  return nb::bytes(bytes.data(), bytes.size());
}

}  // namespace

void bind_saved(nb::module_& m) {
  m.def(
      "_output_locations",
      [] {
        nb::list out;
        for (const arnoldweb::OutputLocation& o : arnoldweb::output_locations()) {
          nb::dict d;
          d["output"] = o.output;
          d["file"] = o.file;
          d["group"] = o.group;
          d["datasets"] = o.datasets;
          out.append(d);
        }
        return out;
      },
      "Where each per-trajectory output can be in a run's directory (the output table): "
      "[{output, file, group, datasets}].");
  m.def(
      "read_saved_summary", [](const std::string& dir) { return json_loads(arnoldweb::read_saved_summary(dir)); },
      nb::arg("dir"),
      "summary.json of an output directory, read and checked as render and compare read it "
      "(a plain file, a JSON object of the right form; OutputError otherwise).");
  m.def(
      "_read_saved_file",
      [](const std::string& dir, const std::string& name) { return saved_bytes(arnoldweb::read_saved_file, dir, name); },
      nb::arg("dir"), nb::arg("name"),
      "The bytes of a file of an output directory, checked against the size and digest summary.json "
      "records (OutputError naming it otherwise).");
  m.def(
      "_continuation_of",
      [](const std::string& dir, double duration, const std::vector<std::string>& sets,
         const std::vector<std::string>& labels) {
        arnoldweb::ContinueArgs args;
        args.duration = duration;
        args.sets = sets;
        args.set_labels = labels;
        const arnoldweb::Continuation c = arnoldweb::continuation_of(dir, args);
        nb::dict d;
        d["scene_toml"] = c.scene_toml;
        d["source"] = c.source;
        d["end_time"] = c.end_time;
        d["overrides"] = c.overrides;
        d["labels"] = c.labels;
        return d;
      },
      nb::arg("dir"), nb::arg("duration"), nb::arg("sets"), nb::arg("labels"),
      "What continuing the finished run in dir starts from: its scene as it ran and the overrides "
      "that start it from its checked states.h5, then `sets` (keys that leave the trajectories "
      "unchanged; SceneError otherwise) (arnoldweb::continuation_of).");
  m.def(
      "_read_saved_hdf5_file",
      [](const std::string& dir, const std::string& name) {
        return saved_bytes(arnoldweb::read_saved_hdf5_file, dir, name);
      },
      nb::arg("dir"), nb::arg("name"),
      "The bytes of an HDF5 file of an output directory, checked as _read_saved_file checks them "
      "and by the HDF5 reader's policy (nothing leads out of the file; OutputError otherwise).");
  m.def("_read_maps", &read_maps, nb::arg("dir"),
        "The maps of an output directory (summary.json, map.h5): nside, map, frames, zoom and the "
        "map's digest as summary.json computes it. Raises OutputError naming a missing or bad file.");
}

}  // namespace awpy
