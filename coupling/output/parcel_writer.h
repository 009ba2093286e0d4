// Writes parcels with parallel HDF5 plus an XDMF index that ParaView opens (a temporal collection of
// Polyvertex grids). Each rank writes its local parcels as one contiguous hyperslab, in rank order.
//
// Files in `directory`: <name>_NNNNNN.h5 (datasets /position (n,3), /velocity (n,3), /dp, /np, /type,
// /id, /time (1), and /connectivity = 0..n-1, without which ParaView's Xdmf3 readers make no vertex
// cells) and <name>.xdmf. The index is replaced atomically (written to <name>.xdmf.partial, then
// renamed) after every rank has closed the snapshot's file, so it lists only complete files.
// A snapshot without parcels is a valid 0-point grid: ParaView's Xdmf3 readers (its default) show it
// empty; its older "XDMF Reader" reports a read error for it and shows it empty too.
// Collective: every rank of `comm` calls every method. HDF5 failures throw std::runtime_error naming
// the file.
#pragma once

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace parcelflow::coupling {

// This rank's parcels: x and v interleaved (3 per parcel), the others one value per parcel.
struct ParcelSnapshot {
  std::vector<double> x, v, dp, np;
  std::vector<int> type;
  std::vector<std::int64_t> id;
};

class ParcelWriter {
 public:
  ParcelWriter(MPI_Comm comm, std::string directory, std::string name);

  // A restarted run: keeps the first `snapshots` files of the series (snapshots() when the checkpoint
  // was written), re-reads their times and sizes, rewrites the index with only them, and numbers the
  // next write `snapshots`. Later files stay on disk until overwritten.
  void continueSeries(std::size_t snapshots);
  // Writes snapshot number snapshots() at `time` and rewrites the index.
  void write(double time, const ParcelSnapshot& local);

  std::size_t snapshots() const { return times_.size(); }

 private:
  std::string fileName(std::size_t index) const;
  void publishIndex() const;  // rank 0 writes the index; a failure throws on every rank
  void writeXdmf() const;

  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
  std::string directory_, name_;
  std::vector<double> times_;  // per snapshot
  std::vector<long> counts_;   // parcels per snapshot, all ranks
};

}  // namespace parcelflow::coupling
