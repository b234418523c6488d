// Unstable manifolds (docs/algorithm.md §5): from a Voronoi vertex
// c_T the future of the flow is determined, so NEXT(T) is computed once per
// Delaunay cell (lazily, memoised) and ROOT(T) -- the maximum reached, or
// infinity -- follows NEXT with memoisation. Without recorded polylines only
// ROOT is kept (4 bytes a cell), and Root() may be called from several threads.
#ifndef flowrecon_SuccessorForest_h
#define flowrecon_SuccessorForest_h

#include "Progress.h"
#include "Triangulation.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

namespace flowrecon
{

/// The two cells of the critical facet (`cell`, `opposite`) whose Voronoi
/// vertices start its flow lines, ordered by their vertex off the facet (input
/// id, infinite last): an order that does not depend on the triangulation's
/// cell order, so the output stays deterministic. Side s of a flow line.
std::array<CellHandle, 2> FlowLineSides(const Triangulation& tri, Id cell, int opposite);

class SuccessorForest
{
public:
  /// `maximumOfCell[cellId]` is the node id of the maximum at a self-centred cell
  /// (else -1); `infinity` the node id of the maximum at infinity; `stub` the
  /// length of the segment drawn for a flow line that escapes to infinity;
  /// `record` keeps the points of the flow lines (for AppendPath), else only the
  /// maxima reached are computed; `exactOnly` walks in exact arithmetic only (tests).
  SuccessorForest(const Triangulation& tri, const std::vector<std::int32_t>& maximumOfCell,
    Id infinity, double stub, bool record, bool exactOnly);

  /// The maximum reached by the flow from the Voronoi vertex of finite cell `cell`.
  /// Thread-safe when the forest does not record polylines.
  Id Root(Id cell);

  /// What RootBelow returns for a flow line it stopped.
  static constexpr Id Pending = -2;

  /// Root(cell), unless the flow first meets a Voronoi vertex whose distance to
  /// its samples is certainly at least sqrt(limitSq) (triangulation units):
  /// then Pending, and *boundSq is a certified lower bound of that squared
  /// distance. The distance grows along the flow, so the maximum reached lies
  /// above it: a flow line stopped there cannot end below it (deferred flow
  /// lines, DeferredFlowLines.h). Thread-safe as Root. `stopCell` (if given)
  /// receives the cell of that Voronoi vertex.
  Id RootBelow(Id cell, double limitSq, double* boundSq, Id* stopCell = nullptr);

  /// Appends the polyline of the flow from c_T (excluded) to its maximum, or to a
  /// stub pointing toward infinity. Flow lines merge: with `shareTails`, the
  /// polyline stops at the first Voronoi vertex an earlier call already drew, so
  /// that the union of all lines is stored once (linear size).
  void AppendPath(Id cell, std::vector<Point3>& out, bool shareTails);

  /// Circumcentre of a finite cell (for drawing; cached).
  Point3 Circumcentre(Id cell);

  /// Recording forests: NEXT of every cell on the flow lines from the Voronoi
  /// vertices of `starts` (finite cell ids), computed in parallel, so that
  /// Root and AppendPath afterwards only read them. The walks are what costs;
  /// each cell's is computed once, by the thread that claims it first.
  void PrecomputeSteps(const std::vector<Id>& starts, const Progress& progress, double from,
    double to);

  /// The cells whose NEXT needed exact arithmetic. Counted per cell, not per
  /// computation: threads racing on one chain may compute a cell twice.
  Id ExactFallbacks() const;

private:
  enum : std::int8_t
  {
    Unknown,
    ToMaximum,
    ToCell,
    ToInfinity
  };
  // 16 bytes: one per Delaunay cell, so its size shows in the memory per point.
  struct Step
  {
    std::int32_t Target = -1;     // node id (ToMaximum) or cell id (ToCell)
    std::uint32_t PathBegin = 0;  // into Paths[Buffer]: walk points (and the stub for ToInfinity)
    std::uint32_t PathCount = 0;
    std::int8_t Kind = Unknown;
    std::uint16_t Buffer = 0;     // which thread's buffer holds the points
  };
  const Step& Next(Id cell);
  /// NEXT(cell); appends its walk points to Paths[buffer] when recording.
  Step ComputeNext(Id cell, std::size_t buffer = 0);
  /// The double circumcentre of a finite cell, uncached (any thread).
  Point3 CircumcentreOf(Id cell) const;
  /// A lower bound of the squared circumradius of a finite cell (0 when
  /// doubles cannot bound it: flat cells).
  double SquaredRadiusAtLeast(Id cell) const;

  const Triangulation& Tri;
  const std::vector<std::int32_t>& MaximumOfCell;
  Id Infinity;
  double Stub;
  bool Record;
  bool ExactOnly;
  std::vector<Step> Steps; // memoised NEXT, only when recording
  // Per cell: ROOT (>= 0), unknown (-1), or NEXT alone, as -2 - cell (a chain
  // that RootBelow stopped: walked once, followed again without walking).
  std::vector<std::atomic<std::int32_t>> Roots;
  std::vector<std::atomic<std::uint8_t>> FellBack; // per cell: NEXT needed exact arithmetic
  std::vector<std::vector<Point3>> Paths; // one buffer per thread slot
  std::vector<Point3> Centres;
  std::vector<bool> HasCentre, Drawn;
};

} // namespace flowrecon

#endif
