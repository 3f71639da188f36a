// arnoldweb: THE PICTURE TABLE of the per-trajectory outputs. One row per
// picture an output draws from its records: its name, as an output's row
// names it (RecordOutput::pictures, lib/src/output_table/output_table.cpp),
// the file it writes, what it needs, and the function that draws it. The
// plugin's interface names no output: it exports write_output_pictures, which
// draws the pictures the output table's datasets name over a grid of initial
// conditions (RecordDataset::picture) and then, for every output the run wrote,
// the rows its output row names.
// Adding a picture of an output: its draw function and its row, registered
// beside it (a namespace-scope `const PictureRegistration`), in a render_*.cpp
// here (every .cpp here is the plugin's), and its name in the output's row.
#pragma once

#include <string>
#include <vector>

#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb::detail {

struct PictureRow {
  std::string name;   // as an output's row names it
  std::string file;   // the file it writes into the run's directory
  bool grid = false;  // only over a grid of initial conditions (ensemble.initial = "grid")
  // Draws the output's records (at least one) into `path`; false: the run
  // holds nothing it draws (e.g. an analysis that was not made). Throws OutputError.
  bool (*draw)(const Plan& plan, const Result& result, const Records& records, const std::string& path) = nullptr;
};

// A row of the table, registered where its function draws (static
// initialisation of the plugin); the table holds every registered row, by name.
struct PictureRegistration {
  explicit PictureRegistration(PictureRow row);
};

const std::vector<PictureRow>& picture_rows();
// The row of a name, or nullptr.
const PictureRow* find_picture(const std::string& name);

// The pictures of the run's outputs into `dir`, their names appended to
// `names`: the datasets' grid pictures, then each output's rows in table order.
// Throws OutputError (also for a name the output table gives that no row has).
void write_output_pictures(const Plan& plan, const Result& result, const std::string& dir,
                           std::vector<std::string>& names);

// The grid pictures the output table's datasets name (fli.png, megno.png; render_indicators.cpp).
void write_dataset_pictures(const Plan& plan, const Result& r, const std::string& dir,
                            std::vector<std::string>& names);

}  // namespace arnoldweb::detail
