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
// Under MPI, --device a,b,c: this rank's entry (rank modulo the list's
// length); none without a list or without MPI (one process drives the whole list).
std::optional<std::string> explicit_rank_device(const std::optional<std::string>& device_option);
// What this process drives. One process: the device (or list, or "all") asked
// for. Several ranks: its entry of a list (--device's, else run.device's); else
// the node's device of the node-local rank's index among the devices of the
// kind asked for ("auto" and "all": the default device's kind; cpu: the cpu backend).
std::string rank_device(const std::optional<std::string>& device_option, const std::string& scene_device);
// Rank 0: the scene as prepared, to every other rank (collective).
void share_scene(const Scene& scene);
// The other ranks' `run` and `resume`: receive the scene, plan it, serve.
int serve_rank(const std::optional<std::string>& device_option);

}  // namespace arnoldweb::cli
