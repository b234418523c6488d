// A compact stand-in for a reconstruction (the default output of `flowrecon
// reconstruct`; `--exact` writes the exact one): Delaunay simplices on the
// samples in place of the exact stable manifolds, about 2 triangles a sample
// on a surface instead of ~9 cells over constructed points. An index-2 node c
// gives the Delaunay triangles its descending walk crosses (docs/algorithm.md
// §4.2): its facet and each u v s* of an exit, a tree of triangles glued along
// the walked edges whose leaves end on the Gabriel edges where S(c) ends,
// homeomorphic to S(c) when no triangle or edge is shared between steps
// (docs/compact-output.md). An index-3 node gives
// the Delaunay cells whose Voronoi vertex flows to it, an index-1 node its
// Gabriel edge, an index-0 node its sample; a triangle that is a facet of a
// written tetrahedron is left out (the solid holds it). Where two walks cross one
// Delaunay triangle the two patches share it: counted, not resolved; where
// two patches close around Voronoi vertices that the exact ones leave open,
// the void is filled.
#ifndef flowrecon_CompactReconstruction_h
#define flowrecon_CompactReconstruction_h

#include "FlowComplex.h"
#include "Progress.h"

#include <array>
#include <tuple>
#include <cstdint>
#include <vector>

namespace flowrecon
{

class UnionFind;

class Retriangulation;

/// Cells over input point ids, each with the node it stands for. Triangles
/// are distinct and appear only when no tetrahedron has them as a facet; an
/// edge or a sample appears only when no triangle or tetrahedron holds it.
struct CompactComplex
{
  std::vector<Id> Vertices, VertexNode;
  std::vector<std::array<Id, 2>> Edges;
  std::vector<Id> EdgeNode;
  std::vector<std::array<Id, 3>> Triangles;
  std::vector<Id> TriangleNode;
  /// Per triangle, how many index-2 nodes' walks cross it (1 but where shared).
  std::vector<int> TriangleClaims;
  /// Per triangle, the Threshold of its node when the maker has it in order
  /// (CompactFamily), else empty: the VTK conversion then reads it per node,
  /// at random, which at 10^6 points was a fifth of a t_r change.
  std::vector<double> TriangleThreshold;
  std::vector<std::array<Id, 4>> Tetrahedra;
  std::vector<Id> TetrahedronNode;
  /// Written triangles crossed by the walks of two (or more) index-2 nodes:
  /// written once, for the least node id.
  Id SharedTriangles = 0;
  /// Written triangles crossed twice by one walk (written once).
  Id RevisitedTriangles = 0;
  /// Voids of the complex with no maximum inside, filled with their Delaunay
  /// cells (see CompactReconstruction).
  Id FilledVoids = 0;
  /// Voids of the complex (bounded regions of its complement), after the filling.
  Id Voids = 0;
  /// b0, b1, b2, b3 of the cells: b2 = Voids (Alexander duality), b1 from the
  /// Euler characteristic; equal to CompactBettiNumbers, in linear time.
  std::array<Id, 4> Betti{ { 0, 0, 0, 0 } };
  /// Walks redone in exact arithmetic.
  Id ExactFallbacks = 0;

  /// Removes the triangles flagged in `drop`, keeping the order, with their
  /// node, claims and threshold; `alongside` (one entry a triangle) alike.
  template <class T>
  void DropTriangles(const std::vector<char>& drop, std::vector<T>& alongside)
  {
    const bool thresholds = this->TriangleThreshold.size() == this->Triangles.size();
    std::size_t kept = 0;
    for (std::size_t k = 0; k < this->Triangles.size(); ++k)
    {
      if (drop[k])
      {
        continue;
      }
      this->Triangles[kept] = this->Triangles[k];
      this->TriangleNode[kept] = this->TriangleNode[k];
      this->TriangleClaims[kept] = this->TriangleClaims[k];
      if (thresholds)
      {
        this->TriangleThreshold[kept] = this->TriangleThreshold[k];
      }
      alongside[kept] = alongside[k];
      ++kept;
    }
    this->Triangles.resize(kept);
    this->TriangleNode.resize(kept);
    this->TriangleClaims.resize(kept);
    this->TriangleThreshold.resize(thresholds ? kept : 0);
    alongside.resize(kept);
  }

