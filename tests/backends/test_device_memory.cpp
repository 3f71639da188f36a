// The memory check every backend makes before it allocates anything
// (detail::check_device_memory, backends/backends.hpp): a map or state records
// that cannot fit the device are refused before any work, with the key to
// change and the numbers. Checked against made-up devices, so the outcome does
// not depend on the machine (issue 12, item 8: nside = 8192 used to end in
// bad_alloc).
#include <doctest/doctest.h>

#include <string>

#include "backends/backends.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

constexpr std::uint64_t kMiB = 1024 * 1024;

// The map at line 3 of the scene, so that the refusal can point at it.
Plan plan_with(int nside, const std::vector<std::string>& sets = {}) {
  std::vector<std::string> all = {awtest::set("observe.velocity_map.nside", nside)};
  all.insert(all.end(), sets.begin(), sets.end());
  return make_plan(awtest::scene_from("[ensemble]\ntrajectories = 1\n[observe]\nvelocity_map = { nside = 64 }\n",
                                      all, "<memory>"));
}

DeviceInfo device_with(std::uint64_t memory) {
  DeviceInfo d;
  d.id = "opencl:7";
  d.backend = "opencl";
  d.name = "Small GPU";
  d.memory = memory;
  return d;
}

}  // namespace

TEST_SUITE("backends") {
  TEST_CASE("a velocity map larger than half the device's memory is refused, naming the key, the MiB and the device") {
    // nside 8192: 12 * 8192^2 pixels x (4-byte chunk counts + 8-byte totals) = 9216 MiB
    const Plan p = plan_with(8192);
    REQUIRE(p.hist_size == 12ull * 8192 * 8192);
    const DeviceInfo gpu = device_with(16 * 1024 * kMiB);  // 16 GiB: 9216 MiB is more than half
    try {
      detail::check_device_memory(p, gpu, 1, 4 * 1024 * kMiB);
      FAIL("nside 8192 accepted on a 16 GiB device");
    } catch (const SceneError& e) {
      CHECK(e.key() == "observe.velocity_map.nside");
      CHECK(e.exit_code() == 2);
      const std::string m = e.message();
      CAPTURE(m);
      CHECK(m.find("the histograms need 9216 MiB on the device") != std::string::npos);
      CHECK(m.find("opencl:7 (Small GPU) has 16384 MiB") != std::string::npos);
      CHECK(m.find("choose a smaller value") != std::string::npos);
    }
    // with twice the map's memory and a large enough allocation it fits
    CHECK_NOTHROW(detail::check_device_memory(p, device_with(18433 * kMiB), 1, 8 * 1024 * kMiB));
  }

  TEST_CASE("a map beyond the largest single allocation is refused even where the memory would hold it") {
    const Plan p = plan_with(1024);  // 12 Mi pixels: 96 MiB of 64-bit totals, 144 MiB in all
    const DeviceInfo gpu = device_with(1024 * kMiB);
    CHECK_NOTHROW(detail::check_device_memory(p, gpu, 1, 96 * kMiB));
    CHECK_THROWS_WITH_AS(detail::check_device_memory(p, gpu, 1, 95 * kMiB),
                         doctest::Contains("largest buffer 95 MiB"), SceneError);
    // the same map on a device of 256 MiB: more than half of it
    CHECK_THROWS_WITH_AS(detail::check_device_memory(p, device_with(256 * kMiB), 1, 1024 * kMiB),
                         doctest::Contains("need 144 MiB"), SceneError);
    CHECK_NOTHROW(detail::check_device_memory(p, device_with(289 * kMiB), 1, 1024 * kMiB));
  }

  TEST_CASE("state records beyond the device's memory are refused: set ensemble.chunk smaller") {
    // initial and final states in double: 48 + 48 + 32 bytes per trajectory of a launch (ensemble.chunk)
    const std::vector<std::string> states = {"observe.initial_states=true", "observe.final_states=true",
                                             "ensemble.trajectories=16777216"};
    auto with_chunk = [&](int chunk) {
      std::vector<std::string> sets = states;
      sets.push_back(awtest::set("ensemble.chunk", chunk));
      return plan_with(1, sets);
    };
    const DeviceInfo gpu = device_with(1024 * kMiB);
    CHECK_NOTHROW(detail::check_device_memory(with_chunk(1 << 22), gpu, 0, 1024 * kMiB));  // 512 MiB
    CHECK_THROWS_WITH_AS(detail::check_device_memory(with_chunk(1 << 23), gpu, 0, 1024 * kMiB),  // 1 GiB
                         doctest::Contains("set ensemble.chunk smaller"), SceneError);
    // without state records the chunk size does not matter
    CHECK_NOTHROW(detail::check_device_memory(plan_with(1, {"ensemble.trajectories=16777216", "ensemble.chunk=8388608"}),
                                              gpu, 0, 1024 * kMiB));
  }

}
