// The components of the space farther than a level r from every sample,
// U_r = {x : d(x) > r}, read off the Delaunay triangulation.
//
// Why the topology needs them. Every point of a reconstruction whose nodes have
// values <= r lies at distance <= r from the samples, so U_r is outside it, and
// two maxima in one component of U_r are in one component of its complement.
// A flow line that reaches a Voronoi vertex in U_r ends at a maximum of the
// same component (the distance grows along the flow): its component says on
// which side of the reconstruction the line ends, without following it there.
//
// Why the triangulation gives them exactly. Inside a Voronoi cell, U_r is the
// cell minus a ball around its sample; pushing away from the sample, then
// inside each facet away from the ball's trace, joins every point of U_r to the
// Voronoi edges within U_r, and so to their Voronoi vertices. Hence the
// components of U_r are those of the graph whose vertices are the Voronoi
// vertices in U_r (the cells of circumradius > r, and infinity) and whose edges
// are the Voronoi edges lying in U_r. The edge dual to a facet f runs along the
// line through f's circumcentre normal to f, where the distance is
// sqrt(R_f^2 + s^2); it reaches down to R_f exactly when f is Gabriel (no apex
// strictly inside f's diametral sphere), else its lowest point is an end.
// Both tests are exact predicates of the kernel.
#ifndef flowrecon_ExteriorRegions_h
#define flowrecon_ExteriorRegions_h

#include "Triangulation.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace flowrecon
{

class UnionFind;

/// The components of U_r (r^2 = `levelSq`, triangulation units), computed
/// over every cell in parallel; deterministic.
///
/// Why a lower level needs only what enters. As r goes down U_r grows, and so
/// does its graph: a cell of circumradius > r stays above any lower level, and
/// a facet whose Voronoi edge lies in U_r (not Gabriel, or R_f > r) lies in the
/// U of any lower level. The components at a lower level are therefore those
/// at r joined by the cells that enter and their facets, and by the facets
/// that failed at r and pass now (Descend): the regions a new object at that
/// level has, for the cost of what changed. The lower levels of a surface
/// sample hold nearly the same cells (TopologyInput.h).
class ExteriorRegions
{
public:
  /// Throws Degenerate when the triangulation is not 3-dimensional.
  /// `lowerLater`: keeps what Descend needs (the cells' flags, the union-find
  /// and the facets that did not join: 6 bytes a cell, and a reference to `tri`).
  ExteriorRegions(const Triangulation& tri, double levelSq, bool lowerLater = false);
  ~ExteriorRegions();

  /// The regions at `levelSq` <= Level() (Why, above); needs lowerLater.
  void Descend(double levelSq);

  double Level() const { return this->LevelSq; } ///< squared
  /// The triangulation's Serial(): regions of one do not fit another.
  std::uint64_t Of() const { return this->TriangulationSerial; }
  /// The region of a finite cell's Voronoi vertex, -1 when it is not in U_r.
  std::int32_t RegionOf(Id cell) const { return this->Region[static_cast<std::size_t>(cell)]; }
  std::int32_t Count() const { return this->Count_; }
  std::int32_t InfiniteRegion() const { return this->Infinite; } ///< infinity's region
  std::int64_t CellsAbove() const { return this->Above; }

private:
  /// Dense region ids, in the order of the regions' smallest cells.
  void Label(const std::vector<char>& above, UnionFind& components);
  /// The cells over Level() not yet in U enter it (flag 2) and are joined
  /// across their facets, as are the facets that failed before (`failed`);
  /// kept for a lower level (`failed` given), every flag is then 1.
  void Enter(std::vector<char>& above, UnionFind& components, std::vector<std::uint8_t>* failed);

  double LevelSq;
  std::uint64_t TriangulationSerial;
  const Triangulation* Tri = nullptr; ///< with lowerLater
  std::vector<char> InU;              ///< with lowerLater: per cell
  std::unique_ptr<UnionFind> Components; ///< with lowerLater
  /// With lowerLater: per cell, bit i for its facet i when it was tested (both
  /// sides in U, in different components) and its Voronoi edge is not in U
  /// (a Gabriel facet with R_f <= r): a lower level tests it again.
  std::vector<std::uint8_t> Failed;
  std::vector<std::int32_t> Region;
  std::int32_t Count_ = 0, Infinite = -1;
  std::int64_t Above = 0;
};

} // namespace flowrecon

#endif
