// Persistent homology (over Z/2) of the flow-complex filtration: finite nodes
// enter in order of critical value, with boundaries given by the Hasse arcs of
// odd multiplicity. It equals the alpha-complex diagram (Dey, Giesen, John).
#ifndef flowrecon_Persistence_h
#define flowrecon_Persistence_h

#include "FlowComplex.h"

#include <vector>

namespace flowrecon
{

struct PersistencePair
{
  int Dimension = 0;   ///< homology dimension = index of the birth node
  Id Birth = -1;       ///< node creating the class
  Id Death = -1;       ///< node killing it, -1 for an essential class
  double BirthValue = 0;
  double DeathValue = 0; ///< +inf for an essential class
};

/// What ComputePersistence did, for tests and benchmarks.
struct PersistenceReport
{
  bool FastPath = false;  ///< false: the input was handed to ComputePersistenceByReduction
  bool GroupedArcs = false; ///< the arcs into each index-2 node were consecutive
  Id ReducedColumns = 0;  ///< H1 columns that needed additions
  Id ColumnAdditions = 0; ///< column additions of the H1 reduction
};

/// All pairs, zero-length ones included, sorted by (dimension, birth value, death
/// value, birth node). The filtration order is by value, then index, then node id.
/// H0 by union-find over the 0->1 arcs, H2 by union-find on the dual graph (maxima
/// and the maximum at infinity joined by the index-2 nodes, in decreasing order),
/// H1 by column reduction with clearing of the remaining index-2 nodes only. The
/// pairs are those of ComputePersistenceByReduction; input outside what the fast
/// path assumes (an index-1 node with more than two lower ends, an index-2 node
/// with more than two finite upper ends, repeated arcs, arcs skipping an index,
/// boundary of boundary not zero) is handed to it. Throws std::out_of_range for an
/// arc of odd multiplicity naming a node that does not exist.
std::vector<PersistencePair> ComputePersistence(const std::vector<Node>& nodes,
  const std::vector<Arc>& arcs, PersistenceReport* report = nullptr);

/// The same pairs by the plain column reduction of the whole boundary matrix
/// (finite nodes, arcs of odd multiplicity): the reference the fast path is tested
/// against, and its fallback.
std::vector<PersistencePair> ComputePersistenceByReduction(
  const std::vector<Node>& nodes, const std::vector<Arc>& arcs);

} // namespace flowrecon

#endif
