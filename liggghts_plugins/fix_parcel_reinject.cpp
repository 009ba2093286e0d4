#include "liggghts_plugins/fix_parcel_reinject.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "liggghts_plugins/fix_support.h"
#include "modify.h"
#include "liggghts_plugins/parcel_settings.h"
#include "liggghts_plugins/per_atom_columns_fix.h"
#include "region.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace LAMMPS_NS::FixConst;

namespace parcelflow::plugins {
namespace {

// a parcel record: these values, then the per-atom columns of the parcelflow fixes
enum Field { TAG = 0, TYPE, MASK, RADIUS, RMASS, DENSITY, NFIELDS };
constexpr int kRestartVersion = 1;

}  // namespace

FixParcelReinject::FixParcelReinject(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg)
{
  try {
    settings_ = parse_reinject_settings(style_arguments(narg, arg));
  } catch (const ArgumentError& e) {
    fail(e.what());
  }
  find_region("outlet", settings_.outlet);
  find_region("return", settings_.return_region);
  if (!atom->sphere_flag || !atom->rmass_flag)
    fail("fix parcel/reinject: needs spheres with per-atom mass (atom_style granular)");
  if (!atom->tag_enable) fail("fix parcel/reinject: needs atom IDs (atom_modify id yes)");
  force_reneighbor = 1;  // atoms are moved far: every reinjection step rebuilds the neighbour lists
  next_reneighbor = -1;
  restart_global = 1;
  vector_flag = 1;
  size_vector = NENTRIES;
  global_freq = 1;
  extvector = 1;
}

void FixParcelReinject::fail(const std::string& msg)
{
  error->all(FLERR, msg.c_str());
  throw ArgumentError(msg);  // not reached: error->all ends the program
}

int FixParcelReinject::setmask() { return PRE_EXCHANGE; }

Region* FixParcelReinject::find_region(const std::string& keyword, const std::string& id)
{
  const int i = domain->find_region(id.c_str());
  if (i < 0)
    fail("fix parcel/reinject: keyword '" + keyword + "' got '" + id +
         "': no region with this ID; allowed: the ID of a region defined before the fix");
  return domain->regions[i];
}

std::vector<FixParcelReinject::Columns> FixParcelReinject::current_columns() const
{
  std::vector<Columns> layout;
  for (int k = 0; k < modify->nfix; ++k)
    if (auto* f = dynamic_cast<PerAtomColumnsFix*>(modify->fix[k])) layout.push_back({f->id, f->ncolumns()});
  return layout;
}

void FixParcelReinject::init()
{
  outlet_ = find_region("outlet", settings_.outlet);
  return_ = find_region("return", settings_.return_region);
  if (!return_->bboxflag || return_->bbox_extends_outside_box())
    fail("fix parcel/reinject: keyword 'return' got '" + settings_.return_region +
         "', a region without a bounding box inside the simulation box; allowed: a bounded region inside the box");
  if (domain->triclinic) fail("fix parcel/reinject: needs an orthogonal simulation box");
  park_dim_ = -1;
  for (int d = 2; d >= 0; --d)
    if (domain->boundary[d][0] <= 1 && domain->boundary[d][1] <= 1) park_dim_ = d;
  if (park_dim_ < 0)
    fail("fix parcel/reinject: needs one dimension with a periodic or fixed boundary (p or f), not all shrink-wrapped");
  const std::vector<Columns> now = current_columns();
  if (!pending_.empty() && !(now == columns_)) {
    std::ostringstream msg;
    msg << "fix " << id << " parcel/reinject: the restart file holds " << pending_.size() / record_size_
        << " pending parcels with the per-atom columns of fixes";
    for (const Columns& c : columns_) msg << " " << c.fix_id << " (" << c.count << ")";
    msg << "; define the same parcelflow fixes (same IDs) before the first run";
    fail(msg.str());
  }
  columns_ = now;
  record_size_ = NFIELDS;
  for (const Columns& c : columns_) record_size_ += c.count;
  next_reneighbor = (update->ntimestep / settings_.every + 1) * settings_.every;
}

// ------------------------------------------------------------------ one reinjection step

void FixParcelReinject::pre_exchange()
{
  if (update->ntimestep != next_reneighbor) return;
  next_reneighbor += settings_.every;
  outlet_->prematch();
  return_->prematch();

  std::vector<double> leaving = gather(take_leaving());
  const std::size_t n = leaving.size() / record_size_;
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return leaving[a * record_size_ + TAG] < leaving[b * record_size_ + TAG]; });
  std::vector<double> queue = pending_;  // pending parcels first, then today's by ID
  counters_[OUT_N] = static_cast<double>(n);
  counters_[OUT_MASS] = 0.0;
  for (std::size_t k : order) {
    const double* r = &leaving[k * record_size_];
    queue.insert(queue.end(), r, r + record_size_);
    counters_[OUT_MASS] += r[RMASS];
  }
  counters_[TOTAL_OUT_N] += counters_[OUT_N];
  counters_[TOTAL_OUT_MASS] += counters_[OUT_MASS];
  place(std::move(queue));
  report_pending();
}

