// The driver of a Delaunay simplex (Lemma A, docs/algorithm.md §1.3): the
// face tau(sigma) whose circumcentre is the point of sigma closest to c_sigma.
// Decided with exact predicates on the input points only (§1.6); any boundary
// outcome means the input is not in general position and raises Degenerate.
#ifndef flowrecon_Driver_h
#define flowrecon_Driver_h

#include "Delaunay.h"

namespace flowrecon
{

/// Which vertex of triangle abc the driver avoids: -1 if abc is acute (self-
/// centred), else 0, 1 or 2 for the obtuse corner (the driver is the opposite edge).
int ObtuseCorner(const KPoint& a, const KPoint& b, const KPoint& c);

struct CellDriver
{
  enum Kind
  {
    Cell,  ///< self-centred: c_T is an index-3 critical point
    Facet, ///< the facet opposite vertex A is visible from c_T
    Edge   ///< the driver is the midpoint of edge (A, B) (local vertex indices)
  };
  Kind Type = Cell;
  int A = -1, B = -1;
};

/// Whether c_T lies strictly inside the finite cell T (an index-3 critical point).
bool IsSelfCentred(CellHandle c);

/// Driver of the finite cell `c`.
CellDriver ClassifyCell(CellHandle c);

} // namespace flowrecon

#endif
