// STUB: replaced by the output writers.
#include "arnoldweb/output.hpp"
#include "arnoldweb/errors.hpp"

namespace arnoldweb {
std::vector<std::string> write_outputs(const Plan&, const Result&, const std::string& dir, bool) {
  throw OutputError(dir, "writers not implemented yet");
}
void check_output_dir(const std::string&, bool) {}
std::string summary_json(const Plan&, const Result&) { return "{}"; }
}  // namespace arnoldweb