// Records of the local parcels in the outlet; the atoms are moved out of the box (see the header).
std::vector<double> FixParcelReinject::take_leaving()
{
  std::vector<double> records;
  std::vector<PerAtomColumnsFix*> fixes;
  for (const Columns& c : columns_)
    fixes.push_back(dynamic_cast<PerAtomColumnsFix*>(modify->fix[modify->find_fix(c.fix_id.c_str())]));
  double** x = atom->x;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit) || !outlet_->match(x[i])) continue;
    const double fields[NFIELDS] = {double(atom->tag[i]), double(atom->type[i]), double(atom->mask[i]),
                                    atom->radius[i],      atom->rmass[i],        atom->density[i]};
    records.insert(records.end(), fields, fields + NFIELDS);
    for (PerAtomColumnsFix* f : fixes) records.insert(records.end(), f->peratom()[i], f->peratom()[i] + f->ncolumns());
    x[i][park_dim_] = domain->boxhi[park_dim_] + 4.0 * domain->prd[park_dim_];
    for (int k = 0; k < 3; ++k) atom->v[i][k] = 0.0;
  }
  return records;
}

// x, y, z, r of the local atoms (and periodic images) whose sphere may touch a sphere of radius up to
// max_radius centred in the return region's bounding box
std::vector<double> FixParcelReinject::near_return_region(double max_radius) const
{
  const double lo[3] = {return_->extent_xlo, return_->extent_ylo, return_->extent_zlo};
  const double hi[3] = {return_->extent_xhi, return_->extent_yhi, return_->extent_zhi};
  const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  std::vector<double> out;
  for (int i = 0; i < atom->nlocal; ++i) {
    const double pad = max_radius + atom->radius[i];
    for (int sx = -periodic[0]; sx <= periodic[0]; ++sx)
      for (int sy = -periodic[1]; sy <= periodic[1]; ++sy)
        for (int sz = -periodic[2]; sz <= periodic[2]; ++sz) {
          const int s[3] = {sx, sy, sz};
          double p[3];
          bool near = true;
          for (int k = 0; k < 3; ++k) {
            p[k] = atom->x[i][k] + s[k] * domain->prd[k];
            near = near && p[k] >= lo[k] - pad && p[k] <= hi[k] + pad;
          }
          if (!near) continue;
          out.insert(out.end(), p, p + 3);
          out.push_back(atom->radius[i]);
        }
  }
  return out;
}

std::vector<double> FixParcelReinject::gather(const std::vector<double>& local) const
{
  const int n = static_cast<int>(local.size());
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int p = 1; p < comm->nprocs; ++p) displs[p] = displs[p - 1] + counts[p - 1];
  std::vector<double> all(displs.back() + counts.back());
  MPI_Allgatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, world);
  return all;
}

