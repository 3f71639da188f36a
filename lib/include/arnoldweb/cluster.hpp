// arnoldweb: one job over several devices. Chunks of the index range go to
// whichever device asks next, and every chunk's outputs are folded into one
// exact reduction, so the result is the same bits for any number of devices
// and any assignment of chunks (docs/cluster.md).
//  - run_job_on_devices: several devices of this process (threads);
//  - Cluster: the ranks of an MPI job (mpirun, srun), one device each; rank 0
//    coordinates (and drives its own device in a thread) and writes the
//    outputs. Available when the library was built with MPI (cluster_built()).
// No MPI header leaks out of this file.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "arnoldweb/run.hpp"

namespace arnoldweb {

// Runs a job over `devices` (threads of this process): results, checkpoints
// and stop requests as run_job's; the results name every device
// (describe_devices) and their kernels.
JobResult run_job_on_devices(const Job& job, const std::vector<Backend*>& devices, const RunOptions& options = {},
                             JobObserver* observer = nullptr);

// One device: run_job; several: run_job_on_devices (a process that drives
// every device of a run.device list, docs/cluster.md).
JobResult run_job_on(const Job& job, const std::vector<Backend*>& devices, const RunOptions& options = {},
                     JobObserver* observer = nullptr);

// Whether this library was built with MPI.
bool cluster_built();

// How many processes the launcher started, from its environment
// (OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_SIZE... ; 1 when not under one).
int launcher_size();
// This process's node-local index among them (0 when not under a launcher).
int launcher_local_rank();

class Cluster {
 public:
  virtual ~Cluster() = default;  // MPI_Finalize
  virtual int rank() const = 0;
  virtual int size() const = 0;
  virtual int local_rank() const = 0;
  // Rank 0's `bytes`, on every rank (collective).
  virtual std::string broadcast(const std::string& bytes) = 0;
  // Rank 0: runs the job over every rank, its own `backend` included;
  // results, checkpoints and stop requests as run_job's.
  virtual JobResult run_job(const Job& job, Backend& backend, const RunOptions& options, JobObserver* observer) = 0;
  // The other ranks: run what rank 0 hands out on `backend` until the job ends.
  virtual void serve(const Job& job, Backend& backend, const RunOptions& options) = 0;
  // Ends every rank of the job now (MPI_Abort) with `code`.
  [[noreturn]] virtual void abort(int code) = 0;
};

// MPI_Init when built with MPI and started by a launcher with more than one
// process; null otherwise.
std::unique_ptr<Cluster> start_cluster(int* argc, char*** argv);

}  // namespace arnoldweb
