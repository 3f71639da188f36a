// arnoldweb: the files of the per-trajectory outputs (states.h5,
// indicators.h5, ...), written from the output table: each file holds the
// rows that name it, each row its datasets under its group, with its digest.
// Nothing here names an output.
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "arnoldweb/output.hpp"
#include "output/atomic_file.hpp"
#include "output/h5_writer.hpp"
#include "output_table/output_table.hpp"
#include "plan/analysis_plan.hpp"
#include "plan/plan_params.hpp"

namespace arnoldweb {
namespace {

using detail::H5Writer;
using detail::RecordOutput;

// Cell centres of `count` cells over [lo, hi].
std::vector<double> centres(double lo, double hi, double count) {
  std::vector<double> c(static_cast<std::size_t>(count));
  for (std::size_t j = 0; j < c.size(); ++j) c[j] = lo + (static_cast<double>(j) + 0.5) * (hi - lo) / count;
  return c;
}

// The grid of initial conditions the trajectories follow (ensemble.initial = "grid").
void write_grid(H5Writer& h, const Scene& s) {
  hid_t g = h.group("grid");
  h.attr(g, "kind", s.grid_kind);
  h.attr(g, "position", s.grid_position);
  if (s.grid_kind == "healpix") {
    h.attr(g, "nside", static_cast<std::int64_t>(s.grid_nside));
    h.attr(g, "ordering", std::string("RING: trajectory i has its momentum along the centre of pixel i"));
    return;
  }
  const bool lonlat = s.grid_kind == "lonlat";
  const auto a = lonlat ? centres(s.box_lon[0], s.box_lon[1], s.grid_resolution[0])
                        : centres(s.grid_range1[0], s.grid_range1[1], s.grid_resolution[0]);
  const auto b = lonlat ? centres(s.box_lat[0], s.box_lat[1], s.grid_resolution[1])
                        : centres(s.grid_range2[0], s.grid_range2[1], s.grid_resolution[1]);
  hid_t da = h.dataset(g, lonlat ? "lon" : "axis1", H5T_NATIVE_DOUBLE, {a.size()}, a.data());
  hid_t db = h.dataset(g, lonlat ? "lat" : "axis2", H5T_NATIVE_DOUBLE, {b.size()}, b.data());
  h.attr(da, "meaning", std::string(lonlat ? "longitude of the momentum direction, degrees (column i)"
                                           : "momentum p[axes[0]] (column i)"));
  h.attr(db, "meaning", std::string(lonlat ? "latitude of the momentum direction, degrees (row j)"
                                           : "momentum p[axes[1]] (row j)"));
  if (!lonlat) {
    h.attr(g, "axes", std::vector<double>{s.grid_axes[0], s.grid_axes[1]});
    h.attr(g, "fixed", s.grid_fixed);
  }
  h.attr(g, "ordering", std::string("trajectory j n1 + i is row j, column i (cell centres)"));
}

void write_dataset(H5Writer& h, hid_t where, const OutputDataset& d) {
  const std::vector<hsize_t> dims(d.shape.begin(), d.shape.end());
  const hid_t set = d.integers ? h.dataset(where, d.name.c_str(), H5T_NATIVE_INT64, dims, d.ints.data())
                               : h.dataset(where, d.name.c_str(), H5T_NATIVE_DOUBLE, dims, d.reals.data());
  if (!d.meaning.empty()) h.attr(set, "meaning", d.meaning);
}

// An attribute a row asks for (RecordOutput::attributes) from the plan, on its group.
void plan_attribute(H5Writer& h, hid_t where, const std::string& name, const Plan& plan) {
  if (name == "duration")
    h.attr(where, "duration", plan.scene.duration);
  else if (name == "time_start")  // when the states were taken, in T (a state file's time)
    h.attr(where, "time", plan.start_time());
  else if (name == "time_end")
    h.attr(where, "time", plan.start_time() + plan.scene.duration);
  else
    throw OutputError(name, "the output table names an attribute the writer does not know");
}

// What a row's table keys write into its group (KeyTable::data), when switched on.
void key_table_data(H5Writer& h, hid_t where, const RecordOutput& row, const Plan& plan) {
  for (const detail::KeyTable& t : row.tables) {
    if (!t.data || !t.on(plan.scene.output_values)) continue;
    for (const detail::KeyData& d :
         t.data(t, plan.scene.output_values, detail::key_plan(plan.scene, plan), detail::params(plan).ints)) {
      if (!d.dataset) {
        if (d.ints.empty())
          h.attr(where, d.name.c_str(), d.reals.at(0));
        else
          h.attr(where, d.name.c_str(), d.ints.at(0));
        continue;
      }
      const hid_t set = d.ints.empty()
                            ? h.dataset(where, d.name.c_str(), H5T_NATIVE_DOUBLE, {d.reals.size()}, d.reals.data())
                            : h.dataset(where, d.name.c_str(), H5T_NATIVE_INT64, {d.ints.size()}, d.ints.data());
      h.attr(set, "meaning", d.meaning);
    }
  }
}

}  // namespace

void write_records_hdf5(const std::string& path, const std::string& file, const Plan& plan, const Result& r) {
  const Scene& s = plan.scene;
  H5Writer h(path);
  {
    detail::run_attributes(h, h.root(), plan, r);
    const std::vector<OutputDataset> datasets = output_datasets(plan, r);
    bool grid = false;
    for (const RecordOutput& row : detail::record_outputs()) {
      if (row.file != file || !r.records_of(row.name)) continue;
      const hid_t where = row.group.empty() ? h.root() : h.group(row.group.c_str());
      for (const OutputDataset& d : datasets)
        if (d.output == row.name) write_dataset(h, where, d);
      h.attr(where, "digest", digest_records(r, row.name));
      for (const std::string& a : row.attributes) plan_attribute(h, where, a, plan);
      for (const detail::DirectionKey& k : row.directions) h.attr(where, k.name().c_str(), k.value(s.output_values));
      key_table_data(h, where, row, plan);
      grid = grid || (row.grid_shaped && s.initial == "grid");
    }
    if (grid) write_grid(h, s);
  }
  detail::write_file_atomically(path, h.finish());
}

std::vector<OutputLocation> output_locations() {
  std::vector<OutputLocation> out;
  for (const RecordOutput& row : detail::record_outputs()) {
    if (row.internal()) continue;
    OutputLocation o{row.name, row.file, row.group, {}, !row.picked};
    for (const auto& d : row.datasets) o.datasets.push_back(d.name);
    out.push_back(std::move(o));
  }
  return out;
}

std::vector<std::string> record_files(const Result& r) {
  std::vector<std::string> files;
  for (const RecordOutput& row : detail::record_outputs())
    if (r.records_of(row.name) && std::find(files.begin(), files.end(), row.file) == files.end())
      files.push_back(row.file);
  return files;
}

}  // namespace arnoldweb
