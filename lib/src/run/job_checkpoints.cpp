// arnoldweb: the checkpoints of a job (job_checkpoints.hpp).
#include "run/job_checkpoints.hpp"

#include <chrono>
#include <stdexcept>

#include "arnoldweb/checkpoint.hpp"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/version.hpp"
#include "run/checkpoint_image.hpp"

namespace arnoldweb::detail {
namespace {

constexpr double kAutoPeriod = 600;        // "auto": every 10 min ...
constexpr double kAutoAbove = 3600;        // ... for jobs estimated above an hour,
constexpr double kAutoEstimateAfter = 60;  // estimated once they ran a minute

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double work_of(const Plan& p, std::uint64_t trajectories) {
  return static_cast<double>(trajectories) * static_cast<double>(p.steps_per_trajectory);
}

}  // namespace

JobCheckpoints::JobCheckpoints(const Job& job, Checkpointing& c) : job_(job), c_(c), identity_(job_identity(job)) {
  start_ = last_ = now_seconds();
}

PartReductions JobCheckpoints::resume() {
  PartReductions parts;
  if (c_.resume.empty()) return parts;
  CheckpointInfo info;
  std::vector<std::string> images;
  read_checkpoint(c_.resume, c_.resume_path, info, images);
  if (info.version != ARNOLDWEB_VERSION)
    throw CheckpointError(c_.resume_path, "the checkpoint was written by arnoldweb " + info.version +
                                              " and this is arnoldweb " ARNOLDWEB_VERSION
                                              "; finish it with that version, or remove it to start afresh");
  if (info.identity != identity_ || info.parts != job_.parts.size())
    throw CheckpointError(c_.resume_path,
                          "the checkpoint is of another scene (" + info.scene_file +
                              " with other values: its identity is " + info.identity + ", this job's is " +
                              identity_ + "); resume it with the scene and --set values it was started with");
  for (std::size_t k = 0; k < images.size(); ++k) {
    try {
      parts.push_back(std::make_unique<Reduction>(Reduction::read(job_.parts[k].plan, images[k])));
    } catch (const std::runtime_error& e) {
      throw CheckpointError(c_.resume_path,
                            "the checkpoint is damaged (part " + std::to_string(k) + ": " + e.what() + ")");
    }
    resumed_work_ += work_of(job_.parts[k].plan, parts.back()->completed());
  }
  return parts;
}

bool JobCheckpoints::due(std::size_t k, const PartReductions& parts) {
  const double t = now_seconds();
  if (c_.every_seconds > 0) return t - last_ >= c_.every_seconds;
  if (c_.every_seconds < 0) {
    if (!auto_on_ && t - start_ >= kAutoEstimateAfter) auto_on_ = estimate_total(k, parts, t) > kAutoAbove;
    return auto_on_ && t - last_ >= kAutoPeriod;
  }
  return false;
}

// Wall seconds the whole job takes, from this run's rate so far.
double JobCheckpoints::estimate_total(std::size_t k, const PartReductions& parts, double t) const {
  double done = 0, all = 0;
  for (std::size_t i = 0; i < job_.parts.size(); ++i) {
    const Plan& p = job_.parts[i].plan;
    all += work_of(p, p.scene.trajectories);
    if (i <= k && i < parts.size()) done += work_of(p, parts[i]->completed());
  }
  done -= resumed_work_;
  if (done <= 0) return 0;
  return (t - start_) / done * (all - resumed_work_);
}

void JobCheckpoints::save(std::size_t k, const PartReductions& parts, const std::vector<std::uint64_t>& histograms,
                          bool stopping, double part_seconds) {
  CheckpointInfo info;
  info.version = ARNOLDWEB_VERSION;
  info.identity = identity_;
  const Scene& main = job_.main().scene;
  info.scene_file = main.file;
  info.scene_text = main.text;
  info.overrides = main.overrides;
  info.override_labels = main.override_labels;
  info.parts = job_.parts.size();
  std::vector<std::string> images;
  for (std::size_t i = 0; i < job_.parts.size(); ++i) {
    info.trajectories += job_.parts[i].plan.scene.trajectories;
    if (i > k) continue;
    if (i < k) {
      images.push_back(parts[i]->image());
    } else {
      Reduction snapshot = *parts[i];
      snapshot.add_histograms(histograms);
      snapshot.seconds += part_seconds;
      images.push_back(snapshot.image());
    }
    info.completed += parts[i]->completed();
  }
  c_.sink->save(write_checkpoint(info, images));
  last_ = now_seconds();
  ++c_.saved;
  c_.saved_incomplete = stopping;
}

}  // namespace arnoldweb::detail
