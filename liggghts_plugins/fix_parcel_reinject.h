// fix ID group parcel/reinject outlet REGION_ID return REGION_ID velocity vx vy vz [every N] [seed S] [attempts K]
//     [placement random|lowest]
//
// Outlet reinjection (the paper's cyclone emulation, DESIGN section 5). On every step that is a multiple of N
// the parcels of the group whose centre lies in the outlet region are taken out and put back into the return
// region with the same ID, type, groups, radius, mass, density and the columns of every parcelflow per-atom
// fix (fix parcel's dp and np among them), velocity (vx, vy, vz) and no rotation, at a random position where
// the sphere lies inside the return region and overlaps no other atom (periodic images included): the first
// such of K random candidates, or with `placement lowest` the lowest of them (a tall return region then
// fills from the bottom, where a dense bed leaves room, as solids leave a dipleg). A parcel
// without such a position after K candidates stays pending in this fix (out of the simulation, so it
// cannot interact) and is tried again first at the next reinjection step; no parcel is dropped.
//
// Parallel: the leaving parcels and the atoms near the return region (its bounding box padded by the
// contact distance) are gathered on every rank, every rank runs the same seeded placement, and the rank
// that owns a chosen position creates the atom there. The leaving atom is not deleted here: it is moved
// out of the box and LIGGGHTS' atom exchange, which runs right after all pre_exchange hooks, drops it.
// Deleting here would reorder the local atoms before LIGGGHTS' contact-history fix (created at the first
// run, so after this fix) saves the shear history from the neighbour list by local index.
//
// Global vector (f_ID[1..10]): parcels out, mass out, parcels in, mass in at the last reinjection step;
// parcels and mass pending now; cumulative parcels out, mass out, parcels in, mass in. The pending
// parcels and the cumulative counters are written to restart files. Full documentation: README.md.
#pragma once

#include <string>
#include <vector>

#include "fix.h"
#include "liggghts_plugins/reinject_settings.h"
#include "liggghts_plugins/sphere_placer.h"

namespace LAMMPS_NS { class Region; }

namespace parcelflow::plugins {

class FixParcelReinject : public LAMMPS_NS::Fix {
 public:
  enum Entry { OUT_N = 0, OUT_MASS, IN_N, IN_MASS, PENDING_N, PENDING_MASS, TOTAL_OUT_N, TOTAL_OUT_MASS,
               TOTAL_IN_N, TOTAL_IN_MASS, NENTRIES };

  FixParcelReinject(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

  int setmask() override;
  void init() override;
  void pre_exchange() override;
  double compute_vector(int i) override;
  void write_restart(FILE* fp) override;
  void restart(char* buf) override;
  void pre_delete(bool unfixflag) override;

  // The global vector (index Entry), the same on every rank.
  double counter(Entry e) const { return counters_[e]; }
  // IDs of the pending parcels, oldest first (every rank).
  std::vector<long> pending_tags() const;
  // IDs of the parcels put back at the last reinjection step (every rank).
  const std::vector<long>& placed_tags() const { return placed_tags_; }
  const ReinjectSettings& settings() const { return settings_; }

 private:
  struct Columns {  // the per-atom columns of one parcelflow fix, as stored in a record
    std::string fix_id;
    int count;
    bool operator==(const Columns& o) const { return fix_id == o.fix_id && count == o.count; }
  };

  LAMMPS_NS::Region* find_region(const std::string& keyword, const std::string& id);
  std::vector<Columns> current_columns() const;
  std::vector<double> take_leaving();
  std::vector<double> near_return_region(double max_radius) const;
  std::vector<double> gather(const std::vector<double>& local) const;
  void place(std::vector<double> queue);
  void create(const double* record, const Point& x);
  void report_pending();
  [[noreturn]] void fail(const std::string& msg);

  ReinjectSettings settings_;
  LAMMPS_NS::Region* outlet_ = nullptr;
  LAMMPS_NS::Region* return_ = nullptr;
  std::vector<Columns> columns_;  // layout of the records' per-atom columns
  int record_size_ = 0;
  std::vector<double> pending_;   // records of the pending parcels, oldest first (the same on every rank)
  double counters_[NENTRIES] = {};
  std::vector<long> placed_tags_;
  int park_dim_ = 0;              // a periodic or fixed dimension to move leaving atoms out of the box in
  double reported_pending_ = 0.0;
};

}  // namespace parcelflow::plugins
