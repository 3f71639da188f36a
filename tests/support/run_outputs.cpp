#include "run_outputs.hpp"

#include <doctest/doctest.h>

#include <fstream>

#include "arnoldweb/device.hpp"

namespace awtest {

nlohmann::json summary_of(const std::string& dir) {
  std::ifstream in(dir + "/summary.json");
  return nlohmann::json::parse(in);
}

void check_same_digests(const std::string& a, const std::string& b) {
  const auto ja = summary_of(a), jb = summary_of(b);
  CHECK(ja["digests"] == jb["digests"]);
  CHECK(ja["completed"] == jb["completed"]);
  CHECK(ja["binned"] == jb["binned"]);
  CHECK(ja["energy_error"]["max"] == jb["energy_error"]["max"]);
  CHECK(ja["energy_error"]["mean"] == jb["energy_error"]["mean"]);
  CHECK(jb["interrupted"] == false);
}

std::string first_opencl() {
  for (const auto& d : arnoldweb::list_devices())
    if (d.backend == "opencl") return d.id;
  return "";
}

}  // namespace awtest
