// arnoldweb: the per-trajectory outputs of a result as datasets (output.hpp:
// output_datasets), from the output table: the columns each dataset takes,
// its shape (the grid's, for grid-shaped rows). The HDF5 writer and Python
// read the same values. Nothing here names an output.
#include <cmath>

#include "arnoldweb/output.hpp"
#include "output_table/output_table.hpp"
#include "plan/plan_params.hpp"

namespace arnoldweb {
namespace {

using detail::RecordDataset;
using detail::RecordOutput;

// A 2-d grid of initial conditions (lonlat, plane): its shape [n2][n1]; else none.
std::vector<std::uint64_t> grid_shape(const Scene& s, std::uint64_t n) {
  if (s.initial != "grid" || s.grid_kind == "healpix") return {};
  const auto n1 = static_cast<std::uint64_t>(s.grid_resolution[0]), n2 = static_cast<std::uint64_t>(s.grid_resolution[1]);
  if (n != n1 * n2) return {};
  return {n2, n1};
}

// Columns [first, first + count) of every record, as one array.
template <class T>
std::vector<T> columns(const std::vector<T>& v, std::size_t per, int first, int count, std::uint64_t n) {
  std::vector<T> out(n * static_cast<std::size_t>(count));
  for (std::uint64_t t = 0; t < n; ++t)
    for (int k = 0; k < count; ++k) out[t * count + k] = v[t * per + static_cast<std::size_t>(first + k)];
  return out;
}

OutputDataset dataset(const RecordOutput& row, const Records& rec, const RecordDataset& d,
                      const std::vector<std::uint64_t>& dims) {
  OutputDataset o;
  o.output = row.name;
  o.name = d.name;
  o.meaning = d.meaning;
  o.file = row.file;
  o.group = row.group;
  const int width = static_cast<int>(d.integers ? rec.ints_per : rec.reals_per);
  const int count = d.count < 0 ? width - d.first : d.count;
  o.shape = dims;
  if (d.group > 1) {
    o.shape.push_back(static_cast<std::uint64_t>(count / d.group));
    o.shape.push_back(static_cast<std::uint64_t>(d.group));
  } else if (count > 1) {
    o.shape.push_back(static_cast<std::uint64_t>(count));
  }
  const std::uint64_t n = rec.count();
  o.integers = d.integers && !d.unwrapped;
  if (o.integers) {
    o.ints = columns(rec.ints, rec.ints_per, d.first, count, n);
    return o;
  }
  o.reals = columns(rec.reals, rec.reals_per, d.first, count, n);
  if (d.unwrapped)  // 2 pi (winding + turns)
    for (std::uint64_t t = 0; t < n; ++t)
      for (int k = 0; k < count; ++k)
        o.reals[t * count + k] = 2 * M_PI * (static_cast<double>(rec.ints[t * rec.ints_per + k]) + o.reals[t * count + k]);
  if (d.log10)
    for (double& v : o.reals) v = std::log10(v);
  return o;
}

}  // namespace

std::vector<OutputDataset> output_datasets(const Plan& plan, const Result& r) {
  std::vector<OutputDataset> out;
  for (const RecordOutput& row : detail::record_outputs()) {
    const Records* rec = r.records_of(row.name);
    if (!rec) continue;
    std::vector<std::uint64_t> dims = row.picked        ? row.picked(detail::params(plan).ints)
                                      : row.grid_shaped ? grid_shape(plan.scene, rec->count())
                                                        : std::vector<std::uint64_t>{};
    if (dims.empty()) dims = {rec->count()};
    for (const RecordDataset& d : row.datasets)
      if (!d.feature || (plan.kernel.features & d.feature)) out.push_back(dataset(row, *rec, d, dims));
  }
  return out;
}

}  // namespace arnoldweb
