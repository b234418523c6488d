// The stable manifold of an index-2 critical point: the descending walk through
// Voronoi facets of docs/algorithm.md §4.2 (Giesen & John's
// STABLEFLOWCOMPLEX). It yields a triangulated patch and the Gabriel edges the
// walk arrives at (the 1-2 incidences, with multiplicity).
#ifndef flowrecon_StableManifold_h
#define flowrecon_StableManifold_h

#include "CriticalSimplices.h"

namespace flowrecon
{

struct Patch
{
  /// Constructed vertices; [0] is the critical point c_f.
  std::vector<Point3> Constructed;
  /// Triangles; a vertex v >= 0 is a triangulation vertex, v < 0 is Constructed[-1 - v].
  /// They are oriented consistently (neighbours run through a shared edge in
  /// opposite directions), so that the patch has a side: see PatchFacesSide.
  std::vector<std::array<Id, 3>> Triangles;
  /// Positions in CriticalSimplices::Edges.Values of the Gabriel edges reached, one per arrival.
  std::vector<Id> Arrivals;
  /// The Delaunay triangles (u, v, s*) whose Voronoi edges the walk crosses, one
  /// per exit, in triangulation vertex ids (only when asked for): with the
  /// critical facet, the Delaunay triangles a compact output puts in its place.
  std::vector<std::array<Id, 3>> Walked;
  /// A Delaunay cell holding each Walked triangle (the walk's exit cell), so
  /// that its two sides need no search of the triangulation.
  std::vector<CellHandle> WalkedCells;
};

/// Stable manifold of the acute Gabriel facet cs.Facets[facet]. With `withGeometry` false
/// only Arrivals are filled. Throws Degenerate if the walk meets a Voronoi vertex.
/// `fallbacks` counts walks redone in exact arithmetic; `exactOnly` skips the
/// interval stage (tests). `withWalked` fills Walked.
Patch ComputeStableManifold(const Triangulation& tri, const CriticalSimplices& cs,
  std::size_t facet, bool withGeometry, Id& fallbacks, bool exactOnly, bool withWalked = false);

/// The side of the critical facet cs.Facets[facet] that the normals of its
/// patch's triangles ((b - a) x (c - a)) face: 0 toward the vertex opposite the
/// facet in cs.Facets[facet].Cell, 1 toward the other cell. (The flow line from
/// the critical point through side s reaches the maximum SuccessorForest gives
/// for that cell.) Exact.
int PatchFacesSide(const Triangulation& tri, const CriticalSimplices& cs, std::size_t facet);

} // namespace flowrecon

#endif
