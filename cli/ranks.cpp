// arnoldweb CLI under mpirun/srun (docs/cluster.md): which device each rank
// drives, the scene rank 0 hands to the others, and the other ranks' side of
// `run` and `resume`.
#include "ranks.hpp"

#include <nlohmann/json.hpp>

#include "arnoldweb/accuracy.hpp"
#include "arnoldweb/cluster.hpp"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/inputs.hpp"
#include "command.hpp"
#include "stop_signals.hpp"

namespace arnoldweb::cli {
namespace {

Cluster* g_cluster = nullptr;

}  // namespace

void set_cluster(Cluster* cluster) { g_cluster = cluster; }
Cluster* cluster() { return g_cluster; }

void refuse_mpirun_without_mpi() {
  if (!g_cluster && launcher_size() > 1)
    throw OutputRefused("", "this arnoldweb was built without MPI, and mpirun (or srun) started " +
                                std::to_string(launcher_size()) +
                                " copies of it: each would run the whole scene. mpirun needs the MPI build "
                                "(install libopenmpi-dev and build again: cmake finds it), or run one process");
}

std::optional<std::string> explicit_rank_device(const std::optional<std::string>& device_option) {
  const auto device = read_device_option(device_option);
  if (!g_cluster || !device) return std::nullopt;
  const auto list = device_entries(*device);
  if (list.size() < 2) return std::nullopt;
  return list[static_cast<std::size_t>(g_cluster->rank()) % list.size()];
}

std::string rank_device(const std::optional<std::string>& device_option, const std::string& scene_device) {
  const std::string spec = device_option ? *read_device_option(device_option) : scene_device;
  if (!g_cluster || g_cluster->size() <= 1) return spec;  // one process drives every device it names
  const auto list = device_entries(spec);
  if (list.size() > 1) return list[static_cast<std::size_t>(g_cluster->rank()) % list.size()];
  // the node-local rank picks the node's device of that index, of the kind
  // asked for ("all": of the default device's kind, the node's GPUs)
  const std::string id = spec == "auto" || spec == "all" ? default_device_id() : spec;
  const std::string kind = id.substr(0, id.find(':'));
  if (kind == "cpu") return "cpu";
  std::vector<std::string> same;
  for (const DeviceInfo& d : list_devices())
    if (d.backend == kind) same.push_back(d.id);
  if (same.empty()) return id;
  return same[static_cast<std::size_t>(g_cluster->local_rank()) % same.size()];
}

void share_scene(const Scene& scene) {
  if (!g_cluster) return;
  const nlohmann::json j = {{"file", scene.file},
                            {"text", scene.text},
                            {"overrides", scene.overrides},
                            {"labels", scene.override_labels}};
  g_cluster->broadcast(j.dump());
}

int serve_rank(const std::optional<std::string>& device_option) {
  Cluster& c = *g_cluster;
  const nlohmann::json j = nlohmann::json::parse(c.broadcast(""));
  const Scene scene = parse_scene(j["text"].get<std::string>(), j["file"].get<std::string>(),
                                  j["overrides"].get<std::vector<std::string>>(),
                                  j["labels"].get<std::vector<std::string>>());
  const Job job = plan_job(scene, read_plan_inputs(scene), cpu_pilot());
  auto backend = open_backend(rank_device(device_option, scene.device));
  StopSignals signals;
  RunOptions options;
  options.stop = &signals.flag();
  c.serve(job, *backend, options);
  return 0;
}

}  // namespace arnoldweb::cli
