// The reduction of a run is exact and mergeable (issue 15, part 1): chunks
// folded in any order, split over several reductions (processes, resumed
// runs) and passed through byte images give the same digests, counts and
// energy statistics, bit for bit, as a plain run.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "arnoldweb/arnoldweb.hpp"
#include "arnoldweb/version.hpp"
#include "plan/plan_params.hpp"
#include "run/checkpoint_image.hpp"
#include "run/exact_sum.hpp"
#include "run/job_checkpoints.hpp"
#include "run/reduction.hpp"
#include "support.hpp"

using arnoldweb::detail::ExactSum;
using arnoldweb::detail::Reduction;

namespace {

const std::string kScene =
    "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 9000\n[integrator]\nstep = 0.02\n"
    "[run]\naverage = 1.0\nduration = 2.0\n[observe]\nvelocity_map = { nside = 8 }\n"
    "energy_error = { every = 0.5 }\nfinal_states = true\ninitial_states = true\n"
    "zoom = { center = [45.0, 0.0], width = 30.0, resolution = 16 }\n[output]\nimages = false\n";

void check_same(const arnoldweb::Result& a, const arnoldweb::Result& b) {
  CHECK(a.completed == b.completed);
  CHECK(a.binned == b.binned);
  CHECK(a.flagged() == b.flagged());
  CHECK(arnoldweb::digest_map(a) == arnoldweb::digest_map(b));
  CHECK(arnoldweb::digest_records(a, "initial_states") == arnoldweb::digest_records(b, "initial_states"));
  CHECK(arnoldweb::digest_records(a, "final_states") == arnoldweb::digest_records(b, "final_states"));
  CHECK(a.zoom == b.zoom);
  CHECK(a.energy.log_hist == b.energy.log_hist);
  CHECK(a.energy.max == b.energy.max);  // exact
  CHECK(a.energy.mean == b.energy.mean);
}

}  // namespace

