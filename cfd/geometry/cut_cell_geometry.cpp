#include "cfd/geometry/cut_cell_geometry.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Side_of_triangle_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "cfd/base/config_error.hpp"
#include "cfd/geometry/cut_cell_polyhedron.hpp"
#include "cfd/base/internal_error.hpp"

namespace parcelflow::cfd {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

using AabbPrimitive = CGAL::AABB_face_graph_triangle_primitive<cgal::Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<cgal::Kernel, AabbPrimitive>>;

// Surface points on a grid plane (within kOnGridPlane) are moved onto it: a cap meant to lie on a plane must not
// leave cells with 1e-16 of fluid or a 1e-16 m solid layer.
TriangleSurface snappedToGridPlanes(TriangleSurface s, const CartesianBackground& b) {
  for (auto& p : s.points)
    for (int d = 0; d < 3; ++d) {
      const auto nearest = b.nearestPlane(d, p[d]);
      if (nearest.offSpacings < kOnGridPlane) p[d] = b.planeCoordinate(d, nearest.plane);
    }
  return s;
}

// fluid ∩ box as a closed mesh (empty when they only touch).
cgal::Mesh clippedToBox(const cgal::Mesh& fluid, const Vec3& lo, const Vec3& hi, const std::string& what) {
  cgal::Mesh piece = fluid;
  cgal::Mesh box = cgal::boxMesh(lo, hi);
  const bool manifold = PMP::clip(piece, box, CGAL::parameters::clip_volume(true));
  PARCELFLOW_ASSERT(manifold, "clipping the fluid surface by " + what + " gave a non-manifold piece");
  return piece;
}

}  // namespace

// Fills a CutCellGeometry: classification, the clip of every cut cell, and the per-face reconciliation.
class CutCellBuilder {
 public:
  CutCellBuilder(CutCellGeometry& g, const TriangleSurface& surface, const std::string& source)
      : g_(g), b_(g.background_), surface_(snappedToGridPlanes(surface, b_)), coplanar_(surface_, b_),
        source_(source) {}

