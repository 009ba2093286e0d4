#pragma once
// The cut-cell geometry of a Cartesian background (issue 31; the mesh builder uses it for mesh.walls: cut_cells).
// From a closed fluid surface (STL file or `geometry:` primitives, see stl_reader.hpp and
// surface_from_geometry.hpp) it computes for every background cell
//   - the fluid volume fraction in [0, 1] and the fluid centroid,
//   - for each of its 6 faces the open (fluid) area fraction and its centroid, one value per face shared
//     by both cells,
//   - for a cut cell its wall: true area, area vector (area-weighted normal, pointing out of the fluid
//     into the solid) and centroid.
// Method (cfd/README.md, "Cut-cell geometry"): cells whose closed box does not meet the surface are
// fluid or solid by an inside test of their centre; every other cell's box is clipped by the fluid
// solid with CGAL's corefinement, and the clipped polyhedron's faces on the box's planes are the open
// face areas, the remaining faces the wall.
#include <array>
#include <string>
#include <vector>

#include "cfd/geometry/cartesian_background.hpp"
#include "cfd/geometry/triangle_surface.hpp"

namespace parcelflow::cfd {

// The faces of a cell: axis = face / 2, lower side for even, upper side for odd.
enum CellFace { XMin = 0, XMax, YMin, YMax, ZMin, ZMax };

struct CutCellWall {
  double area = 0;                  // sum of the wall triangles' areas
  Vec3 areaVector = Vec3::Zero();   // sum of area x unit normal (out of the fluid); |areaVector| <= area,
                                    // equal for a plane wall; it closes the cell: sum of open face area
                                    // vectors + areaVector = 0
  Vec3 centroid = Vec3::Zero();     // area-weighted centroid of the wall triangles
  Vec3 normal() const { return areaVector.normalized(); }
};

class CutCellGeometry {
 public:
  // `source` names the surface in messages (e.g. "geometry.stl = column.stl"). Throws ConfigError when
  // no cell of the background has fluid. Surface points closer than 1e-9 spacings to a grid plane are
  // moved onto it (a cap at z = 7 m meant to lie on a grid plane must not leave 1e-16 slivers).
  CutCellGeometry(const TriangleSurface& fluidSurface, const CartesianBackground& background,
                  const std::string& source);

  const CartesianBackground& background() const { return background_; }

  // `cell` is the background index (CartesianBackground::index).
  double fluidFraction(long cell) const { return fluidFraction_[cell]; }
  // Centroid of the cell's fluid volume (the box centre for an uncut cell, and for a cut cell whose
  // box only touches the surface).
  Vec3 fluidCentroid(long cell) const;
  double openFraction(long cell, CellFace face) const;
  // Centroid of the open part of a face (the face centre when it is whole or closed).
  Vec3 openCentroid(long cell, CellFace face) const;
  bool isCut(long cell) const { return wallIndex_[cell] >= 0; }
  // The wall of a cut cell (a cut cell whose box only touches the surface has a zero wall).
  const CutCellWall& wall(long cell) const;

  struct Statistics {
    long fluidCells = 0, solidCells = 0, cutCells = 0;  // cut: the box meets the surface
    double fluidVolume = 0, wallArea = 0;
    double maxSharedFaceMismatch = 0;  // |difference| of a shared face's open area from its two cells,
                                       // relative to the face area (round-off only)
    double maxClosureError = 0;        // max over cut cells of |sum of face area vectors| / face area
    double seconds = 0;                // wall-clock time of the construction
  };
  const Statistics& statistics() const { return statistics_; }

 private:
  long faceIndex(int axis, int i, int j, int k) const;
  // (i, j, k) of a cell's face on its axis' plane of faces (the cell's, or the next one up for a + face)
  std::array<int, 3> faceCell(long cell, CellFace face) const;

  CartesianBackground background_;
  std::vector<double> fluidFraction_;
  std::vector<double> openFraction_[3];  // per axis, (n_axis + 1) planes of faces
  std::vector<int> wallIndex_;           // per cell, into walls_ and centroids_, -1 for uncut cells
  std::vector<CutCellWall> walls_;
  std::vector<Vec3> centroids_;          // fluid centroid per cut cell
  std::vector<std::pair<long, Vec3>> cutFaceCentroids_[3];  // per axis: (face, open centroid) of the
                                                            // partly open faces, sorted by face
  Statistics statistics_;

  friend class CutCellBuilder;
};

}  // namespace parcelflow::cfd
