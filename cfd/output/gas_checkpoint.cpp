#include "cfd/output/gas_checkpoint.hpp"

#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "cfd/base/config_error.hpp"
#include "cfd/io/hdf5_file.hpp"

namespace parcelflow::cfd {

namespace {

// The axis direction of an outward boundary area vector: 0..5 = -x, +x, -y, +y, -z, +z.
long long direction(const Vec3& area) {
  int axis = 0;
  for (int d = 1; d < 3; ++d)
    if (std::abs(area[d]) > std::abs(area[axis])) axis = d;
  return 2 * axis + (area[axis] > 0.0 ? 1 : 0);
}

long long pairKey(long long a, long long b, long long n) { return a * n + b; }

// Face values by key (a face's two cells, or a boundary face's cell). One key can hold several faces (a merged
// cut cell's two faces to one neighbour; a cell's wall and box sides): their centres tell them apart. Files
// written before the centres were stored key boundary faces by cell and axis direction, one face per key.
class FaceValues {
 public:
  void add(long long key, const Vec3& centre, double value) { byKey_[key].push_back({centre, value}); }
  // The value of the face of `key` whose centre is nearest to `centre`; false when the key is absent.
  bool find(long long key, const Vec3& centre, double& value) const {
    const auto it = byKey_.find(key);
    if (it == byKey_.end()) return false;
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [at, v] : it->second) {
      const double distance = std::isnan(at[0]) ? 0.0 : (at - centre).squaredNorm();
      if (distance < best) {
        best = distance;
        value = v;
      }
    }
    return true;
  }

 private:
  std::unordered_map<long long, std::vector<std::pair<Vec3, double>>> byKey_;
};

// Rows of 3 doubles, or NaN centres for a file without the dataset.
std::vector<Vec3> centresOf(const Hdf5Reader& file, const std::string& name, std::size_t rows) {
  std::vector<Vec3> centres(rows, Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
  if (!file.hasDataset(name)) return centres;
  const std::vector<double> xyz = file.doubles(name);
  for (std::size_t r = 0; r < rows && 3 * r + 2 < xyz.size(); ++r)
    centres[r] = Vec3(xyz[3 * r], xyz[3 * r + 1], xyz[3 * r + 2]);
  return centres;
}

}  // namespace

void writeGasCheckpoint(const GasSolver& gas, const std::string& path, const std::string& checkpoint_id) {
  const Mesh& m = gas.mesh();
  const GasSolver::State s = gas.state();
  const int n = m.nOwnedCells();
  std::vector<long long> cells(n);
  std::vector<double> velocity(3 * static_cast<std::size_t>(n)), gradPRgh(velocity.size());
  for (int c = 0; c < n; ++c) {
    cells[c] = m.globalId(c);
    for (int d = 0; d < 3; ++d) {
      velocity[3 * c + d] = s.velocity[c][d];
      gradPRgh[3 * c + d] = s.gradPRgh[c][d];
    }
  }
  std::vector<long long> faces;
  std::vector<double> phi, faceCentres, boundaryCentres;
  for (int f = 0; f < m.nInternalFaces(); ++f)
    if (m.faceOwner(f) < n) {
      faces.insert(faces.end(), {m.globalId(m.faceOwner(f)), m.globalId(m.faceNeighbour(f))});
      phi.push_back(s.phi[f]);
      faceCentres.insert(faceCentres.end(), m.faceCentre(f).data(), m.faceCentre(f).data() + 3);
    }
  std::vector<long long> boundary;
  std::vector<double> phiB;
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    boundary.insert(boundary.end(), {m.globalId(m.boundaryCell(b)), direction(m.boundaryArea(b))});
    phiB.push_back(s.phiBoundary[b]);
    boundaryCentres.insert(boundaryCentres.end(), m.boundaryCentre(b).data(), m.boundaryCentre(b).data() + 3);
  }
  const long nFaces = static_cast<long>(phi.size()), nBoundary = static_cast<long>(phiB.size());
  const long cellOffset = rowOffset(n, m.comm()), faceOffset = rowOffset(nFaces, m.comm()),
             boundaryOffset = rowOffset(nBoundary, m.comm());
  const long totalFaces = static_cast<long>(m.sum(static_cast<double>(nFaces)));
  const long totalBoundary = static_cast<long>(m.sum(static_cast<double>(nBoundary)));
  const long total = m.nGlobalCells();

