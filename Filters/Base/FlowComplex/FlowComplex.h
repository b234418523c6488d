// The flow complex of the distance function to a finite point set in R^3:
// critical points (Hasse nodes), their incidences (Hasse arcs) and the
// geometry of their stable and unstable manifolds. Plain data, no VTK.
#ifndef flowrecon_FlowComplex_h
#define flowrecon_FlowComplex_h

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace flowrecon
{

using Id = std::int64_t;
using Point3 = std::array<double, 3>;

/// A critical point of d_P, i.e. a node of the Hasse diagram. Ids are 32-bit in
/// the stored structures (nodes, arcs): the flow complex of a cloud has about 11
/// nodes and 35 arcs per point, so this halves its memory; the builder refuses
/// clouds whose complex would not fit (about 190 million points).
struct Node
{
  double Value = 0;               ///< d_P at the critical point (+inf for infinity)
  Point3 Location{ { 0, 0, 0 } }; ///< the critical point (for infinity: bounding-box centre)
  std::array<std::int32_t, 4> Simplex{ { -1, -1, -1, -1 } }; ///< sorted input ids of N(x), -1 padded
  int Index = 0;                  ///< 0..3; the maximum at infinity has index 3
  bool IsInfinity() const { return Simplex[0] < 0; }
};

/// A flow line (side 0 or 1, in the builder's order of the two cells of the
/// node's triangle) stopped at a point of distance Bound: the maximum it
/// reaches has a value above Bound (the distance grows along the flow).
struct PendingFlowLine
{
  std::int32_t Node = -1;
  std::int32_t Side = 0;
  float Bound = 0; ///< rounded down (12 bytes a line: they are most lines)
};

/// Arc of the Hasse diagram from an index-i node to an index-(i+1) node.
/// Multiplicity counts how many times the flow arrives: for 1->2 arcs the number of
/// descending walks of the upper stable manifold ending on the Gabriel edge, for
/// 2->3 arcs how many of the two unstable flow lines reach the maximum.
struct Arc
{
  std::int32_t Lower = -1;
  std::int32_t Upper = -1;
  std::int32_t Multiplicity = 1;

  Arc() = default;
  Arc(Id lower, Id upper, Id multiplicity)
    : Lower(static_cast<std::int32_t>(lower))
    , Upper(static_cast<std::int32_t>(upper))
    , Multiplicity(static_cast<std::int32_t>(multiplicity))
  {
  }
};

/// One unstable flow line of an index-2 point, from the point to a maximum.
struct FlowLine
{
  Id Node = -1;              ///< the index-2 node it leaves
  Id Target = -1;            ///< the maximum (possibly the maximum at infinity)
  std::vector<Point3> Points; ///< polyline; toward infinity: ends on a stub, cut at the DrawingBox
};

/// What was done about degenerate input (docs/algorithm.md §2.3).
struct DegeneracyReport
{
  Id InputPoints = 0;
  Id DuplicatePoints = 0;     ///< merged into their first occurrence
  Id RightAngles = 0;         ///< right triangles seen in the first attempt
  Id ApexOnSphere = 0;        ///< apex on a facet's diametral sphere (first attempt)
  Id WalkTies = 0;            ///< ties or zero steps met by a walk (first attempt)
  int Attempts = 1;           ///< 1 = no perturbation was needed
  std::uint64_t Seed = 1;     ///< seed of the perturbation (with Attempts, enough to redo it)
  double PerturbationMagnitude = 0; ///< max displacement applied to each coordinate
  /// Critical points of a perturbed run whose simplex has no critical point on
  /// the input (docs/algorithm.md §2.3): left at their perturbed value. Others
  /// are evaluated exactly on the input points.
  Id PerturbedValues = 0;
  Id ExactFallbacks = 0;      ///< walks whose interval filter failed and were redone exactly
  bool Perturbed() const { return Attempts > 1; }
};

/// Wall-clock seconds per phase.
struct Timings
{
  double Delaunay = 0, CriticalPoints = 0, StableManifolds = 0, UnstableManifolds = 0,
         Assembly = 0, Total = 0;
};

/// The filtration order of nodes a and b: by critical value, then index (a
/// face before its cofaces when values tie), then id (determinism).
inline bool FiltrationLess(const std::vector<Node>& nodes, Id a, Id b)
{
  const Node& x = nodes[a];
  const Node& y = nodes[b];
  if (x.Value != y.Value)
  {
    return x.Value < y.Value;
  }
  return x.Index != y.Index ? x.Index < y.Index : a < b;
}

/// The persistence ratio V(upper) / V(lower) of an arc or a pair (paper §3):
/// +inf when the lower value is not positive (index-0 nodes have value 0).
/// Not clamped: the queues of simplification and reconstruction take it as it
/// is, so that rounding of nearly tied values reorders nothing.
inline double PersistenceRatio(double upper, double lower)
{
  return lower > 0 ? upper / lower : HUGE_VAL;
}

/// The same, never below 1: ratios are >= 1 in exact arithmetic, and rounding
/// of nearly tied values (or a shorter sibling, for horizontal extension) must
/// not show one below (the arcs' Ratio array, horizontal priorities).
inline double PersistenceRatioAtLeastOne(double upper, double lower)
{
  return std::max(1.0, PersistenceRatio(upper, lower));
}

struct FlowComplex
{
  /// Vertices of all manifold geometry: the input points first (ids = input ids),
  /// then constructed points (critical points and walk vertices).
  std::vector<Point3> Points;
  Id NumberOfInputPoints = 0;
  /// Representative[i] = the input id that stands for input point i (duplicates merged).
  std::vector<Id> Representative;

  /// Nodes grouped by index (0, 1, 2, 3), the maximum at infinity last; within an
  /// index, in a deterministic order that follows the samples along a Hilbert curve.
  std::vector<Node> Nodes;
  Id InfinityNode = -1;
  /// Point id (into Points) of each node's critical point (-1 for index 1,
  /// infinity and nodes whose geometry was not drawn); empty when the
  /// stable-manifold geometry was not computed. Stored as the CriticalPoints
  /// array StableManifoldPointId.
  std::vector<Id> NodePoint;
  /// Arcs: 0->1 arcs first, then 1->2, then 2->3, each group in node order
  /// (deterministic); one entry per pair of nodes.
  std::vector<Arc> Arcs;

  /// Stable manifolds. Index 0: the sample itself; index 1: its Gabriel edge
  /// (Simplex[0], Simplex[1]). Index 2: triangles over Points, grouped by node.
  std::vector<std::array<Id, 3>> Triangles;
  std::vector<Id> TriangleNode;
  /// Index 3: tetrahedra (cone from the maximum over its boundary patches, fins once).
  std::vector<std::array<Id, 4>> Tetrahedra;
  std::vector<Id> TetrahedronNode;

  /// Index-2 nodes (sorted) whose patches were not walked, so that their 1-2
  /// arcs are missing (BuildOptions::DeferPatchesAboveRatio): every ratio of
  /// those arcs is at least DeferralRatio. Empty for a complete diagram.
  std::vector<Id> DeferredPatches;
  double DeferralRatio = HUGE_VAL;

  /// Flow lines of index-2 nodes not followed to their maximum
  /// (BuildOptions::DeferFlowLinesAboveRatio), sorted: their 2-3 arcs are
  /// missing. Empty for a complete diagram.
  std::vector<PendingFlowLine> PendingFlowLines;

  /// Unstable manifolds of index-2 nodes: two flow lines each.
  std::vector<FlowLine> FlowLines;

  DegeneracyReport Report;
  Timings Time;

  /// Number of nodes of each index 0..3, the maximum at infinity not counted.
  std::array<Id, 4> CountByIndex() const
  {
    std::array<Id, 4> n{ { 0, 0, 0, 0 } };
    for (const Node& node : this->Nodes)
    {
      if (!node.IsInfinity())
      {
        ++n[node.Index];
      }
    }
    return n;
  }
};

} // namespace flowrecon

#endif