// The same placement on every rank (same records, obstacles and random numbers); the owner of a position
// creates the atom. Records without a position become the new pending list, in queue order.
void FixParcelReinject::place(std::vector<double> queue)
{
  placed_tags_.clear();
  counters_[IN_N] = counters_[IN_MASS] = 0.0;
  pending_.clear();
  const std::size_t n = queue.size() / record_size_;
  if (n > 0) {
    double max_radius = 0.0;
    for (std::size_t k = 0; k < n; ++k) max_radius = std::max(max_radius, queue[k * record_size_ + RADIUS]);
    const std::vector<double> near = gather(near_return_region(max_radius));
    double cell = 2.0 * max_radius;
    for (std::size_t j = 3; j < near.size(); j += 4) cell = std::max(cell, 2.0 * near[j]);
    const Point lo = {return_->extent_xlo, return_->extent_ylo, return_->extent_zlo};
    const Point hi = {return_->extent_xhi, return_->extent_yhi, return_->extent_zhi};
    Region* region = return_;
    SpherePlacer placer(lo, hi, cell, [region](const Point& c, double r) {
      Point p = c;
      return region->match_shrinkby_cut(p.data(), r) != 0;
    }, settings_.seed, static_cast<std::uint64_t>(update->ntimestep));
    for (std::size_t j = 0; j < near.size(); j += 4) placer.add({near[j], near[j + 1], near[j + 2]}, near[j + 3]);
    long created = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double* r = &queue[k * record_size_];
      Point x;
      const bool placed = settings_.lowest ? placer.place_lowest(r[RADIUS], settings_.attempts, x)
                                           : placer.place(r[RADIUS], settings_.attempts, x);
      if (!placed) {
        pending_.insert(pending_.end(), r, r + record_size_);
        continue;
      }
      placed_tags_.push_back(static_cast<long>(r[TAG]));
      counters_[IN_N] += 1.0;
      counters_[IN_MASS] += r[RMASS];
      bool mine = true;
      for (int d = 0; d < 3; ++d) mine = mine && x[d] >= domain->sublo[d] && x[d] < domain->subhi[d];
      if (mine) {
        create(r, x);
        ++created;
      }
    }
    long all_created = 0;
    MPI_Allreduce(&created, &all_created, 1, MPI_LONG, MPI_SUM, world);
    if (all_created != static_cast<long>(placed_tags_.size()))
      error->all(FLERR, "fix parcel/reinject: internal error: a placed parcel has no owning rank");
    // LIGGGHTS' atom map was sized at its last map_init: for the atoms then present (map_array up to their
    // largest ID, which a pending parcel may exceed) plus 1000 spare entries of `sametag`, which the map_clear
    // at the start of the coming exchange writes for every local atom. A burst of new atoms overran it
    // (heap corruption, measured with 67,500 parcels), so re-size it as fix insert does after inserting.
    if (all_created > 0 && atom->map_style) {
      atom->nghost = 0;
      atom->map_init();
      atom->map_set();
    }
  }
  counters_[TOTAL_IN_N] += counters_[IN_N];
  counters_[TOTAL_IN_MASS] += counters_[IN_MASS];
  counters_[PENDING_N] = static_cast<double>(pending_.size() / record_size_);
  counters_[PENDING_MASS] = 0.0;
  for (std::size_t k = 0; k < pending_.size(); k += record_size_) counters_[PENDING_MASS] += pending_[k + RMASS];
}

void FixParcelReinject::create(const double* record, const Point& x)
{
  double pos[3] = {x[0], x[1], x[2]};
  atom->avec->create_atom(static_cast<int>(record[TYPE]), pos);
  const int m = atom->nlocal - 1;
  atom->tag[m] = static_cast<tagint>(record[TAG]);
  atom->mask[m] = static_cast<int>(record[MASK]);
  atom->radius[m] = record[RADIUS];
  atom->rmass[m] = record[RMASS];
  atom->density[m] = record[DENSITY];
  for (int k = 0; k < 3; ++k) {
    atom->v[m][k] = settings_.velocity[k];
    atom->omega[m][k] = 0.0;
  }
  for (int k = 0; k < modify->nfix; ++k)  // contact histories etc. start fresh, as for an inserted atom
    if (modify->fix[k]->create_attribute) modify->fix[k]->set_arrays(m);
  const double* column = record + NFIELDS;
  for (const Columns& c : columns_) {
    auto* f = dynamic_cast<PerAtomColumnsFix*>(modify->fix[modify->find_fix(c.fix_id.c_str())]);
    std::copy(column, column + c.count, f->peratom()[m]);
    column += c.count;
  }
}