  void build() {
    const auto start = std::chrono::steady_clock::now();
    const cgal::Mesh fluid = cgal::toMesh(surface_);
    const std::vector<bool> cut = classify(fluid);
    // Each cut cell is clipped from the whole (valid) fluid mesh. Clipping a row's or a layer's piece
    // instead would touch fewer triangles, but the pieces carry rounded intersection points that can
    // make them slightly self-intersecting, and CGAL's corefinement then looped forever (measured on
    // the tessellated cylinder): correctness first.
    for (long c = 0; c < b_.size(); ++c)
      if (cut[c]) {
        const auto ijk = b_.ijk(c);
        measure(fluid, ijk[0], ijk[1], ijk[2]);
      }
    reconcileFaces(cut);
    auto& st = g_.statistics_;
    for (long c = 0; c < b_.size(); ++c) st.fluidVolume += g_.fluidFraction_[c] * b_.cellVolume();
    if (!(st.fluidVolume > 0))
      throw ConfigError(source_, "a surface enclosing " + std::to_string(surface_.volume()) + " m3",
                        "a fluid surface that leaves fluid in at least one cell of the mesh box (mesh.origin, "
                        "mesh.lengths)");
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

 private:
  std::pair<Vec3, Vec3> box(int i, int j, int k, int ni, int nj, int nk) const {
    const Vec3 lo(b_.planeCoordinate(0, i), b_.planeCoordinate(1, j), b_.planeCoordinate(2, k));
    const Vec3 hi(b_.planeCoordinate(0, i + ni), b_.planeCoordinate(1, j + nj), b_.planeCoordinate(2, k + nk));
    return {lo, hi};
  }

  // Cells whose closed box meets the surface are cut (the box touching it counts, so that degenerate
  // contacts go through the exact clip); the others are fluid or solid as their centre.
  std::vector<bool> classify(const cgal::Mesh& fluid) {
    Tree tree(faces(fluid).first, faces(fluid).second, fluid);
    tree.accelerate_distance_queries();
    CGAL::Side_of_triangle_mesh<cgal::Mesh, cgal::Kernel> inside(fluid);
    std::vector<bool> cut(b_.size(), false);
    auto& st = g_.statistics_;
    for (int k = 0; k < b_.n()[2]; ++k)
      for (int j = 0; j < b_.n()[1]; ++j)
        for (int i = 0; i < b_.n()[0]; ++i) {
          const long c = b_.index(i, j, k);
          const auto [lo, hi] = box(i, j, k, 1, 1, 1);
          if (tree.do_intersect(cgal::Kernel::Iso_cuboid_3(cgal::toPoint(lo), cgal::toPoint(hi)))) {
            cut[c] = true;
            ++st.cutCells;
          } else if (inside(cgal::toPoint(b_.centre(i, j, k))) == CGAL::ON_BOUNDED_SIDE) {
            g_.fluidFraction_[c] = 1.0;
            ++st.fluidCells;
          } else {
            ++st.solidCells;
          }
        }
    return cut;
  }

  void measure(const cgal::Mesh& fluid, int i, int j, int k) {
    const auto [lo, hi] = box(i, j, k, 1, 1, 1);
    const std::string where = "cell (" + std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) + ")";
    const cgal::Mesh piece = clippedToBox(fluid, lo, hi, where);
    std::array<bool, 6> onBoundary{};
    const std::array<int, 3> ijk = {i, j, k};
    for (int f = 0; f < 6; ++f) onBoundary[f] = f % 2 ? ijk[f / 2] == b_.n()[f / 2] - 1 : ijk[f / 2] == 0;
    const CutCellMeasure m = measureCutCell(piece, lo, hi, ijk, onBoundary, coplanar_);

    const long c = b_.index(i, j, k);
    const double volume = b_.cellVolume();
    PARCELFLOW_ASSERT(m.volume > -1e-12 * volume && m.volume < (1 + 1e-12) * volume,
                      where + ": clipped fluid volume outside [0, cell volume]");
    g_.fluidFraction_[c] = std::clamp(m.volume / volume, 0.0, 1.0);
    g_.wallIndex_[c] = static_cast<int>(g_.walls_.size());
    g_.walls_.push_back(m.wall);
    g_.centroids_.push_back(m.centroid);
    auto& st = g_.statistics_;
    st.wallArea += m.wall.area;
    const double largestFace = std::max({b_.spacing()[0] * b_.spacing()[1], b_.spacing()[1] * b_.spacing()[2],
                                         b_.spacing()[0] * b_.spacing()[2]});
    st.maxClosureError = std::max(st.maxClosureError, m.closureError / largestFace);
    PARCELFLOW_ASSERT(m.closureError < 1e-9 * largestFace, where + ": the clipped polyhedron is not closed");
    for (int f = 0; f < 6; ++f) {
      const int d = f / 2;
      const long face = g_.faceIndex(d, i + (d == 0) * (f % 2), j + (d == 1) * (f % 2), k + (d == 2) * (f % 2));
      const double fraction = m.openArea[f] / faceArea(d);
      auto& seen = seenFace_[d];
      if (seen.empty()) seen.assign(g_.openFraction_[d].size(), -1.0);
      if (seen[face] < 0) {
        seen[face] = fraction;
        seenCentroid_[d][face] = m.openCentroid[f];
      } else {
        st.maxSharedFaceMismatch = std::max(st.maxSharedFaceMismatch, std::abs(seen[face] - fraction));
        seen[face] = 0.5 * (seen[face] + fraction);  // both cells computed it; they agree to round-off
        seenCentroid_[d][face] = 0.5 * (seenCentroid_[d][face] + m.openCentroid[f]);
      }
    }
  }

  double faceArea(int axis) const {
    return b_.spacing()[(axis + 1) % 3] * b_.spacing()[(axis + 2) % 3];
  }

