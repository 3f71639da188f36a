// arnoldweb: diffusion.csv (analysis_files.hpp).
#include "output/analysis_files.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace arnoldweb::detail {

std::string diffusion_csv(const Result& result) {
  const auto it = result.analyses.find("diffusion");
  if (it == result.analyses.end()) return "";
  const nlohmann::json j = nlohmann::json::parse(it->second);
  if (!j.contains("moments")) return "";
  const nlohmann::json& m = j["moments"];
  auto cell = [](const nlohmann::json& v) {
    if (!v.is_number()) return std::string();
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", v.get<double>());
    return std::string(b);
  };
  // beside the moments, the fits' D and the linearity of their growth (the same on every row)
  static const char* const kFit[] = {"D", "D_error", "D_first_half", "D_second_half", "alpha", "alpha_error"};
  std::string header = "t,along_mean,along_variance,across_variance", fits;
  for (const char* direction : {"along", "across"})
    for (const char* key : kFit) {
      header += std::string(",") + direction + "_" + key;
      const std::string fit = std::string(direction) + "_fit";
      fits += "," + (j.contains(fit) ? cell(j[fit].value(key, nlohmann::json())) : std::string());
    }
  std::string csv = header + "\n";
  for (std::size_t k = 0; k < m["t"].size(); ++k)
    csv += cell(m["t"][k]) + "," + cell(m["along_mean"][k]) + "," + cell(m["along_variance"][k]) + "," +
           cell(m["across_variance"][k]) + fits + "\n";
  return csv;
}

}  // namespace arnoldweb::detail
