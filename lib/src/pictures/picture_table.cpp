// arnoldweb: the picture table (picture_table.hpp).
#include "pictures/picture_table.hpp"

#include "arnoldweb/errors.hpp"
#include "output_table/output_table.hpp"

namespace arnoldweb::detail {

// The rows' draw functions (PictureRow::draw), each where its picture is drawn.
bool draw_map_and_fli(const Plan& plan, const Result& r, const Records& rec, const std::string& path);  // render_indicators.cpp
bool draw_frequency_map(const Plan& plan, const Result& r, const Records& rec, const std::string& path);  // render_analyses.cpp
bool draw_diffusion_index(const Plan& plan, const Result& r, const Records& rec, const std::string& path);
bool draw_diffusion(const Plan& plan, const Result& r, const Records& rec, const std::string& path);
bool draw_orbits(const Plan& plan, const Result& r, const Records& rec, const std::string& path);

const std::vector<PictureRow>& picture_rows() {
  static const std::vector<PictureRow> rows = {
      // the velocity map beside the FLI of a healpix grid (observe.fli)
      {"map_and_fli", "map_and_fli.png", true, draw_map_and_fli},
      // every trajectory at its first window's (nu_x, nu_y), coloured by its diffusion index
      {"frequency_map", "frequency_map.png", false, draw_frequency_map},
      {"diffusion_index", "diffusion_index.png", true, draw_diffusion_index},
      // the variance of the actions along and across the resonance with the fit of D
      {"diffusion", "diffusion.png", false, draw_diffusion},
      // the picked orbits: momentum, direction and energy error
      {"orbits", "trajectories.png", false, draw_orbits},
  };
  return rows;
}

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
