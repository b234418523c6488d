// The critical simplices of a stored flow complex, read off its nodes and
// checked on the triangulation of its samples, instead of classifying every
// Delaunay simplex again: a later stage that walks some of its patches
// (Retriangulation) needs them. One pass over the cells finds the nodes'
// simplices, and the predicates run on those alone (a surface sample's
// triangulation has about ten times more simplices than critical ones): 1.6 s
// against 2.3-2.9 s for the classification on 3*10^5 torus points, without its
// table of every Delaunay edge.
#ifndef flowrecon_StoredCriticalSimplices_h
#define flowrecon_StoredCriticalSimplices_h

#include "CriticalSimplices.h"
#include "FlowComplex.h"
#include "Progress.h"
#include "Triangulation.h"

#include <vector>

namespace flowrecon
{

/// The critical simplices of `tri` named by `nodes` (a flow complex built on
/// the triangulation's points: node k < tri.NumberOfVertices() is vertex k,
/// then the index-1, index-2 and index-3 nodes in the order of their sorted
/// vertex ids, then the maximum at infinity). `inputId` gives the input id of
/// each vertex (the nodes' Simplex holds input ids). Each node's simplex must
/// be a simplex of `tri` and critical there, by the same exact predicates as
/// FindCriticalSimplices (an edge no Delaunay facet is obtuse against, an acute
/// facet with both apices strictly outside its diametral ball, a cell that
/// holds its circumcentre), and the lists must be strictly sorted, without a
/// tie on any predicate; the result is then what FindCriticalSimplices gives.
/// Otherwise throws InputError(`mismatch`). What cannot be checked without
/// classifying every simplex is that no critical simplex is missing from the
/// nodes; the counts still add up to the Euler characteristic of space.
CriticalSimplices StoredCriticalSimplices(const Triangulation& tri, const std::vector<Node>& nodes,
  const std::vector<Id>& inputId, const char* mismatch, const Progress& progress = Progress());

} // namespace flowrecon

#endif
