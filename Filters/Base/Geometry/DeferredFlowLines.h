// Deferred flow lines (BuildOptions::DeferFlowLinesAboveRatio), followed when a
// stage needs them: the unstable-manifold counterpart of DeferredPatches.h. On
// samples of surfaces most flow lines of index-2 points run from the surface to
// the medial axis, across long chains of Voronoi facets, yet their 2-3 arcs have
// ratios far above any t_r a user tries.
//
// Why the capped run stays exact. A line stopped at distance B reaches a
// maximum of value > B. Over Z/2 the simplification acts on the row of a node x
// by row operations, so x's final arcs follow from its raw arcs by replaying the
// 2-3 cancellations (Replay below); what a pending line changes lies among the
// maxima its replay can reach, whose values are >= Low(B) (LowerBound). Hence:
// - the simplification is the eager one when no pair has a lower with pending
//   lines (its Out list is moved to others) and every pending x has
//   Low(B) > t_p V(x) (none of its arcs it changes is a candidate): checked
//   after it (SetSimplification), else Degenerate makes the caller redo the run
//   without deferral;
// - upflow below the cap is unchanged for nodes with Low(B) >= cap V(x); the
//   others are followed before the reconstruction;
// - a maximum m inserted below the cap needs In(m): the lines with Low(B) <= V(m)
//   are followed when m is inserted (InChangesUpTo).
#ifndef flowrecon_DeferredFlowLines_h
#define flowrecon_DeferredFlowLines_h

#include "FlowComplex.h"
#include "Reconstruction.h"
#include "Simplification.h"

