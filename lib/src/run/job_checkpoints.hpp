// arnoldweb: the checkpoints of a job (run.hpp: Checkpointing;
// checkpoint.hpp): when one is due (every_seconds, or "auto": every 10 min
// once the job is estimated above an hour), saving the reductions of the
// parts begun (the current one with the devices' histograms so far), and
// reading them back to resume. Used by run_job (one process) and by the
// coordinator of several (scale/).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "arnoldweb/run.hpp"
#include "run/reduction.hpp"

namespace arnoldweb::detail {

using PartReductions = std::vector<std::unique_ptr<Reduction>>;

class JobCheckpoints {
 public:
  JobCheckpoints(const Job& job, Checkpointing& c);
  // The reductions of the parts begun, from c.resume (empty if none); throws
  // CheckpointError for a damaged checkpoint or one of another scene or version.
  PartReductions resume();
  // Whether a stop request saves a checkpoint (on, or "auto" switched on).
  bool active() const { return c_.every_seconds >= 0 || auto_on_; }
  // Whether a periodic checkpoint is due now, part k running.
  bool due(std::size_t k, const PartReductions& parts);
  // Saves parts [0, k], part k with `histograms` (the devices' so far) added.
  void save(std::size_t k, const PartReductions& parts, const std::vector<std::uint64_t>& histograms, bool stopping,
            double part_seconds);

 private:
  double estimate_total(std::size_t k, const PartReductions& parts, double t) const;
  const Job& job_;
  Checkpointing& c_;
  std::string identity_;
  double start_ = 0, last_ = 0, resumed_work_ = 0;
  bool auto_on_ = false;
};

}  // namespace arnoldweb::detail
