// Betti numbers of every reconstruction of one run, read off the Hasse diagram
// without geometry (Delfinado & Edelsbrunner's incremental Betti numbers for
// complexes in S^3).
//
// Why it is exact. The stable manifolds of the critical points, with the
// maximum at infinity, decompose S^3 = R^3 + {inf}, and the raw diagram's arcs
// counted mod 2 are the boundary operator of that decomposition. The
// reconstruction at t_r = t is drawn as the raw cells of its nodes and of the
// pairs they carry, with their faces: the closed subcomplex K_t of the raw
// nodes with presence < t (PresenceTimes).
// Adding the cells of K_t one at a time (faces first), each changes exactly one
// Betti number by one:
// - a vertex: b0 + 1;
// - an edge: b0 - 1 when it joins two components (union-find over the 0-1
//   arcs), else b1 + 1;
// - a 2-cell: b2 + 1 when it separates its complement component in two, else
//   b1 - 1. By Alexander duality b2(K_t) = (components of S^3 - K_t) - 1, and
//   the complement's components are the maxima outside K_t joined by the index-2
//   nodes outside (a 2-cell has two sides): a union-find run backwards, from the
//   largest threshold down, says which 2-cells separate;
// - a maximum: b2 - 1 (closure makes it the last maximum of its component).
// This is the cellular homology of the raw diagram's chain complex: the homology
// of the drawn cells wherever each stable manifold is drawn as a cell, which the
// tests check against the persistent homology of the drawn cells.
#ifndef flowrecon_HasseTopology_h
#define flowrecon_HasseTopology_h

#include "CellHomology.h"
#include "FlowComplex.h"
#include "Reconstruction.h"

#include <utility>
#include <vector>

namespace flowrecon
{

/// When each node's cells are in the reconstruction: the Threshold (in `run`)
/// of its carrier (`carriers`, CellCarriers: the node whose insertion draws its
/// cells), or of a coface's, since the drawing holds every face of a cell; +inf
/// when never. `rawArcs`: the diagram before simplification, with the 1-2 arcs
/// of every node that has a carrier (or whose maxima have one).
std::vector<double> PresenceTimes(const std::vector<Node>& nodes, const std::vector<Arc>& rawArcs,
  const std::vector<Id>& carriers, const ReconstructionResult& run);

/// The bars of the nested family K_t = {nodes with presence < t} of the
/// unsimplified complex: a class is present for t_r in (Birth, Death], Death
/// +inf for a class that lives past every finite presence. BirthCell and
/// DeathCell are node ids. Bars of dimensions 0 and 2 follow the elder rule;
/// in dimension 1 a death takes the latest birth (the counts, which are all the
/// Betti numbers need, do not depend on that choice).
///
/// Why the unsimplified complex: a cancellation adds boundaries mod 2, so a
/// shared edge of a cancelled pair vanishes from the merged node's boundary
/// while the drawing keeps it; the raw cells with PresenceTimes are exactly
/// what is drawn. `rawArcs` must hold the 0-1 arcs, the 2-3 arcs of every
/// index-2 node, grouped by lower node (even multiplicities count as absent).
/// Throws InputError when they do not form a closed filtration of a
/// decomposition of S^3 (a node before its boundary, a 2-cell with one side).
/// `joined`: pairs of maxima never present that lie in one component of the
/// complement at every threshold (TopologyInput.h); rawArcs may then give a
/// 2-cell's side as any maximum of the component its side lies in.
std::vector<Bar> HasseBarcode(const std::vector<Node>& nodes, const std::vector<Arc>& rawArcs,
  const std::vector<double>& presence, const std::vector<std::pair<Id, Id>>& joined = {});

} // namespace flowrecon

#endif
