// arnoldweb: what the process launcher says about this process (cluster.hpp),
// read from the environment of OpenMPI, MPICH/Hydra (PMI) and Slurm job steps (srun).
#include <cstdlib>

#include "arnoldweb/cluster.hpp"

namespace arnoldweb {
namespace {

int first_number(std::initializer_list<const char*> names, int fallback) {
  for (const char* n : names)
    if (const char* v = std::getenv(n); v && *v) return std::atoi(v);
  return fallback;
}

}  // namespace

int launcher_size() {
  return first_number({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS"}, 1);
}

int launcher_local_rank() {
  return first_number({"OMPI_COMM_WORLD_LOCAL_RANK", "MPI_LOCALRANKID", "SLURM_LOCALID"}, 0);
}

}  // namespace arnoldweb
