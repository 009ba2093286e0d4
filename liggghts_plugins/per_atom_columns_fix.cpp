#include "liggghts_plugins/per_atom_columns_fix.h"

#include <cstring>

#include "atom.h"
#include "memory.h"

namespace parcelflow::plugins {

PerAtomColumnsFix::PerAtomColumnsFix(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg, int ncolumns)
    : Fix(lmp, narg, arg), ncolumns_(ncolumns)
{
  peratom_flag = 1;
  size_peratom_cols = ncolumns;
  peratom_freq = 1;
  create_attribute = 1;  // set_arrays() for atoms created later
  restart_peratom = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(0);  // grow, copy, exchange
  atom->add_callback(1);  // restart
}

PerAtomColumnsFix::~PerAtomColumnsFix()
{
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(data_);
}

void PerAtomColumnsFix::grow_arrays(int nmax)
{
  memory->grow(data_, nmax, ncolumns_, "parcelflow:per-atom columns");
  array_atom = data_;
}

void PerAtomColumnsFix::copy_arrays(int i, int j, int)
{
  std::memcpy(data_[j], data_[i], ncolumns_ * sizeof(double));
}

int PerAtomColumnsFix::pack_exchange(int i, double* buf)
{
  std::memcpy(buf, data_[i], ncolumns_ * sizeof(double));
  return ncolumns_;
}

int PerAtomColumnsFix::unpack_exchange(int nlocal, double* buf)
{
  std::memcpy(data_[nlocal], buf, ncolumns_ * sizeof(double));
  ++atoms_received_;
  return ncolumns_;
}

int PerAtomColumnsFix::pack_restart(int i, double* buf)
{
  buf[0] = ncolumns_ + 1;  // values in this record, including this one
  std::memcpy(buf + 1, data_[i], ncolumns_ * sizeof(double));
  return ncolumns_ + 1;
}

void PerAtomColumnsFix::unpack_restart(int nlocal, int nth)
{
  double** extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; ++k) m += static_cast<int>(extra[nlocal][m]);
  std::memcpy(data_[nlocal], &extra[nlocal][m + 1], ncolumns_ * sizeof(double));
}

int PerAtomColumnsFix::size_restart(int) { return ncolumns_ + 1; }

int PerAtomColumnsFix::maxsize_restart() { return ncolumns_ + 1; }

double PerAtomColumnsFix::memory_usage() { return static_cast<double>(atom->nmax) * ncolumns_ * sizeof(double); }

}  // namespace parcelflow::plugins
