// arnoldweb CLI under mpirun/srun (ranks.cpp): rank 0 checks, coordinates
// and writes; the other ranks plan the scene rank 0 shares and drive one
// device each.
#pragma once

#include <optional>
#include <string>

#include "arnoldweb/cluster.hpp"
#include "arnoldweb/scene.hpp"

namespace arnoldweb::cli {

void set_cluster(Cluster* cluster);
Cluster* cluster();  // null in one process

// A build without MPI started by mpirun: refused (each copy would run the whole scene).
void refuse_mpirun_without_mpi();
// --device a,b,c: this rank's entry (rank modulo the list's length); none without a list.
std::optional<std::string> explicit_rank_device(const std::optional<std::string>& device_option);
// The device this rank drives: its entry of a --device list; else, with
// several ranks, the node's device of the node-local rank's index among the
// devices of the kind asked for (cpu: the cpu backend); else the device asked for.
std::string rank_device(const std::optional<std::string>& device_option, const std::string& scene_device);
// Rank 0: the scene as prepared, to every other rank (collective).
void share_scene(const Scene& scene);
// The other ranks' `run` and `resume`: receive the scene, plan it, serve.
int serve_rank(const std::optional<std::string>& device_option);

}  // namespace arnoldweb::cli
