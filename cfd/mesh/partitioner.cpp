#include "cfd/mesh/partitioner.hpp"

#include <metis.h>

#include <string>

#include "cfd/base/config_error.hpp"
#include "cfd/base/internal_error.hpp"

namespace parcelflow::cfd {

std::vector<int> Partitioner::partition(MPI_Comm comm, const std::vector<int>& xadj,
                                        const std::vector<int>& adjncy,
                                        const std::vector<int>& weights) {
  int rank = 0, nRanks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &nRanks);
  const int nCells = static_cast<int>(xadj.size()) - 1;
  if (nCells < nRanks)
    throw ConfigError("the mesh has " + std::to_string(nCells) + " fluid cells, fewer than the " +
                      std::to_string(nRanks) + " MPI ranks");
  std::vector<int> part(nCells, 0);
  if (nRanks == 1) return part;
  if (rank == 0) {
    idx_t nvtxs = nCells, ncon = 1, nparts = nRanks, objval = 0;
    std::vector<idx_t> x(xadj.begin(), xadj.end()), a(adjncy.begin(), adjncy.end());
    std::vector<idx_t> w(weights.begin(), weights.end()), p(nCells);
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    const int status = METIS_PartGraphKway(&nvtxs, &ncon, x.data(), a.data(), w.data(), nullptr,
                                           nullptr, &nparts, nullptr, nullptr, options, &objval,
                                           p.data());
    PARCELFLOW_ASSERT(status == METIS_OK, "METIS_PartGraphKway failed with " +
                                                  std::to_string(status));
    part.assign(p.begin(), p.end());
  }
  MPI_Bcast(part.data(), nCells, MPI_INT, 0, comm);
  return part;
}

}  // namespace parcelflow::cfd
