#pragma once
// Solids above a bound moved to the neighbouring cells instead of being dropped, so that the gas-fraction
// floor keeps the solids volume (issue 29). A parcel larger than its cells deposits lumps: in the settled
// fluidized bed of np 8 parcels (5 mm on 3.125 mm cells) 21 % of the bed's cells got more than 0.7 solids,
// and the floor a_g >= 0.3 dropped 0.009 of the bed's 0.66; the gas then saw a looser bed, whose drag on the
// packed branch was 8 % below the beads' (cases/coarse_graining/fluidized/README.md).
// One pass, with E_c = max(0, s_c - s_max) V_c the excess and R_c = max(0, s_max - s_c) V_c the room of a
// cell and S_n = sum of R over the face neighbours of n: cell n gives min(E_n, S_n), and each face neighbour
// c of n receives R_c min(1, E_n / S_n). What n gives is what its neighbours receive, so sum V s is kept to
// round-off on any number of ranks (each owner computes its cells from halo copies of E, R and S). A cell
// receiving from several neighbours can end above s_max; the next pass moves that on. After `passes`
// passes, or once no owned cell of any rank has an excess above 1e-12 of its volume, the rest stays for the
// floor to cut (and count).
#include <vector>

#include "cfd/mesh/mesh.hpp"

namespace parcelflow::cfd {

struct SpillStats {
  long cells = 0;         // owned cells that gave solids, summed over the passes (this rank)
  int passes = 0;         // passes made (the same on every rank)
};

// owned: the solids fraction on the owned cells, changed in place. Collective.
SpillStats spillExcessSolids(const Mesh& mesh, std::vector<double>& owned, double maxSolids, int passes = 20);

}  // namespace parcelflow::cfd
