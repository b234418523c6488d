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

/// All pairs, zero-length ones included, sorted by (dimension, birth value, death value).
std::vector<PersistencePair> ComputePersistence(
  const std::vector<Node>& nodes, const std::vector<Arc>& arcs);

} // namespace flowrecon

#endif