TEST_SUITE("reduction") {
  TEST_CASE("an exact sum does not depend on the order or the split of its terms") {
    std::mt19937_64 rng(7);
    std::vector<double> v;
    for (int i = 0; i < 20000; ++i)
      v.push_back(std::ldexp(std::uniform_real_distribution<double>(0.5, 1.0)(rng), static_cast<int>(rng() % 200) - 150));
    v.push_back(4.9e-324);  // a subnormal
    ExactSum in_order;
    for (double x : v) in_order.add(x);
    std::shuffle(v.begin(), v.end(), rng);
    ExactSum a, b;
    for (std::size_t i = 0; i < v.size(); ++i) (i % 3 ? a : b).add(v[i]);
    b.merge(a);
    CHECK(b.value() == in_order.value());
    CHECK(ExactSum::read(b.image()).value() == in_order.value());
    // the exact sum is rounded once: 2^53 + 1 + 1 is 2^53 + 2 (in sequence, doubles give 2^53)
    ExactSum c;
    for (double x : {9007199254740992.0, 1.0, 1.0}) c.add(x);
    CHECK(c.value() == 9007199254740994.0);
    // ties to even, with the sticky bits below the halfway point
    ExactSum d;
    for (double x : {9007199254740992.0, 1.0, std::ldexp(1.0, -60)}) d.add(x);
    CHECK(d.value() == 9007199254740994.0);
    ExactSum e;
    e.add(9007199254740992.0);
    e.add(1.0);
    CHECK(e.value() == 9007199254740992.0);
  }

  TEST_CASE("chunks folded in a shuffled order, split over two reductions and two devices, give the plain run's bits") {
    const arnoldweb::Scene scene = awtest::scene_from(kScene);
    const arnoldweb::Plan plan = arnoldweb::make_plan(scene);
    const arnoldweb::Result plain = awtest::run_on("cpu", plan);
    REQUIRE(plain.completed == 9000);

    // the index range cut differently: granule-aligned chunks of 1024 and 2048
    std::vector<arnoldweb::detail::IndexRange> ranges;
    for (std::uint64_t first = 0, k = 0; first < 9000; ++k) {
      const std::uint64_t n = std::min<std::uint64_t>(k % 2 ? 2048 : 1024, 9000 - first);
      ranges.push_back({first, n});
      first += n;
    }
    std::mt19937_64 rng(3);
    std::shuffle(ranges.begin(), ranges.end(), rng);
    auto dev_a = arnoldweb::open_backend("cpu"), dev_b = arnoldweb::open_backend("cpu");
    const std::uint64_t max_chunk = arnoldweb::largest_chunk(plan);
    dev_a->prepare(plan, max_chunk);
    dev_b->prepare(plan, max_chunk);
    Reduction a(plan), b(plan);
    arnoldweb::ChunkOutput out;
    for (std::size_t i = 0; i < ranges.size(); ++i) {
      auto& dev = i % 2 ? *dev_b : *dev_a;
      dev.run_chunk(ranges[i].first, ranges[i].count, out);
      (i % 2 ? b : a).add(ranges[i].first, ranges[i].count, out);
    }
    a.add_histograms(dev_a->read_histograms());
    b.add_histograms(dev_b->read_histograms());
    CHECK_FALSE(a.complete());
    CHECK(a.pending().size() > 1);
    // b travels as a byte image (a message between processes, a checkpoint)
    Reduction b_read = Reduction::read(plan, b.image());
    a.merge(b_read);
    CHECK(a.complete());
    CHECK(a.pending().empty());
    check_same(plain, a.result());
    // the same chunk twice is refused, not counted twice
    CHECK_THROWS(a.merge(b_read));
  }

  TEST_CASE("a device's hold on a chunk's records lasts as long as the records, and no longer") {
    // CUDA locks the host memory its read-back fills (ChunkOutput::holds); the lock is let go when
    // the records are freed, not on the run's path, and never after their memory is gone
    const arnoldweb::Plan plan = arnoldweb::make_plan(awtest::scene_from(kScene));
    const auto& ints = arnoldweb::detail::params(plan).ints;
    int released = 0;
    const auto hold = [&released] { return std::shared_ptr<void>(&released, [&released](void*) { ++released; }); };
    {
      Reduction red(plan);
      arnoldweb::ChunkOutput out;
      out.counters.assign(AW_C_COUNT, 0);
      out.rec_r.assign(1024 * static_cast<std::size_t>(ints.rec_reals), 0.0);
      out.rec_i.assign(1024 * static_cast<std::size_t>(ints.rec_ints), 0);
      out.holds = {hold(), hold()};
      red.add(0, 1024, out);
      CHECK(out.holds.empty());  // taken with the records
      CHECK(released == 0);
      const arnoldweb::Result r = red.result();  // reading the records out copies them
      CHECK(r.completed == 1024);
      CHECK(released == 0);
      // a chunk whose output is dropped lets go of its hold with it
      arnoldweb::ChunkOutput dropped;
      dropped.holds = {hold()};
      dropped = arnoldweb::ChunkOutput{};
      CHECK(released == 1);
    }
    CHECK(released == 3);  // the reduction's records freed: their holds let go
  }

  TEST_CASE("a damaged image, or one of another plan, is refused") {
    const arnoldweb::Plan plan = arnoldweb::make_plan(awtest::scene_from(kScene));
    const arnoldweb::Plan other = arnoldweb::make_plan(awtest::scene_from(kScene, {"ensemble.trajectories=100"}));
    Reduction r(plan);
    const std::string image = r.image();
    CHECK_NOTHROW(Reduction::read(plan, image));
    CHECK_THROWS(Reduction::read(other, image));
    CHECK_THROWS(Reduction::read(plan, image.substr(0, image.size() - 3)));
  }

  TEST_CASE("a checkpoint's identity is the scene's values apart from the defaults") {
    // a key that a later version adds, at its default, must not change the identity of a
    // campaign's checkpoint: only values that differ from Scene{} enter it
    using arnoldweb::detail::values_apart_from_defaults;
    CHECK(values_apart_from_defaults(arnoldweb::Scene{}) == "");
    const std::string text = values_apart_from_defaults(awtest::scene_from("[run]\nduration = 7.0\naverage = 7.0\n"));
    CHECK(text == "[run] average = 7.0\n[run] duration = 7.0\n");
    // what does not change results is not part of it
    CHECK(values_apart_from_defaults(awtest::scene_from("[run]\ndevice = \"cpu\"\ncheckpoint_every = 60\n"
                                                        "[output]\ndir = \"elsewhere\"\n")) == "");
  }

  TEST_CASE("a checkpoint of another scene or version, or a damaged one, is a CheckpointError") {
    const arnoldweb::Job job = arnoldweb::plan_job(awtest::scene_from(kScene));
    const arnoldweb::Job other = arnoldweb::plan_job(awtest::scene_from(kScene, {"ensemble.seed=2"}));
    const arnoldweb::Job same = arnoldweb::plan_job(awtest::scene_from(kScene, {"run.device=\"opencl:0\""}));
    CHECK(arnoldweb::job_identity(job) != arnoldweb::job_identity(other));
    CHECK(arnoldweb::job_identity(job) == arnoldweb::job_identity(same));  // the device does not change results
    arnoldweb::CheckpointInfo info;
    info.version = ARNOLDWEB_VERSION;
    info.identity = arnoldweb::job_identity(job);
    info.parts = 1;
    const Reduction r(job.main());
    const std::string good = arnoldweb::detail::write_checkpoint(info, {r.image()});
    auto resume = [&](const arnoldweb::Job& j, const std::string& image) {
      arnoldweb::Checkpointing c;
      c.resume = image;
      c.resume_path = "ck";
      arnoldweb::detail::JobCheckpoints cp(j, c);
      return cp.resume().size();
    };
    CHECK(resume(job, good) == 1);
    CHECK_THROWS_WITH_AS(resume(other, good), doctest::Contains("another scene"), arnoldweb::CheckpointError);
    std::string flipped = good;
    flipped[flipped.size() / 2] ^= 1;
    CHECK_THROWS_WITH_AS(resume(job, flipped), doctest::Contains("damaged"), arnoldweb::CheckpointError);
    CHECK_THROWS_WITH_AS(resume(job, good.substr(0, 40)), doctest::Contains("damaged"), arnoldweb::CheckpointError);
    CHECK_THROWS_WITH_AS(resume(job, "not a checkpoint at all"), doctest::Contains("not an arnoldweb checkpoint"),
                         arnoldweb::CheckpointError);
    info.version = "0.0.1";
    CHECK_THROWS_WITH_AS(resume(job, arnoldweb::detail::write_checkpoint(info, {r.image()})),
                         doctest::Contains("written by arnoldweb 0.0.1"), arnoldweb::CheckpointError);
  }
}