void FixParcelReinject::report_pending()
{
  const double n = counters_[PENDING_N];
  if (n == reported_pending_) return;
  reported_pending_ = n;
  if (comm->me != 0) return;
  char msg[512];
  if (n > 0)
    std::snprintf(msg, sizeof msg,
                  "fix %s parcel/reinject: step " BIGINT_FORMAT ": %.0f parcels (mass %.6g) pending: no free "
                  "position in region %s within %d attempts each; retried every %ld steps",
                  id, update->ntimestep, n, counters_[PENDING_MASS], settings_.return_region.c_str(),
                  settings_.attempts, settings_.every);
  else
    std::snprintf(msg, sizeof msg, "fix %s parcel/reinject: step " BIGINT_FORMAT ": all pending parcels put back",
                  id, update->ntimestep);
  error->warning(FLERR, msg);
}

// ------------------------------------------------------------------ output, restart, unfix

double FixParcelReinject::compute_vector(int i) { return counters_[i]; }

std::vector<long> FixParcelReinject::pending_tags() const
{
  std::vector<long> tags;
  for (std::size_t k = 0; k < pending_.size(); k += record_size_) tags.push_back(static_cast<long>(pending_[k + TAG]));
  return tags;
}

// version, cumulative counters, column layout (fix ID as characters, count), record size, pending records
void FixParcelReinject::write_restart(FILE* fp)
{
  std::vector<double> list = {double(kRestartVersion), counters_[TOTAL_OUT_N], counters_[TOTAL_OUT_MASS],
                              counters_[TOTAL_IN_N], counters_[TOTAL_IN_MASS], double(columns_.size())};
  for (const Columns& c : columns_) {
    list.push_back(double(c.fix_id.size()));
    for (char ch : c.fix_id) list.push_back(double(ch));
    list.push_back(double(c.count));
  }
  list.push_back(double(record_size_));
  list.push_back(double(pending_.size()));
  list.insert(list.end(), pending_.begin(), pending_.end());
  write_global_state(comm->me, fp, list);
}

void FixParcelReinject::restart(char* buf)
{
  const double* list = reinterpret_cast<const double*>(buf);
  if (static_cast<int>(list[0]) != kRestartVersion)
    fail("fix parcel/reinject: the restart file holds an unknown version of this fix's state");
  std::size_t n = 1;
  for (Entry e : {TOTAL_OUT_N, TOTAL_OUT_MASS, TOTAL_IN_N, TOTAL_IN_MASS}) counters_[e] = list[n++];
  columns_.resize(static_cast<std::size_t>(list[n++]));
  for (Columns& c : columns_) {
    c.fix_id.resize(static_cast<std::size_t>(list[n++]));
    for (char& ch : c.fix_id) ch = static_cast<char>(list[n++]);
    c.count = static_cast<int>(list[n++]);
  }
  record_size_ = static_cast<int>(list[n++]);
  const std::size_t values = static_cast<std::size_t>(list[n++]);
  pending_.assign(list + n, list + n + values);
  counters_[PENDING_N] = static_cast<double>(values / record_size_);
  for (std::size_t k = 0; k < values; k += record_size_) counters_[PENDING_MASS] += pending_[k + RMASS];
  reported_pending_ = counters_[PENDING_N];
}

void FixParcelReinject::pre_delete(bool unfixflag)
{
  if (unfixflag && !pending_.empty() && comm->me == 0) {
    char msg[256];
    std::snprintf(msg, sizeof msg, "fix %s parcel/reinject: unfix drops %zu pending parcels (mass %.6g)", id,
                  pending_.size() / record_size_, counters_[PENDING_MASS]);
    error->warning(FLERR, msg);
  }
}

}  // namespace parcelflow::plugins
