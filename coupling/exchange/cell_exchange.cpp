#include "cell_exchange.h"

#include <mpi.h>

#include <numeric>
#include <stdexcept>
#include <string>

#include "cfd/internal_error.hpp"

namespace parcelflow::coupling {

namespace {

std::vector<int> scaled(const std::vector<int>& v, int factor) {
  std::vector<int> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out[i] = v[i] * factor;
  return out;
}

}  // namespace

void CellExchange::setCells(const std::vector<long>& cells) {
  MPI_Comm comm = owners_.comm();
  int nranks = 0;
  MPI_Comm_size(comm, &nranks);
  Routing& r = route_;
  r = Routing{};
  r.send_counts.assign(nranks, 0);
  for (long cell : cells) {
    const int owner = owners_.ownerRank(cell);
    PARCELFLOW_ASSERT(owner >= 0, "CellExchange: background cell " + std::to_string(cell) + " is not fluid");
    ++r.send_counts[owner];
  }
  r.send_offsets.assign(nranks, 0);
  std::partial_sum(r.send_counts.begin(), r.send_counts.end() - 1, r.send_offsets.begin() + 1);
  std::vector<int> fill = r.send_offsets;
  r.order.resize(cells.size());
  std::vector<int> send_index(cells.size());
  for (std::size_t t = 0; t < cells.size(); ++t) {
    const int slot = fill[owners_.ownerRank(cells[t])]++;
    r.order[slot] = static_cast<int>(t);
    send_index[slot] = owners_.ownerIndex(cells[t]);
  }
  r.recv_counts.assign(nranks, 0);
  MPI_Alltoall(r.send_counts.data(), 1, MPI_INT, r.recv_counts.data(), 1, MPI_INT, comm);
  r.recv_offsets.assign(nranks, 0);
  std::partial_sum(r.recv_counts.begin(), r.recv_counts.end() - 1, r.recv_offsets.begin() + 1);
  r.remote_index.resize(r.recv_offsets.back() + r.recv_counts.back());
  MPI_Alltoallv(send_index.data(), r.send_counts.data(), r.send_offsets.data(), MPI_INT, r.remote_index.data(),
                r.recv_counts.data(), r.recv_offsets.data(), MPI_INT, comm);
}

void CellExchange::sumToOwners(const std::vector<double>& values, int width, std::vector<double>& owned) const {
  const Routing& r = route_;
  PARCELFLOW_ASSERT(values.size() == r.order.size() * width, "CellExchange: values do not match the routed cells");
  std::vector<double> send(values.size());
  for (std::size_t slot = 0; slot < r.order.size(); ++slot)
    for (int k = 0; k < width; ++k) send[slot * width + k] = values[r.order[slot] * width + k];
  std::vector<double> recv(r.remote_index.size() * width);
  MPI_Alltoallv(send.data(), scaled(r.send_counts, width).data(), scaled(r.send_offsets, width).data(), MPI_DOUBLE,
                recv.data(), scaled(r.recv_counts, width).data(), scaled(r.recv_offsets, width).data(), MPI_DOUBLE,
                owners_.comm());
  for (std::size_t t = 0; t < r.remote_index.size(); ++t)
    for (int k = 0; k < width; ++k) owned[r.remote_index[t] * width + k] += recv[t * width + k];
}

void CellExchange::fetchFromOwners(const std::vector<double>& owned, int width, std::vector<double>& out) const {
  const Routing& r = route_;
  std::vector<double> reply(r.remote_index.size() * width);
  for (std::size_t t = 0; t < r.remote_index.size(); ++t)
    for (int k = 0; k < width; ++k) reply[t * width + k] = owned[r.remote_index[t] * width + k];
  std::vector<double> recv(r.order.size() * width);
  MPI_Alltoallv(reply.data(), scaled(r.recv_counts, width).data(), scaled(r.recv_offsets, width).data(), MPI_DOUBLE,
                recv.data(), scaled(r.send_counts, width).data(), scaled(r.send_offsets, width).data(), MPI_DOUBLE,
                owners_.comm());
  out.assign(r.order.size() * width, 0.0);
  for (std::size_t slot = 0; slot < r.order.size(); ++slot)
    for (int k = 0; k < width; ++k) out[r.order[slot] * width + k] = recv[slot * width + k];
}

}  // namespace parcelflow::coupling