  Hdf5Writer file(path, m.comm());
  file.attribute("checkpoint_id", checkpoint_id);
  file.attribute("time", s.time);
  file.attribute("global_cells", static_cast<double>(total));
  file.write("cell_id", cells.data(), total, cellOffset, n, 1);
  file.write("alpha", s.alpha.data(), total, cellOffset, n, 1);
  file.write("p_rgh", s.pRgh.data(), total, cellOffset, n, 1);
  file.write("velocity", velocity.data(), total, cellOffset, n, 3);
  file.write("grad_p_rgh", gradPRgh.data(), total, cellOffset, n, 3);
  file.write("face_cells", faces.data(), totalFaces, faceOffset, nFaces, 2);
  file.write("phi", phi.data(), totalFaces, faceOffset, nFaces, 1);
  file.write("face_centre", faceCentres.data(), totalFaces, faceOffset, nFaces, 3);
  file.write("boundary_key", boundary.data(), totalBoundary, boundaryOffset, nBoundary, 2);
  file.write("phi_b", phiB.data(), totalBoundary, boundaryOffset, nBoundary, 1);
  file.write("boundary_centre", boundaryCentres.data(), totalBoundary, boundaryOffset, nBoundary, 3);
  file.close();
}

void readGasCheckpoint(GasSolver& gas, const std::string& path, const std::string& checkpoint_id) {
  const Mesh& m = gas.mesh();
  const Hdf5Reader file(path);
  const std::string id = file.textAttribute("checkpoint_id");
  if (id != checkpoint_id)
    throw ConfigError(path + ": checkpoint_id", id, "the id of the checkpoint it belongs to, " + checkpoint_id);
  const long total = static_cast<long>(file.numberAttribute("global_cells"));
  if (total != m.nGlobalCells())
    throw ConfigError(path + ": global_cells", std::to_string(total),
                      "the " + std::to_string(m.nGlobalCells()) + " fluid cells of this case's mesh");
  const std::vector<long long> ids = file.integers("cell_id");
  const std::vector<double> alpha = file.doubles("alpha"), pRgh = file.doubles("p_rgh"),
                            velocity = file.doubles("velocity"), gradPRgh = file.doubles("grad_p_rgh");
  std::unordered_map<long long, std::size_t> rowOfCell;
  for (std::size_t r = 0; r < ids.size(); ++r) rowOfCell[ids[r]] = r;

  GasSolver::State s = gas.state();
  s.time = file.numberAttribute("time");
  // Cells or faces of this mesh the file lacks; counted on all ranks first, so that all stop together.
  double missing = 0.0;
  for (int c = 0; c < m.nOwnedCells(); ++c) {
    const auto it = rowOfCell.find(m.globalId(c));
    if (it == rowOfCell.end()) {
      ++missing;
      continue;
    }
    s.alpha[c] = alpha[it->second];
    s.pRgh[c] = pRgh[it->second];
    for (int d = 0; d < 3; ++d) {
      s.velocity[c][d] = velocity[3 * it->second + d];
      s.gradPRgh[c][d] = gradPRgh[3 * it->second + d];
    }
  }

  const std::vector<long long> faces = file.integers("face_cells");
  const std::vector<double> phi = file.doubles("phi");
  const std::vector<Vec3> faceCentres = centresOf(file, "face_centre", phi.size());
  FaceValues phiOfFace;
  for (std::size_t r = 0; r < phi.size(); ++r)
    phiOfFace.add(pairKey(faces[2 * r], faces[2 * r + 1], total), faceCentres[r], phi[r]);
  for (int f = 0; f < m.nInternalFaces(); ++f)
    if (!phiOfFace.find(pairKey(m.globalId(m.faceOwner(f)), m.globalId(m.faceNeighbour(f)), total), m.faceCentre(f),
                        s.phi[f]))
      ++missing;
  const std::vector<long long> boundary = file.integers("boundary_key");
  const std::vector<double> phiB = file.doubles("phi_b");
  const std::vector<Vec3> boundaryCentres = centresOf(file, "boundary_centre", phiB.size());
  // With centres a boundary face is found by its cell and centre alone: the axis direction of a cut wall facing
  // 45 degrees between two axes is decided by round-off.
  const bool byCentre = file.hasDataset("boundary_centre");
  const auto boundaryKey = [&](long long cell, long long axisDirection) {
    return byCentre ? cell : cell * 6 + axisDirection;
  };
  FaceValues phiOfBoundary;
  for (std::size_t r = 0; r < phiB.size(); ++r)
    phiOfBoundary.add(boundaryKey(boundary[2 * r], boundary[2 * r + 1]), boundaryCentres[r], phiB[r]);
  for (int b = 0; b < m.nBoundaryFaces(); ++b)
    if (!phiOfBoundary.find(boundaryKey(m.globalId(m.boundaryCell(b)), direction(m.boundaryArea(b))),
                            m.boundaryCentre(b), s.phiBoundary[b]))
      ++missing;
  const double missingGlobal = m.sum(missing);
  if (missingGlobal > 0.0)
    throw ConfigError(path, std::to_string(static_cast<long>(missingGlobal)) + " cells and faces of this mesh missing",
                      "a checkpoint of this case's mesh (same mesh and geometry)");
  gas.restore(s);
}

}  // namespace parcelflow::cfd
