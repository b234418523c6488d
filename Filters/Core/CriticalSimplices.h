// The critical points of d_P as Delaunay simplices (§2 of
// flow-complex-algorithm.md): Gabriel edges (index 1), acute Gabriel facets
// (index 2) and self-centred cells (index 3). Vertex indices are those of the
// Triangulation; every list is sorted, which fixes the node order.
#ifndef flowrecon_CriticalSimplices_h
#define flowrecon_CriticalSimplices_h

#include "Progress.h"
#include "Triangulation.h"

#include <array>
#include <cstdint>
#include <vector>

namespace flowrecon
{

struct CriticalSimplices
{
  std::vector<std::array<Id, 2>> Edges;
  std::vector<std::array<Id, 3>> Facets;
  /// A cell containing each facet and the index of the opposite vertex in it.
  std::vector<std::pair<CellHandle, int>> FacetCells;
  std::vector<std::array<Id, 4>> Cells;
  std::vector<Id> CellOfMaximum; ///< triangulation cell id of each entry of Cells
  Id RightAngles = 0;  ///< right triangles among the Delaunay facets
  Id ApexOnSphere = 0; ///< facets with an apex on their diametral sphere

  /// All Delaunay edges (u < v) as adjacency lists: the v of vertex u are
  /// Neighbours[Offsets[u] .. Offsets[u+1]), sorted; GabrielIndex gives the
  /// position of that edge in Edges, or -1.
  std::vector<Id> Offsets;
  std::vector<std::int32_t> Neighbours, GabrielIndex; // 32-bit: the largest table here

  /// Position of Gabriel edge (u, v) in Edges, or -1 if uv is not Gabriel.
  Id FindEdge(Id u, Id v) const;
  bool Degenerate() const { return this->RightAngles > 0 || this->ApexOnSphere > 0; }
};

/// Enumerates the critical simplices, counting degeneracies instead of failing
/// on them (the caller perturbs and retries when Degenerate() is true).
CriticalSimplices FindCriticalSimplices(const Triangulation& tri, const Progress& progress);

} // namespace flowrecon

#endif
