// arnoldweb: the picture table (picture_table.hpp).
#include "pictures/picture_table.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <utility>

#include "arnoldweb/errors.hpp"
#include "output_table/output_table.hpp"

namespace arnoldweb::detail {

namespace {
// The registered rows, by name: built on first use, so that the registrations
// of every translation unit find it whatever their order of initialisation.
std::vector<PictureRow>& registered_rows() {
  static std::vector<PictureRow> rows;
  return rows;
}
}  // namespace

PictureRegistration::PictureRegistration(PictureRow row) {
  std::vector<PictureRow>& rows = registered_rows();
  if (find_picture(row.name)) {  // a programming error: every test that opens the plugin stops here
    std::fprintf(stderr, "arnoldweb pictures plugin: two pictures are registered as \"%s\"\n", row.name.c_str());
    std::abort();
  }
  const auto at = std::upper_bound(rows.begin(), rows.end(), row.name,
                                   [](const std::string& name, const PictureRow& r) { return name < r.name; });
  rows.insert(at, std::move(row));
}

const std::vector<PictureRow>& picture_rows() { return registered_rows(); }

const PictureRow* find_picture(const std::string& name) {
  for (const PictureRow& p : picture_rows())
    if (p.name == name) return &p;
  return nullptr;
}

void write_output_pictures(const Plan& plan, const Result& r, const std::string& dir,
                           std::vector<std::string>& names) {
  write_dataset_pictures(plan, r, dir, names);
  for (const RecordOutput* row : records_reported(plan.kernel.features)) {
    const Records* rec = r.records_of(row->name);
    if (!rec || rec->count() == 0) continue;
    for (const std::string& name : row->pictures) {
      const PictureRow* p = find_picture(name);
      if (!p) throw OutputError(dir, "the output table names a picture the plugin does not draw: " + name);
      if (p->grid && plan.scene.initial != "grid") continue;
      if (p->draw(plan, r, *rec, dir + "/" + p->file)) names.push_back(p->file);
    }
  }
}

}  // namespace arnoldweb::detail
