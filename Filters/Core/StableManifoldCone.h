// The tetrahedra of an index-3 stable manifold: a cone from its maximum over the
// triangles of its boundary patches, split where the boundary meets itself so
// that the cone has the cell's topology.
#ifndef flowrecon_StableManifoldCone_h
#define flowrecon_StableManifoldCone_h

#include "FlowComplex.h"

#include <array>
#include <vector>

namespace flowrecon
{

/// Appends to `tetrahedra` the cone from point `apex` over `boundary` (triangles
/// of point ids into `points`), and to `points` the points its subdivision adds.
///
/// A cell can wrap around and meet itself at a sample: its boundary is then a
/// sphere pinched there (the sample's link in the boundary has several
/// components), and the closed cell is a ball with boundary points identified,
/// which has a loop. A plain cone would also glue the segments from the apex to
/// the pinched point, filling that loop: the union with the neighbouring cells,
/// which fill it too, would enclose a void the flow complex does not have (seen
/// on tube-like samples: 12 voids at t_r = inf on 6000 torus points). So for
/// every component but the first, the segment from the apex to the pinched point
/// gets a point of its own (a stellar subdivision of that edge in the tetrahedra
/// of that component), and the sheets meet at the sample only.
/// Returns the number of tetrahedra appended: boundary.size() when nothing is
/// pinched, more otherwise.
Id AppendCone(Id apex, const std::vector<std::array<Id, 3>>& boundary,
  std::vector<Point3>& points, std::vector<std::array<Id, 4>>& tetrahedra);

} // namespace flowrecon

#endif