  // A face computed by a cut cell takes that value (the mean of both cells' when both are cut); any
  // other face is open exactly when a cell on its side is fluid (both neighbours are uncut, so both
  // are fluid or both solid).
  void reconcileFaces(const std::vector<bool>& cut) {
    const auto& n = b_.n();
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < n[2] + (d == 2); ++k)
        for (int j = 0; j < n[1] + (d == 1); ++j)
          for (int i = 0; i < n[0] + (d == 0); ++i) {
            const long face = g_.faceIndex(d, i, j, k);
            if (!seenFace_[d].empty() && seenFace_[d][face] >= 0) {
              const double fraction = std::clamp(seenFace_[d][face], 0.0, 1.0);
              g_.openFraction_[d][face] = fraction;
              if (fraction > 0.0 && fraction < 1.0)
                g_.cutFaceCentroids_[d].emplace_back(face, seenCentroid_[d].at(face));
              continue;
            }
            // The cell on the face's upper side, or the lower one on the background's upper side.
            std::array<int, 3> ijk = {i, j, k};
            if (ijk[d] == n[d]) --ijk[d];
            const long c = b_.index(ijk[0], ijk[1], ijk[2]);
            PARCELFLOW_ASSERT(!cut[c], "a cut cell's face was not measured");
            g_.openFraction_[d][face] = g_.fluidFraction_[c];
          }
  }

  CutCellGeometry& g_;
  const CartesianBackground& b_;
  TriangleSurface surface_;
  CoplanarSurfaceIndex coplanar_;
  std::string source_;
  std::vector<double> seenFace_[3];
  std::map<long, Vec3> seenCentroid_[3];  // open centroid of the faces in seenFace_
};

CutCellGeometry::CutCellGeometry(const TriangleSurface& fluidSurface, const CartesianBackground& background,
                                 const std::string& source)
    : background_(background), fluidFraction_(background.size(), 0.0), wallIndex_(background.size(), -1) {
  const auto& n = background.n();
  for (int d = 0; d < 3; ++d) {
    std::array<long, 3> planes = {n[0], n[1], n[2]};
    ++planes[d];
    openFraction_[d].assign(planes[0] * planes[1] * planes[2], 0.0);
  }
  CutCellBuilder(*this, fluidSurface, source).build();
}

long CutCellGeometry::faceIndex(int axis, int i, int j, int k) const {
  std::array<long, 3> planes = {background_.n()[0], background_.n()[1], background_.n()[2]};
  ++planes[axis];
  return i + planes[0] * (j + planes[1] * static_cast<long>(k));
}

Vec3 CutCellGeometry::fluidCentroid(long cell) const {
  if (wallIndex_[cell] >= 0) return centroids_[wallIndex_[cell]];
  const auto ijk = background_.ijk(cell);
  return background_.centre(ijk[0], ijk[1], ijk[2]);
}

std::array<int, 3> CutCellGeometry::faceCell(long cell, CellFace face) const {
  auto ijk = background_.ijk(cell);
  ijk[face / 2] += face % 2;
  return ijk;
}

Vec3 CutCellGeometry::openCentroid(long cell, CellFace face) const {
  const auto ijk = faceCell(cell, face);
  const int axis = face / 2;
  const auto& cutFaces = cutFaceCentroids_[axis];
  const long index = faceIndex(axis, ijk[0], ijk[1], ijk[2]);
  const auto it = std::lower_bound(cutFaces.begin(), cutFaces.end(), std::make_pair(index, Vec3(Vec3::Zero())),
                                   [](const auto& a, const auto& b) { return a.first < b.first; });
  if (it != cutFaces.end() && it->first == index) return it->second;
  // Whole or closed: the centre of the face.
  Vec3 centre = background_.centre(ijk[0], ijk[1], ijk[2]);
  centre[axis] = background_.origin()[axis] + ijk[axis] * background_.spacing()[axis];
  return centre;
}

double CutCellGeometry::openFraction(long cell, CellFace face) const {
  const auto ijk = faceCell(cell, face);
  const int axis = face / 2;
  return openFraction_[axis][faceIndex(axis, ijk[0], ijk[1], ijk[2])];
}

const CutCellWall& CutCellGeometry::wall(long cell) const {
  PARCELFLOW_ASSERT(wallIndex_[cell] >= 0, "wall() of a cell that is not cut");
  return walls_[wallIndex_[cell]];
}

}  // namespace parcelflow::cfd
