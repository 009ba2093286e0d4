#include "coupling/exchange/cell_exchange.h"

#include <mpi.h>

#include <numeric>
#include <stdexcept>
#include <string>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

void CellExchange::setCells(const std::vector<long>& cells) {
  MPI_Comm comm = owners_.comm();
  int nranks = 0;
  MPI_Comm_size(comm, &nranks);
  Routing& r = route_;  // refilled in place: its vectors keep their capacity from step to step
  r.send_counts.assign(nranks, 0);
  for (long cell : cells) {
    const int owner = owners_.ownerRank(cell);
    PARCELFLOW_ASSERT(owner >= 0, "CellExchange: background cell " + std::to_string(cell) + " is not fluid");
    ++r.send_counts[owner];
  }
  r.send_offsets.assign(nranks, 0);
  std::partial_sum(r.send_counts.begin(), r.send_counts.end() - 1, r.send_offsets.begin() + 1);
  std::vector<int>& fill = counts_[0];
  fill = r.send_offsets;
  r.order.resize(cells.size());
  r.send_index.resize(cells.size());
  for (std::size_t t = 0; t < cells.size(); ++t) {
    const int slot = fill[owners_.ownerRank(cells[t])]++;
    r.order[slot] = static_cast<int>(t);
    r.send_index[slot] = owners_.ownerIndex(cells[t]);
  }
  r.recv_counts.assign(nranks, 0);
  MPI_Alltoall(r.send_counts.data(), 1, MPI_INT, r.recv_counts.data(), 1, MPI_INT, comm);
  r.recv_offsets.assign(nranks, 0);
  std::partial_sum(r.recv_counts.begin(), r.recv_counts.end() - 1, r.recv_offsets.begin() + 1);
  r.remote_index.resize(r.recv_offsets.back() + r.recv_counts.back());
  MPI_Alltoallv(r.send_index.data(), r.send_counts.data(), r.send_offsets.data(), MPI_INT, r.remote_index.data(),
                r.recv_counts.data(), r.recv_offsets.data(), MPI_INT, comm);
}

void CellExchange::scaleCounts(int width) const {
  const Routing& r = route_;
  const std::vector<int>* counts[4] = {&r.send_counts, &r.send_offsets, &r.recv_counts, &r.recv_offsets};
  for (int a = 0; a < 4; ++a) {
    counts_[a].resize(counts[a]->size());
    for (std::size_t i = 0; i < counts[a]->size(); ++i) counts_[a][i] = (*counts[a])[i] * width;
  }
}

void CellExchange::sumToOwners(const std::vector<double>& values, int width, std::vector<double>& owned) const {
  const Routing& r = route_;
  PARCELFLOW_ASSERT(values.size() == r.order.size() * width, "CellExchange: values do not match the routed cells");
  send_.resize(values.size());
  for (std::size_t slot = 0; slot < r.order.size(); ++slot)
    for (int k = 0; k < width; ++k) send_[slot * width + k] = values[r.order[slot] * width + k];
  recv_.resize(r.remote_index.size() * width);
  scaleCounts(width);
  MPI_Alltoallv(send_.data(), counts_[0].data(), counts_[1].data(), MPI_DOUBLE, recv_.data(), counts_[2].data(),
                counts_[3].data(), MPI_DOUBLE, owners_.comm());
  for (std::size_t t = 0; t < r.remote_index.size(); ++t)
    for (int k = 0; k < width; ++k) owned[r.remote_index[t] * width + k] += recv_[t * width + k];
}

void CellExchange::fetchFromOwners(const std::vector<double>& owned, int width, std::vector<double>& out) const {
  const Routing& r = route_;
  send_.resize(r.remote_index.size() * width);  // the owners' reply
  for (std::size_t t = 0; t < r.remote_index.size(); ++t)
    for (int k = 0; k < width; ++k) send_[t * width + k] = owned[r.remote_index[t] * width + k];
  recv_.resize(r.order.size() * width);
  scaleCounts(width);
  MPI_Alltoallv(send_.data(), counts_[2].data(), counts_[3].data(), MPI_DOUBLE, recv_.data(), counts_[0].data(),
                counts_[1].data(), MPI_DOUBLE, owners_.comm());
  out.resize(r.order.size() * width);
  for (std::size_t slot = 0; slot < r.order.size(); ++slot)
    for (int k = 0; k < width; ++k) out[r.order[slot] * width + k] = recv_[slot * width + k];
}

}  // namespace parcelflow::coupling
