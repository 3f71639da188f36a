// arnoldweb tests: what runs wrote, compared (the checkpoint, scale, device-list
// and expression tests share these).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace awtest {

// The summary.json of an output directory.
nlohmann::json summary_of(const std::string& dir);
// Checks (doctest CHECKs) that the run written to `b` has the digests, counts and energy
// statistics of the run written to `a`, and was not interrupted.
void check_same_digests(const std::string& a, const std::string& b);
// The id of the first OpenCL device (PoCL here), or "" when there is none.
std::string first_opencl();

}  // namespace awtest
