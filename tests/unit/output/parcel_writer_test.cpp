// ParcelWriter on 1 and 2 ranks: a series with empty ranks and an empty snapshot, continued after a
// "restart", read back by check_parcels.py with h5py; and failures that name the file.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <mpi.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "coupling/output/parcel_writer.h"

using parcelflow::coupling::ParcelSnapshot;
using parcelflow::coupling::ParcelWriter;
namespace fs = std::filesystem;

namespace {
int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int size() {
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

// A fresh folder in the temporary directory, shared by all ranks and removed at scope exit.
class TempFolder {
 public:
  TempFolder() {
    char buffer[4096] = {};
    if (rank() == 0) {
      std::string pattern = (fs::temp_directory_path() / "parcel_writer_XXXXXX").string();
      if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
      pattern.copy(buffer, sizeof buffer - 1);
    }
    MPI_Bcast(buffer, sizeof buffer, MPI_CHAR, 0, MPI_COMM_WORLD);
    path_ = buffer;
  }
  ~TempFolder() {
    MPI_Barrier(MPI_COMM_WORLD);
    if (rank() == 0) fs::remove_all(path_);
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// n parcels of this rank; ids 1000 * rank + 7 i + 1, every value a function of the id (check_parcels.py).
ParcelSnapshot parcels(int n) {
  ParcelSnapshot s;
  for (int i = 0; i < n; ++i) {
    const long id = 1000L * rank() + 7 * i + 1;
    const double k = static_cast<double>(id);
    s.x.insert(s.x.end(), {1e-3 * k, 2e-3 * k, 3e-3 * k});
    s.v.insert(s.v.end(), {-k, 0.5 * k, 0.25 * k});
    s.dp.push_back(1e-3 * (1 + id % 3));
    s.np.push_back(8.0 + k);
    s.type.push_back(1 + static_cast<int>(id % 2));
    s.id.push_back(id);
  }
  return s;
}
}  // namespace

TEST(ParcelWriter, WritesSeriesAndContinuesIt) {
  TempFolder dir;
  const int ranks = size();
  {
    ParcelWriter writer(MPI_COMM_WORLD, dir.path(), "parcels");
    writer.write(0.25, parcels(3 + 2 * rank()));
    writer.write(0.5, parcels(0));                      // no parcels at all
    writer.write(0.75, parcels(rank() == 0 ? 0 : 4));   // rank 0 empty
    writer.write(1.0, parcels(9));                      // after the checkpoint: dropped below
    EXPECT_EQ(writer.snapshots(), 4u);
  }
  ParcelWriter continued(MPI_COMM_WORLD, dir.path(), "parcels");
  continued.continueSeries(3);
  EXPECT_EQ(continued.snapshots(), 3u);
  continued.write(1.0, parcels(2));
  EXPECT_EQ(continued.snapshots(), 4u);
  int status = 0;
  if (rank() == 0) {
    const std::string expected = "0.25:" + std::to_string(ranks * (ranks + 2)) + " 0.5:0 0.75:" +
                                 std::to_string(4 * (ranks - 1)) + " 1.0:" + std::to_string(2 * ranks);
    const std::string command = PARCELFLOW_PYTHON " " PARCELFLOW_CHECK_PARCELS " " + dir.path() + " " + expected;
    status = std::system(command.c_str());
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
  EXPECT_EQ(status, 0) << "check_parcels.py failed";
}

TEST(ParcelWriter, FailuresNameTheFile) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // the expected failures need no HDF5 error stack
  TempFolder dir;
  const std::string missing = dir.path() + "/no_such_folder";
  ParcelWriter writer(MPI_COMM_WORLD, missing, "p");
  try {
    writer.write(0.0, parcels(1));
    ADD_FAILURE() << "writing into a missing folder did not throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(missing + "/p_000000.h5"), std::string::npos) << e.what();
  }
  ParcelWriter continued(MPI_COMM_WORLD, dir.path(), "p");
  try {
    continued.continueSeries(1);
    ADD_FAILURE() << "continuing from a missing snapshot did not throw";
  } catch (const std::runtime_error& e) {
    if (rank() == 0) {
      EXPECT_NE(std::string(e.what()).find("p_000000.h5"), std::string::npos) << e.what();
    }
  }
}
