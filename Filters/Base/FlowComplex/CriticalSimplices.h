// The critical points of d_P as Delaunay simplices (docs/algorithm.md §2):
// Gabriel edges (index 1), acute Gabriel facets (index 2) and self-centred cells
// (index 3). Vertex indices are those of the Triangulation; every list is sorted,
// which fixes the node order.
#ifndef flowrecon_CriticalSimplices_h
#define flowrecon_CriticalSimplices_h

#include "CompressedRows.h"
#include "Progress.h"
#include "Triangulation.h"

#include <array>
#include <cstdint>
#include <vector>

namespace flowrecon
{

/// An acute Gabriel facet (vertex ids in increasing order), with the id of a
/// cell containing it and the index of the opposite vertex in that cell.
/// 32-bit ids: these lists are among the largest of the computation.
struct CriticalFacet
{
  std::array<std::int32_t, 3> Vertices;
  std::int32_t Cell;
  std::int32_t Opposite;
};

/// A self-centred cell (vertex ids in increasing order) and its cell id.
struct CriticalCell
{
  std::array<std::int32_t, 4> Vertices;
  std::int32_t Cell;
};

struct CriticalSimplices
{
  /// Gabriel edges (u < v) in lexicographic order, one row per vertex u; an
  /// edge's position in Edges.Values is its id (node Base1 + id).
  CompressedRows<std::array<Id, 2>> Edges;
  std::vector<CriticalFacet> Facets; ///< sorted by vertices
  std::vector<CriticalCell> Cells;   ///< sorted by vertices
  Id RightAngles = 0;  ///< right triangles among the Delaunay facets
  Id ApexOnSphere = 0; ///< facets with an apex on their diametral sphere

  /// Position of Gabriel edge (u, v) in Edges.Values, or -1 if uv is not
  /// Gabriel. Needs Edges.Offsets (freed after the walks unless kept).
  Id FindEdge(Id u, Id v) const;
  bool Degenerate() const { return this->RightAngles > 0 || this->ApexOnSphere > 0; }
};

/// 64-bit copy of a list of 32-bit vertex ids.
template <std::size_t N>
std::array<Id, N> Widen(const std::array<std::int32_t, N>& v)
{
  std::array<Id, N> w;
  for (std::size_t i = 0; i < N; ++i)
  {
    w[i] = v[i];
  }
  return w;
}

/// Enumerates the critical simplices, counting degeneracies instead of failing
/// on them (the caller perturbs and retries when Degenerate() is true).
CriticalSimplices FindCriticalSimplices(const Triangulation& tri, const Progress& progress);

} // namespace flowrecon

#endif
