#include "gas_checkpoint.hpp"

#include <unordered_map>

#include "config_error.hpp"
#include "hdf5_file.hpp"

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
  std::vector<double> phi;
  for (int f = 0; f < m.nInternalFaces(); ++f)
    if (m.faceOwner(f) < n) {
      faces.insert(faces.end(), {m.globalId(m.faceOwner(f)), m.globalId(m.faceNeighbour(f))});
      phi.push_back(s.phi[f]);
    }
  std::vector<long long> boundary;
  std::vector<double> phiB;
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    boundary.insert(boundary.end(), {m.globalId(m.boundaryCell(b)), direction(m.boundaryArea(b))});
    phiB.push_back(s.phiBoundary[b]);
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
  file.write("boundary_key", boundary.data(), totalBoundary, boundaryOffset, nBoundary, 2);
  file.write("phi_b", phiB.data(), totalBoundary, boundaryOffset, nBoundary, 1);
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
  std::unordered_map<long long, double> phiOfFace;
  for (std::size_t r = 0; r < phi.size(); ++r) phiOfFace[pairKey(faces[2 * r], faces[2 * r + 1], total)] = phi[r];
  for (int f = 0; f < m.nInternalFaces(); ++f) {
    const auto it = phiOfFace.find(pairKey(m.globalId(m.faceOwner(f)), m.globalId(m.faceNeighbour(f)), total));
    if (it == phiOfFace.end())
      ++missing;
    else
      s.phi[f] = it->second;
  }
  const std::vector<long long> boundary = file.integers("boundary_key");
  const std::vector<double> phiB = file.doubles("phi_b");
  std::unordered_map<long long, double> phiOfBoundary;
  for (std::size_t r = 0; r < phiB.size(); ++r) phiOfBoundary[boundary[2 * r] * 6 + boundary[2 * r + 1]] = phiB[r];
  for (int b = 0; b < m.nBoundaryFaces(); ++b) {
    const auto it = phiOfBoundary.find(m.globalId(m.boundaryCell(b)) * 6 + direction(m.boundaryArea(b)));
    if (it == phiOfBoundary.end())
      ++missing;
    else
      s.phiBoundary[b] = it->second;
  }
  const double missingGlobal = m.sum(missing);
  if (missingGlobal > 0.0)
    throw ConfigError(path, std::to_string(static_cast<long>(missingGlobal)) + " cells and faces of this mesh missing",
                      "a checkpoint of this case's mesh (same mesh and geometry)");
  gas.restore(s);
}

}  // namespace parcelflow::cfd
