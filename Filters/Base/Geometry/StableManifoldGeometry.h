// Geometry on demand (docs/design.md, "Cost follows the output"): the triangulated
// stable manifolds of chosen nodes only. The whole complex's geometry grows like
// n^1.5 on samples of surfaces with tubes, while a stage outputs a small part.
#ifndef flowrecon_StableManifoldGeometry_h
#define flowrecon_StableManifoldGeometry_h

#include "FlowComplexBuilder.h"

#include <vector>

namespace flowrecon
{

class Retriangulation;

/// Cells of each node's stable manifold, read off the unsimplified Hasse diagram
/// without drawing anything: a descending walk starts with 3 branches and each
/// exit adds 2 branches and 2 triangles, each arrival 1 triangle, so A arrivals
/// (the sum of the node's 1-2 multiplicities) make 3A - 6 triangles. An index-3
/// cone has one tetrahedron per triangle of its boundary patches (fins once), and
/// one more per triangle at a point where the boundary meets itself (rare: these
/// counts are then a little low; see StableManifoldCone.h).
/// 0 for index 0 and 1 and for the maximum at infinity.
std::vector<Id> StableManifoldCellCounts(const std::vector<Node>& nodes, const std::vector<Arc>& arcs);

/// The finite nodes of index 2 and 3 in filtration order (value, index, id) whose
/// cells (`counts`) add up to at most `budget`, stopping at the first that does not
/// fit: the drawing is then the complex below a value, closed under faces.
std::vector<Id> NodesWithinBudget(
  const std::vector<Node>& nodes, const std::vector<Id>& counts, Id budget);

/// Draws the stable manifolds of `draw` (node ids; those of index 2 and 3 get
/// cells, others are ignored) into fc.Points, Triangles, TriangleNode,
/// Tetrahedra, TetrahedronNode and NodePoint, which are reset first. `fc` must be
/// the flow complex BuildFlowComplex computed from `points` with the same
/// options.Seed (its Nodes and Report.Attempts are used; its arcs may be
/// simplified): the triangulation of the points is recomputed (the floor cost)
/// and only the walks of the drawn patches run. fc.Points starts with `points`.
/// Throws InputError if the nodes do not belong to these points, or if the cells
/// would not fit in memory (`advice` says what to do); Aborted on request.
/// `unsimplifiedArcs`, when given, holds (at least) the 2-3 arcs of the
/// unsimplified complex: the cones' boundaries are then read from it instead of
/// being found again by flow-line roots.
/// `retriangulation`, when given, is that triangulation already made (with the
/// same options): it is used instead of a new one.
void DrawStableManifolds(const std::vector<Point3>& points, const BuildOptions& options,
  const std::vector<Id>& draw, FlowComplex& fc, const Progress& progress,
  const std::string& advice, const std::vector<Arc>* unsimplifiedArcs = nullptr,
  const Retriangulation* retriangulation = nullptr);

} // namespace flowrecon

#endif
