// Test helpers: one in-process LIGGGHTS instance with parcelflow's styles, driven by script commands,
// and per-atom values gathered by atom ID onto every rank.
#pragma once

#include <mpi.h>

#include <array>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "atom.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "liggghts_plugins/register_styles.h"

namespace parcelflow::plugins::testing {

inline int rank() { int r; MPI_Comm_rank(MPI_COMM_WORLD, &r); return r; }
inline int nranks() { int n; MPI_Comm_size(MPI_COMM_WORLD, &n); return n; }

// A scratch directory shared by all ranks (created by rank 0), and its removal (collective; tests call it
// when they pass, so a failed test leaves its logs and files behind).
std::string scratch_dir(const std::string& name);
void remove_scratch_dir(const std::string& dir);

class Session {
 public:
  // log: a file name, or "none"
  explicit Session(const std::string& log = "none");
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  void cmd(const std::string& line) { lmp_->input->one(line.c_str()); }
  void file(const std::string& path) { lmp_->input->file(path.c_str()); }
  // `clear` re-creates Modify: the styles must be registered again (parcelflow's program does it itself)
  void clear() { cmd("clear"); register_styles(lmp_); }
  template <class T> T* fix(const std::string& id)
  {
    const int i = lmp_->modify->find_fix(id.c_str());
    return i < 0 ? nullptr : dynamic_cast<T*>(lmp_->modify->fix[i]);
  }
  LAMMPS_NS::LAMMPS* lmp() { return lmp_; }

 private:
  MPI_Comm comm_;
  LAMMPS_NS::LAMMPS* lmp_;
};

// values(i) of every local atom, gathered by tag on every rank
template <std::size_t N>
std::map<int, std::array<double, N>> gather_by_tag(LAMMPS_NS::LAMMPS* lmp,
                                                   const std::function<std::array<double, N>(int)>& values)
{
  std::vector<double> local;
  for (int i = 0; i < lmp->atom->nlocal; ++i) {
    local.push_back(lmp->atom->tag[i]);
    const auto v = values(i);
    local.insert(local.end(), v.begin(), v.end());
  }
  int n = static_cast<int>(local.size()), p = nranks();
  std::vector<int> counts(p), displs(p, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int k = 1; k < p; ++k) displs[k] = displs[k - 1] + counts[k - 1];
  std::vector<double> all(displs[p - 1] + counts[p - 1]);
  MPI_Allgatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  std::map<int, std::array<double, N>> out;
  for (std::size_t k = 0; k < all.size(); k += N + 1) {
    std::array<double, N> v;
    for (std::size_t c = 0; c < N; ++c) v[c] = all[k + 1 + c];
    out[static_cast<int>(all[k])] = v;
  }
  return out;
}

inline long sum_all(long v) { long r; MPI_Allreduce(&v, &r, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD); return r; }
inline double sum_all(double v) { double r; MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD); return r; }
inline double max_all(double v) { double r; MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD); return r; }

// printf on rank 0 only (line-buffered)
#define PF_PRINT(...) do { if (::parcelflow::plugins::testing::rank() == 0) { std::printf(__VA_ARGS__); std::fflush(stdout); } } while (0)

}  // namespace parcelflow::plugins::testing