  Id NumberOfCells() const
  {
    return static_cast<Id>(this->Vertices.size() + this->Edges.size() + this->Triangles.size() +
      this->Tetrahedra.size());
  }
};

/// A Delaunay triangle (input ids, sorted) crossed by the walk of an index-2 node.
struct CompactClaim
{
  std::array<Id, 3> Triangle;
  Id Node;
  /// The finite Delaunay cells on its two sides (-1: infinite) and the
  /// triangle's index in each: where the search for voids meets it as a wall.
  std::array<std::int32_t, 2> Cells{ { -1, -1 } };
  std::array<std::int8_t, 2> Facets{ { 0, 0 } };
  /// By triangle, then node; the sides break the remaining ties (one walk
  /// crossing a triangle twice, once from each side), so that any sort, a
  /// parallel one too, gives one order.
  bool operator<(const CompactClaim& o) const
  {
    return std::tie(this->Triangle, this->Node, this->Cells, this->Facets) <
      std::tie(o.Triangle, o.Node, o.Cells, o.Facets);
  }
};

/// What the compact complex of any subset of some candidate nodes is made of,
/// computed once: the walks of the index-2 candidates and the candidate
/// maximum each Delaunay cell flows to. A filter that shows the compact complex
/// for each t_r keeps them, so that a new t_r walks nothing again.
struct CompactPieces
{
  /// Every index-2 candidate's facet and the triangles its walk crosses, one
  /// claim per crossing, sorted (by triangle, then node).
  std::vector<CompactClaim> Claims;
  /// Per Delaunay cell, the candidate maximum it flows to, -1 for none; empty
  /// without candidate maxima.
  std::vector<std::int32_t> CellMaximum; // 32-bit node ids: one per Delaunay cell
  /// Walks redone in exact arithmetic, per index-2 candidate that needed any.
  std::vector<std::pair<Id, Id>> ExactFallbacks;
  /// Per Delaunay cell, its four neighbours' ids (-1: infinite), opposite its
  /// vertices: the search for voids follows millions of them, which CGAL's
  /// cells, scattered in memory, make several times slower.
  std::vector<std::array<std::int32_t, 4>> Neighbours;
};

/// The pieces of the nodes `candidates` (as `selected` below); progress from
/// 0 to 1 of `progress`. The patches the build recorded (RecordedWalks.h) are
/// not walked again. With `releaseFlow`, re's flow (Retriangulation::Flow) and
/// recorded walks are freed once the last piece that reads them is made.
CompactPieces PrepareCompact(const Retriangulation& re, const std::vector<Node>& nodes,
  const std::vector<Id>& candidates, const Progress& progress = Progress(), bool releaseFlow = false);

/// What the selection reads of the Delaunay cells, without the triangulation:
/// a caller that keeps the pieces for many thresholds (CompactFamily) frees
/// the triangulation, which is several times larger (10^6 torus points: 17 M
/// cells, about 1.4 GB against 0.27 GB for this).
struct CompactCells
{
  std::vector<std::array<std::int32_t, 4>> Vertices; ///< per cell, its input ids, sorted
  std::vector<std::int32_t> Maxima;                  ///< the cells holding a maximum
};

/// The cells of `re` (input ids below 2^31; throws InputError otherwise).
CompactCells CellsOf(const Retriangulation& re);
/// The sorted input ids of the cells `ids` of `re` alone (as CellsOf): what a
/// caller that frees the triangulation keeps of the cells it may write.
std::vector<std::array<std::int32_t, 4>> VerticesOfCells(
  const Retriangulation& re, const std::vector<std::int32_t>& ids);
/// The cells of `re` that hold a maximum (CompactCells::Maxima).
std::vector<std::int32_t> MaximumCells(const Retriangulation& re);

/// The compact complex of `selected`, which must be among the candidates
/// `pieces` were prepared for: the same complex as CompactReconstruction's, in
/// time linear in the pieces and the triangulation.
/// Without `betti`, compact.Betti is left zero (a caller that has the exact
/// reconstruction's Betti numbers does not need them again).
CompactComplex SelectCompact(const Retriangulation& re, const std::vector<Node>& nodes,
  const CompactPieces& pieces, const std::vector<Id>& selected, bool betti = true);
/// The same from the cells of the triangulation the pieces were prepared on.
CompactComplex SelectCompact(const CompactCells& cells, const std::vector<Node>& nodes,
  const CompactPieces& pieces, const std::vector<Id>& selected, bool betti = true);

/// The compact complex of the nodes `selected` (ids of `nodes`, any index;
/// the maximum at infinity is ignored). `re` is the triangulation of the
/// points the complex of `nodes` was built from (Retriangulation.h); only the
/// walks of the selected index-2 nodes run, and the flow lines of every
/// Delaunay cell when a maximum is selected (up to its value). A bounded
/// region of the complement that holds no maximum is filled with its cells:
/// the exact reconstruction has no such void. Throws InputError when a node
/// does not belong to `re`, Degenerate if a walk meets a tie. With
/// `releaseFlow`, re's flow is freed once no piece needs it (PrepareCompact;
/// Retriangulation::ReleaseFlow: only for a caller that knows nothing else
/// holds it).
CompactComplex CompactReconstruction(const Retriangulation& re, const std::vector<Node>& nodes,
  const std::vector<Id>& selected, const Progress& progress = Progress(), bool releaseFlow = false);

/// b0, b1, b2, b3 of the simplicial complex the cells span, by cell homology
/// (CellHomology): the oracle of compact.Betti, superlinear (50 s for 2 10^6
/// triangles).
std::array<Id, 4> CompactBettiNumbers(const CompactComplex& compact);

/// Marks in `used` (sized `points`) the samples that `cells` holds and joins
/// them, cell by cell, in `components` (sized `points`): its parts. A cell
/// with an id outside 0..points-1 (a damaged file) is passed over.
void JoinCells(const CompactComplex& cells, Id points, std::vector<char>& used, UnionFind& components);

} // namespace flowrecon

#endif
