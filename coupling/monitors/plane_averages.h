// Means of a cell field on horizontal planes (pressure, gas fraction): the volume-weighted mean over the
// fluid cells of the background layer that contains the plane's height, or, given the field's vertical
// gradient, of its linear reconstruction at the plane's exact height (so a plane at the plate, z = 0,
// gets the plate's pressure). One all-reduce per call.
#pragma once

#include <vector>

#include "cfd/mesh/mesh.hpp"

namespace parcelflow::coupling {

class PlaneAverages {
 public:
  // Throws cfd::ConfigError naming `key` when a height has no fluid cell.
  PlaneAverages(const cfd::Mesh& mesh, const std::vector<double>& heights, const char* key);
  std::vector<double> means(const cfd::ScalarField& field) const;  // owned entries are read
  std::vector<double> meansAtHeights(const cfd::ScalarField& field, const cfd::VectorField& gradient) const;
  // The fluid cross-section of plane k's layer.
  double layerArea(std::size_t k) const { return layer_area_[k]; }

 private:
  const cfd::Mesh& mesh_;
  std::vector<int> layer_of_plane_;
  std::vector<int> layer_of_cell_;  // owned cells
  std::vector<double> height_, layer_centre_, layer_area_;
};

}  // namespace parcelflow::coupling
