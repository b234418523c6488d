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
///
/// A cell can also meet itself along an edge (a Gabriel edge where several of
/// its boundary patches arrive): the triangles around that edge then belong to
/// several sheets, and which ones pair up depends on the side of each triangle
/// the cell is on. So `boundary` is oriented: the normal (b - a) x (c - a) of
/// each triangle faces into the cell, except for the triangles marked in
/// `twoSided` (a fin: the cell on both sides), whose orientation is free.
/// Around such an edge the triangles are paired through the wedges of the cell
/// (SheetsAroundEdge); if the geometry does not tell, they stay one sheet.
/// Returns the number of tetrahedra appended: boundary.size() when nothing is
/// pinched, more otherwise.
Id AppendCone(Id apex, const std::vector<std::array<Id, 3>>& boundary,
  std::vector<Point3>& points, std::vector<std::array<Id, 4>>& tetrahedra,
  const std::vector<char>* twoSided = nullptr);

/// The boundary of a cone, as AppendCone takes it, gathered patch by patch.
struct ConeBoundary
{
  std::vector<std::array<Id, 3>> Triangles;
  std::vector<char> TwoSided;

  void Clear()
  {
    this->Triangles.clear();
    this->TwoSided.clear();
  }
  /// Adds the triangles [first, last) of a patch (oriented consistently, as
  /// Patch::Triangles), reversed when their normals face away from the cell,
  /// two-sided when the patch is a fin of the cell.
  void Add(const std::array<Id, 3>* first, const std::array<Id, 3>* last, bool reverse, bool fin)
  {
    for (; first != last; ++first)
    {
      const std::array<Id, 3>& t = *first;
      this->Triangles.push_back(reverse ? std::array<Id, 3>{ { t[0], t[2], t[1] } } : t);
      this->TwoSided.push_back(fin ? 1 : 0);
    }
  }
};

/// The sheets of a cell around the edge (p, x) that `triangles` (positions into
/// `boundary`, each holding p and x, oriented as for AppendCone) share: sorted
/// by angle around the edge, two consecutive triangles are in one sheet when
/// the wedge between them is inside the cell, that is when the first faces
/// forward into it and the second back. Returns, for each triangle, the first
/// triangle of its sheet (its position in `triangles`), or an empty vector when
/// the triangles do not bound wedges consistently (coinciding half-planes, or a
/// wedge claimed from one side only).
std::vector<std::size_t> SheetsAroundEdge(const std::vector<Point3>& points,
  const std::vector<std::array<Id, 3>>& boundary, const std::vector<char>* twoSided, Id p, Id x,
  const std::vector<std::size_t>& triangles);

} // namespace flowrecon

#endif
