// Base of parcelflow's fixes that keep a fixed number of per-atom columns (double** data_, one row per
// atom): the rows follow their atoms between ranks (grow/copy/exchange), are written to and read from
// restart files, and are the fix's per-atom output (dump f_ID[1..n]). Derived fixes set the values of new
// atoms in set_arrays().
#pragma once

#include "fix.h"

namespace parcelflow::plugins {

class PerAtomColumnsFix : public LAMMPS_NS::Fix {
 public:
  PerAtomColumnsFix(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg, int ncolumns);
  ~PerAtomColumnsFix() override;

  void grow_arrays(int nmax) final;
  void copy_arrays(int i, int j, int delflag) final;
  int pack_exchange(int i, double* buf) final;
  int unpack_exchange(int nlocal, double* buf) final;
  int pack_restart(int i, double* buf) final;
  void unpack_restart(int nlocal, int nth) final;
  int size_restart(int i) final;
  int maxsize_restart() final;
  double memory_usage() final;

  // Row i (local atom) of the columns; re-fetch after every run (atoms move and reorder).
  double** peratom() { return data_; }
  int ncolumns() const { return ncolumns_; }
  // Atoms this rank received from other ranks since the fix was created (shows migration in tests).
  long atoms_received() const { return atoms_received_; }

 protected:
  double** data_ = nullptr;

 private:
  const int ncolumns_;
  long atoms_received_ = 0;
};

}  // namespace parcelflow::plugins