#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace flowrecon
{

class Retriangulation;
class SuccessorForest;

class DeferredFlowLines
{
public:
  /// `fc`: a complex with pending flow lines; `rawArcs`: its 2-3 arcs as built
  /// (before any simplification), grouped by lower node in increasing order;
  /// `re`: its triangulation, which must outlive this object (the other
  /// arguments are copied from). Throws InputError when they do not fit.
  DeferredFlowLines(
    const FlowComplex& fc, const std::vector<Arc>& rawArcs, const Retriangulation& re);
  ~DeferredFlowLines();

  /// Index-2 nodes with a pending line, sorted.
  const std::vector<Id>& Nodes() const { return this->Pending; }
  bool IsPending(Id node) const; ///< has a line not followed yet
  Id LinesDeferred() const { return static_cast<Id>(this->Lines.size()); }
  Id LinesFollowed() const { return this->Followed; }

  /// Follows every line of `nodes` (others are skipped) to its maximum, in
  /// parallel. Throws Degenerate when a walk meets a tie.
  void Follow(const std::vector<Id>& nodes);

  /// Follows the nodes with a line whose bound is <= value: every raw arc
  /// into a maximum of value <= `value` is then known (for drawing cones).
  void FollowBoundsUpTo(double value);

  /// The raw 2-3 arcs of the nodes followed so far, as the builder makes them
  /// (side order, one arc of multiplicity 2 when both lines meet), grouped by
  /// lower node.
  std::vector<Arc> FollowedRawArcs() const;

  /// The two ends of the lines of a node not followed yet (EndsAbove).
  struct Ends
  {
    Id Node;
    std::array<Id, 2> End; ///< by side: a maximum, or -2 - c for the cell c of a stop
  };

  /// Where lines end at one level (EndsAbove), by line position, -1 when not
  /// walked yet: kept for the next object made from the same build's pending
  /// lines (the run of another t_p), which has the same lines in the same
  /// places and need not walk them again.
  struct EndMemo
  {
    double LevelSq = 0;
    std::uint64_t Triangulation = 0; ///< its Serial()
    std::vector<std::int32_t> End;
  };

  /// The nodes not followed yet (in increasing order), their lines walked only
  /// until a Voronoi vertex certainly farther than sqrt(levelSq) from the
  /// samples (the stop), or to their maximum when there is none on the way
  /// (their nodes stay pending). For the topology: where a line goes beyond a
  /// level no reconstruction reaches is said by ExteriorRegions. With `only`
  /// (a flag per node), only the flagged nodes. With `memo`, the ends it
  /// holds for this level are read, not walked, and the others are added
  /// (it is reset when it was made for another level or triangulation).
  std::vector<Ends> EndsAbove(
    double levelSq, const std::vector<char>* only = nullptr, EndMemo* memo = nullptr);

  /// `arcs` (grouped by index of the lower node, the 2-3 ones by lower node)
  /// with the 2-3 arcs of the nodes followed so far replaced by their raw arcs.
  void CompleteRawArcs(std::vector<Arc>& arcs) const;

  /// Records the simplification the caller made (null: none) on the raw arcs,
  /// with pending lines left out, and checks that it is the eager one (see
  /// above); throws Degenerate when that cannot be shown. Needs Uppers.
  void SetSimplification(const SimplificationResult* s, double persistenceThreshold);

  /// A lower bound of every value the replay of a line stopped at `bound` can
  /// reach (after SetSimplification).
  double LowerBound(double bound) const;

  /// The pending nodes x with LowerBound(bound) < ratio * V(x) for a line of
  /// theirs: whose arcs below `ratio` the pending lines may change.
  std::vector<Id> NodesBelowRatio(double ratio) const;

  /// The final arcs (simplified) of a followed node that survives:
  /// (maximum, multiplicity) sorted, as the eager simplification gives them.
  std::vector<std::pair<Id, int>> FinalArcs(Id x) const;

  /// `simplifiedArcs` (sorted by (Lower, Upper)) with the 2-3 arcs of the
  /// surviving nodes followed since SetSimplification replaced by their
  /// FinalArcs (those followed before were in the simplification's input).
  void CompleteSimplifiedArcs(std::vector<Arc>& simplifiedArcs);

  /// Follows the lines not followed yet whose LowerBound is <= value (all
  /// lines of their nodes), and returns how the In lists of maxima change,
  /// against `simplifiedArcs` (sorted by (Lower, Upper)), for the surviving
  /// nodes followed now: what LateArcs::FlowLinesInto returns. With `run`,
  /// the nodes it has inserted are passed over for good: a maximum's
  /// regularization adds nothing through them, and their lines stay pending
  /// (the topology ends them at the level their presence needs,
  /// TopologyInput.h). On surface samples at t_p 0 the inner maxima enter
  /// after nearly every surface patch: their lines were most of the run.
  std::vector<InListChange> InChangesUpTo(double value, const std::vector<Arc>& simplifiedArcs,
    const std::vector<Insertion>* run = nullptr);

private:
  struct Line
  {
    std::int32_t Node, Side;
    float Bound;
    std::int32_t Target; ///< -1 until followed
  };
  const Retriangulation& Re;
  std::vector<double> Values; ///< of the nodes
  Id Base3 = 0, InfinityNode = -1; ///< maxima: [Base3, InfinityNode]
  std::vector<Line> Lines;       ///< sorted by (Node, Side)
  std::vector<Id> Pending;       ///< distinct nodes of Lines
  std::vector<Id> PendingBegin;  ///< per pending node: its first line
  std::vector<std::int32_t> Other; ///< per pending node: the followed line's maximum (-1: none)
  std::vector<char> Done;          ///< per pending node: followed
  bool Simplified = false;         ///< SetSimplification was called
  std::vector<Id> FollowedSince;   ///< nodes followed after it, not yet completed
  /// (LowerBound of the least line bound, position) of the pending nodes, sorted.
  std::vector<std::pair<double, std::size_t>> ByLowerBound;
  std::size_t NextByBound = 0;
  Id Followed = 0;
  SuccessorForest* Forest = nullptr; ///< Re.Flow(): shared with the build and the other runs

  // From SetSimplification:
  std::vector<std::int32_t> RemovedAt;   ///< per node: the 2-3 pair removing it as upper, or -1
  CompressedRows<Id> Uppers;             ///< per pair (see SimplificationResult)
  std::vector<bool> Survives;
  std::vector<double> SortedValues, SuffixLow; ///< maxima by value; min LowExp from there on

  std::size_t Position(Id node) const; ///< in Pending; npos when absent
  /// Appends the raw 2-3 arcs of the followed Pending[k].
  void AppendRawRow(std::size_t k, std::vector<Arc>& arcs) const;
  void MakeForest(); ///< (serial) Forest, before the lines are followed in parallel
  double LeastBound(std::size_t k) const;
};

/// Replaces the rows of `arcs` from position `tail` on (sorted by lower node)
/// by `rows` (sorted by lower node): a node with a row in `rows` keeps only it.
void ReplaceRows(std::vector<Arc>& arcs, std::size_t tail, const std::vector<Arc>& rows);

} // namespace flowrecon

#endif
