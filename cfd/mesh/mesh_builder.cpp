#include "cfd/mesh/mesh_builder.hpp"

#include <algorithm>
#include <map>

#include "cfd/mesh/cell_groups.hpp"
#include "cfd/base/config_error.hpp"
#include "cfd/base/internal_error.hpp"
#include "cfd/mesh/partitioner.hpp"
#include "cfd/geometry/surface_from_geometry.hpp"

namespace parcelflow::cfd {

namespace {
const char* kSideNames[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
}  // namespace

Mesh MeshBuilder::build(const MeshSettings& settings, const Geometry& geometry, MPI_Comm comm) {
  Mesh mesh;
  MPI_Comm_dup(comm, &mesh.comm_);
  mesh.commOwner_ = std::shared_ptr<MPI_Comm>(new MPI_Comm(mesh.comm_), [](MPI_Comm* c) {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Comm_free(c);
    delete c;
  });
  comm = mesh.comm_;
  MPI_Comm_rank(comm, &mesh.rank_);
  MPI_Comm_size(comm, &mesh.nRanks_);
  mesh.background_ = CartesianBackground(settings.origin, settings.lengths, settings.cells);
  const auto& bg = mesh.background_;
  const long nBg = bg.size();

  // Cut cells: every rank computes the whole geometry (same input, same result on every rank).
  std::optional<CutCellGeometry> cut;
  if (settings.walls == WallRepresentation::CutCells)
    cut.emplace(surfaceOfGeometry(geometry, bg), bg, "case.yaml: geometry");
  // Fluid selection (cell-centre inside, or any fluid volume for cut cells), small cut cells merged
  // into a neighbour, global numbering of the cells in their masters' background order.
  std::vector<bool> fluid(nBg);
  for (long b = 0; b < nBg; ++b) {
    const auto ijk = bg.ijk(b);
    fluid[b] = cut ? cut->fluidFraction(b) > 0.0 : geometry.isFluid(bg.centre(ijk[0], ijk[1], ijk[2]));
  }
  const CellGroups groups = groupCells(bg, fluid, cut ? &*cut : nullptr, settings.smallCellFraction);
  const auto& globalOfBackground = groups.globalOfBackground;
  const int nGlobal = static_cast<int>(groups.backgroundOfGlobal.size());
  if (nGlobal == 0) throw ConfigError("case.yaml: geometry: selects no fluid cell of the mesh");
  mesh.nGlobal_ = nGlobal;
  mesh.mergedCells_ = groups.mergedCells;
  mesh.unmergedSmallCells_ = groups.unmergedSmallCells;

  // Face graph and weights for METIS: a merged cell's neighbours are its members' (each once).
  std::vector<int> xadj{0}, adjncy, weights(nGlobal, 1);
  for (int g = 0; g < nGlobal; ++g) {
    std::vector<int> neighbours;
    for (long member : groups.members[g]) {
      const auto ijk = bg.ijk(member);
      for (int d = 0; d < 3; ++d)
        for (int s = -1; s <= 1; s += 2) {
          auto n = ijk;
          n[d] += s;
          if (!bg.inside(n[0], n[1], n[2])) continue;
          const int ng = globalOfBackground[bg.index(n[0], n[1], n[2])];
          // In the order found, so that meshes without merged cells get the same partition as before.
          if (ng >= 0 && ng != g && std::find(neighbours.begin(), neighbours.end(), ng) == neighbours.end())
            neighbours.push_back(ng);
        }
    }
    adjncy.insert(adjncy.end(), neighbours.begin(), neighbours.end());
    xadj.push_back(static_cast<int>(adjncy.size()));
    const auto ijk = bg.ijk(groups.backgroundOfGlobal[g]);
    const Vec3 x = bg.centre(ijk[0], ijk[1], ijk[2]);
    for (const auto& w : settings.partitionWeights)
      if (w.region.contains(x)) weights[g] = w.weight;
  }
  // Global fluid-cell id -> owner rank.
  const std::vector<int> part = Partitioner::partition(comm, xadj, adjncy, weights);

  for (int g = 0; g < nGlobal; ++g)
    if (part[g] == mesh.rank_) mesh.globalId_.push_back(g);
  mesh.nOwned_ = static_cast<int>(mesh.globalId_.size());
  const double haveCells = mesh.nOwned_ > 0 ? 1.0 : 0.0;
  double allHave = 0.0;
  MPI_Allreduce(&haveCells, &allHave, 1, MPI_DOUBLE, MPI_MIN, comm);
  if (allHave < 1.0) throw ConfigError("the partition left an MPI rank without cells: use fewer ranks");

  addGhostLayers(mesh, groups, settings.ghostLayers);
  const FluidRegions regions = fluidRegions(bg, groups, cut ? &*cut : nullptr);
  mesh.fluidRegionCells_ = regions.cells;
  for (long g : regions.firstGlobal) {
    const auto ijk = bg.ijk(groups.backgroundOfGlobal[g]);
    mesh.fluidRegionPoint_.push_back(bg.centre(ijk[0], ijk[1], ijk[2]));
  }
  mesh.backgroundToLocal_.assign(nBg, -1);
  for (int c = 0; c < mesh.nLocalCells(); ++c) {
    mesh.fluidRegion_.push_back(regions.ofGlobal[mesh.globalId_[c]]);
    const auto& members = groups.members[mesh.globalId_[c]];
    for (long member : members) {
      mesh.backgroundToLocal_[member] = c;
      mesh.memberBackground_.push_back(member);
      mesh.memberFraction_.push_back(cut ? cut->fluidFraction(member) : 1.0);
    }
    mesh.memberStart_.push_back(static_cast<int>(mesh.memberBackground_.size()));
    const long b = members.front();
    mesh.backgroundIndex_.push_back(b);
    const auto ijk = bg.ijk(b);
    // A cut cell's centre is its fluid centroid (of all its members when merged): the boundary terms
    // that use boundary centre - cell centre (pressure extrapolation, wall distance) then stay within
    // the fluid and the cell.
    if (!cut) {
      mesh.cellCentre_.push_back(bg.centre(ijk[0], ijk[1], ijk[2]));
      mesh.cellVolume_.push_back(bg.cellVolume());
    } else if (members.size() == 1) {  // exactly the geometry's centroid (v c / v is not c to the last bit)
      mesh.cellCentre_.push_back(cut->fluidCentroid(b));
      mesh.cellVolume_.push_back(bg.cellVolume() * cut->fluidFraction(b));
    } else {
      double volume = 0.0;
      Vec3 moment = Vec3::Zero();
      for (long member : members) {
        const double v = bg.cellVolume() * cut->fluidFraction(member);
        volume += v;
        moment += v * cut->fluidCentroid(member);
      }
      mesh.cellCentre_.push_back(moment / volume);
      mesh.cellVolume_.push_back(volume);
    }
  }
  buildHalo(mesh, part);
  buildFaces(mesh, geometry, cut, groups);
  addFaceCorrections(mesh);
  return mesh;
}

// Each internal face's non-orthogonality, from the finished faces and centres (ghosts included).
void MeshBuilder::addFaceCorrections(Mesh& mesh) {
  for (int f = 0; f < mesh.nInternalFaces(); ++f) {
    const Vec3 n = mesh.faceArea(f) / mesh.faceMagArea(f);
    const Vec3 d = mesh.cellCentre(mesh.faceNeighbour(f)) - mesh.cellCentre(mesh.faceOwner(f));
    const Vec3 offset = n - d / d.dot(n);
    if (offset.isZero(0.0)) continue;
    mesh.nonOrthogonalFaces_.push_back(f);
    mesh.nonOrthogonality_.push_back(offset);
  }
}

void MeshBuilder::addGhostLayers(Mesh& mesh, const CellGroups& groups, int layers) {
  const auto& bg = mesh.background_;
  std::vector<char> present(groups.backgroundOfGlobal.size(), 0);
  for (long g : mesh.globalId_) present[g] = 1;
  int begin = 0;
  for (int layer = 1; layer <= layers; ++layer) {
    const int end = mesh.nLocalCells();
    std::vector<int> added;  // global ids of the new layer
    for (int c = begin; c < end; ++c)
      for (long member : groups.members[mesh.globalId_[c]]) {
        const auto ijk = bg.ijk(member);
        for (int dk = -1; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
              const int i = ijk[0] + di, j = ijk[1] + dj, k = ijk[2] + dk;
              if (!bg.inside(i, j, k)) continue;
              const int g = groups.globalOfBackground[bg.index(i, j, k)];
              if (g < 0 || present[g]) continue;  // solid, or present already
              present[g] = 1;
              added.push_back(g);
            }
      }
    std::sort(added.begin(), added.end());
    mesh.globalId_.insert(mesh.globalId_.end(), added.begin(), added.end());
    begin = end;
  }
}

void MeshBuilder::buildHalo(Mesh& mesh, const std::vector<int>& part) {
  // Each rank asks the owners of its ghosts for them, in its ghost order.
  std::map<int, std::vector<int>> recvByRank;  // owner rank -> local ghost cells
  for (int c = mesh.nOwned_; c < mesh.nLocalCells(); ++c)
    recvByRank[part[mesh.globalId_[c]]].push_back(c);
  const int nRanks = mesh.nRanks_;
  std::vector<int> requestCount(nRanks, 0), incomingCount(nRanks, 0);
  for (const auto& [r, cells] : recvByRank) requestCount[r] = static_cast<int>(cells.size());
  MPI_Alltoall(requestCount.data(), 1, MPI_INT, incomingCount.data(), 1, MPI_INT, mesh.comm_);
  std::vector<int> sendDispl(nRanks + 1, 0), recvDispl(nRanks + 1, 0);
  for (int r = 0; r < nRanks; ++r) {
    sendDispl[r + 1] = sendDispl[r] + requestCount[r];
    recvDispl[r + 1] = recvDispl[r] + incomingCount[r];
  }
  std::vector<int> requested(sendDispl[nRanks]), incoming(recvDispl[nRanks]);
  for (const auto& [r, cells] : recvByRank)
    for (std::size_t i = 0; i < cells.size(); ++i)
      requested[sendDispl[r] + i] = static_cast<int>(mesh.globalId_[cells[i]]);
  MPI_Alltoallv(requested.data(), requestCount.data(), sendDispl.data(), MPI_INT, incoming.data(),
                incomingCount.data(), recvDispl.data(), MPI_INT, mesh.comm_);
  std::vector<Halo::Neighbour> neighbours;
  for (int r = 0; r < nRanks; ++r) {
    if (requestCount[r] == 0 && incomingCount[r] == 0) continue;
    Halo::Neighbour nb;
    nb.rank = r;
    if (recvByRank.count(r)) nb.recv = recvByRank[r];
    for (int i = recvDispl[r]; i < recvDispl[r + 1]; ++i) {
      // Owned global ids are sorted, so a binary search finds the local index.
      const auto begin = mesh.globalId_.begin(), end = begin + mesh.nOwned_;
      const auto it = std::lower_bound(begin, end, static_cast<long>(incoming[i]));
      const int local = (it != end && *it == incoming[i]) ? static_cast<int>(it - begin) : -1;
      PARCELFLOW_ASSERT(local >= 0 && local < mesh.nOwned_, "halo request for a cell not owned");
      nb.send.push_back(local);
    }
    neighbours.push_back(std::move(nb));
  }
  mesh.halo_ = Halo(mesh.comm_, mesh.nLocalCells(), std::move(neighbours));
}

void MeshBuilder::buildFaces(Mesh& mesh, const Geometry& geometry, const std::optional<CutCellGeometry>& cut,
                             const CellGroups& groups) {
  const auto& bg = mesh.background_;
  const Vec3 h = bg.spacing();
  // Patch list, identical on every rank: box sides, the default wall patch, named cut-outs.
  std::vector<std::string>& names = mesh.patchNames_;
  for (int d = 0; d < 3; ++d)
    for (int s = 0; s < 2; ++s) names.push_back(kSideNames[d][s]);
  names.push_back(Geometry::defaultWallPatch);
  for (const auto& item : geometry.items())
    if (!item.patch.empty() && std::find(names.begin(), names.end(), item.patch) == names.end())
      names.push_back(item.patch);
  std::vector<long> localCount(names.size(), 0);

  for (int c = 0; c < mesh.nOwned_; ++c)
    for (long b : groups.members[mesh.globalId_[c]]) {
      const auto ijk = bg.ijk(b);
      if (cut && cut->isCut(b)) addCutCellWall(mesh, geometry, c, cut->wall(b), localCount);
      for (int d = 0; d < 3; ++d) {
        Vec3 e = Vec3::Zero();
        e[d] = 1.0;
        for (int s = -1; s <= 1; s += 2) {
          // Open area of the face; a closed face of a cut cell is wall already counted in its wall face.
          const auto cellFace = static_cast<CellFace>(2 * d + (s > 0 ? 1 : 0));
          const double open = cut ? cut->openFraction(b, cellFace) : 1.0;
          if (open <= 0.0) continue;
          const double area = open * h.prod() / h[d];
          auto n = ijk;
          n[d] += s;
          const Vec3 faceCentre =
              cut ? cut->openCentroid(b, cellFace) : Vec3(mesh.cellCentre_[c] + 0.5 * s * h[d] * e);
          std::string patch;
          if (!bg.inside(n[0], n[1], n[2])) {
            patch = kSideNames[d][s > 0 ? 1 : 0];
          } else {
            const int nb = mesh.localCellOfBackground(n[0], n[1], n[2]);
            if (nb == c) continue;  // between two members of a merged cell
            if (nb < 0) {
              patch = geometry.wallPatchAt(bg.centre(n[0], n[1], n[2]));
            } else {
              // Owned pairs are added once, from the -d side; faces to ghosts from the owned side.
              if (s < 0 && nb < mesh.nOwned_) continue;
              addInternalFace(mesh, s > 0 ? c : nb, s > 0 ? nb : c, d, area, faceCentre, cut.has_value());
              continue;
            }
          }
          addBoundaryFace(mesh, c, s * area * e, area, faceCentre,
                          cut ? std::abs(faceCentre[d] - mesh.cellCentre_[c][d]) : 0.5 * h[d], patch, localCount);
        }
      }
    }
  mesh.patchGlobalFaces_.assign(names.size(), 0);
  MPI_Allreduce(localCount.data(), mesh.patchGlobalFaces_.data(), static_cast<int>(names.size()),
                MPI_LONG, MPI_SUM, mesh.comm_);
}

// A face normal to axis d between the cells `low` (on its -d side) and `high`. The owner is the cell of
// the lower global id (both ranks sharing a face orient it alike); the area vector points from it to
// the neighbour. Without merged cells that is always `low`.
void MeshBuilder::addInternalFace(Mesh& mesh, int low, int high, int d, double area, const Vec3& faceCentre,
                                  bool cutCells) {
  const bool lowOwns = mesh.globalId_[low] < mesh.globalId_[high];
  Vec3 areaVector = Vec3::Zero();
  areaVector[d] = lowOwns ? area : -area;
  mesh.faceOwner_.push_back(lowOwns ? low : high);
  mesh.faceNeighbour_.push_back(lowOwns ? high : low);
  mesh.faceArea_.push_back(areaVector);
  mesh.faceAxis_.push_back(static_cast<std::int8_t>(d));
  mesh.faceMagArea_.push_back(area);
  mesh.faceCentre_.push_back(faceCentre);
  if (!cutCells) {
    mesh.faceWeight_.push_back(0.5);
    mesh.faceDelta_.push_back(mesh.background_.spacing()[d]);
    return;
  }
  // The normal gradient and the interpolation use the centroids' distances along d; the solver
  // corrects for their offset along the face (non-orthogonality).
  const double xl = mesh.cellCentre_[low][d], xh = mesh.cellCentre_[high][d];
  PARCELFLOW_ASSERT(xh > xl, "a fluid centroid is not on its side of a face");
  const double lowWeight = (xh - faceCentre[d]) / (xh - xl);
  mesh.faceWeight_.push_back(lowOwns ? lowWeight : 1.0 - lowWeight);
  mesh.faceDelta_.push_back(xh - xl);
}

// The wall of a cut cell is one boundary face: its area vector closes the cell, its delta is the normal
// distance of the cell centre from the wall plane (the wall stress uses it as the wall distance).
// The patch is the one of the solid just beyond the wall centroid, as for staircase walls.
void MeshBuilder::addCutCellWall(Mesh& mesh, const Geometry& geometry, int cell, const CutCellWall& wall,
                                 std::vector<long>& localCount) {
  const double magArea = wall.areaVector.norm();
  if (magArea <= 0.0) return;  // the box only touches the surface
  const Vec3 normal = wall.areaVector / magArea;
  const double h = mesh.background_.spacing().minCoeff();
  // The cell centre is the fluid centroid: on the fluid side of a plane wall and of the mean wall plane
  // of a convex fluid piece. Where wall pieces facing different ways leave the fluid concave (around a
  // baffle's edge) it can lie on or beyond that plane; the distance to the wall centroid stands in there.
  const Vec3 toWall = wall.centroid - mesh.cellCentre_[cell];
  double distance = toWall.dot(normal);
  if (!(distance > 0.0)) distance = toWall.norm();
  PARCELFLOW_ASSERT(distance > 0.0, "a cut cell's fluid centroid lies on its wall centroid");
  addBoundaryFace(mesh, cell, wall.areaVector, magArea, wall.centroid, distance,
                  geometry.wallPatchAt(wall.centroid + 1e-6 * h * normal), localCount);
}

void MeshBuilder::addBoundaryFace(Mesh& mesh, int cell, const Vec3& area, double magArea, const Vec3& centre,
                                  double delta, const std::string& patch, std::vector<long>& localCount) {
  const auto& names = mesh.patchNames_;
  const int pid = static_cast<int>(std::find(names.begin(), names.end(), patch) - names.begin());
  PARCELFLOW_ASSERT(pid < static_cast<int>(names.size()), "unknown patch " + patch);
  mesh.boundaryCell_.push_back(cell);
  mesh.boundaryArea_.push_back(area);
  mesh.boundaryMagArea_.push_back(magArea);
  mesh.boundaryCentre_.push_back(centre);
  mesh.boundaryDelta_.push_back(delta);
  mesh.boundaryPatch_.push_back(pid);
  ++localCount[pid];
}

}  // namespace parcelflow::cfd
