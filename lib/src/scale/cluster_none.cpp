// arnoldweb: a build without MPI (cluster.hpp): no cluster.
#include "arnoldweb/cluster.hpp"

namespace arnoldweb {

bool cluster_built() { return false; }

std::unique_ptr<Cluster> start_cluster(int*, char***) { return nullptr; }

}  // namespace arnoldweb
