#include "cfd/mesh/halo.hpp"

#include <string>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::cfd {

namespace {
constexpr int kHaloTag = 4711;
}

Halo::Halo(MPI_Comm comm, int nLocal, std::vector<Neighbour> neighbours)
    : comm_(comm), nLocal_(nLocal), neighbours_(std::move(neighbours)) {}

void Halo::checkSize(std::size_t size) const {
  PARCELFLOW_ASSERT(static_cast<int>(size) == nLocal_,
                        "halo field has " + std::to_string(size) + " entries, mesh has " +
                            std::to_string(nLocal_) + " local cells");
}

void Halo::exchangeRaw(double* data, int width, std::size_t size) const {
  checkSize(size);
  if (neighbours_.empty()) return;
  std::vector<std::vector<double>> sendBuf(neighbours_.size()), recvBuf(neighbours_.size());
  std::vector<MPI_Request> requests;
  requests.reserve(2 * neighbours_.size());
  for (std::size_t n = 0; n < neighbours_.size(); ++n) {
    const auto& nb = neighbours_[n];
    recvBuf[n].resize(nb.recv.size() * width);
    requests.emplace_back();
    MPI_Irecv(recvBuf[n].data(), static_cast<int>(recvBuf[n].size()), MPI_DOUBLE, nb.rank, kHaloTag,
              comm_, &requests.back());
  }
  for (std::size_t n = 0; n < neighbours_.size(); ++n) {
    const auto& nb = neighbours_[n];
    auto& buf = sendBuf[n];
    buf.reserve(nb.send.size() * width);
    for (int c : nb.send)
      for (int w = 0; w < width; ++w) buf.push_back(data[static_cast<std::size_t>(c) * width + w]);
    requests.emplace_back();
    MPI_Isend(buf.data(), static_cast<int>(buf.size()), MPI_DOUBLE, nb.rank, kHaloTag, comm_,
              &requests.back());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  for (std::size_t n = 0; n < neighbours_.size(); ++n) {
    const auto& nb = neighbours_[n];
    for (std::size_t i = 0; i < nb.recv.size(); ++i)
      for (int w = 0; w < width; ++w)
        data[static_cast<std::size_t>(nb.recv[i]) * width + w] = recvBuf[n][i * width + w];
  }
}

}  // namespace parcelflow::cfd
