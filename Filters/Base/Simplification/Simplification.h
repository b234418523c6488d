// Persistence-guided simplification of the Hasse diagram (paper §3.3):
// cancellations of incident pairs in order of increasing ratio V(b)/V(a).
#ifndef flowrecon_Simplification_h
#define flowrecon_Simplification_h

#include "CompressedRows.h"
#include "FlowComplex.h"
#include "Progress.h"

#include <utility>
#include <vector>

namespace flowrecon
{

/// One cancellation: Lower = a, Upper = b, dim b = dim a + 1.
struct CancelledPair
{
  Id Lower = -1;
  Id Upper = -1;
  double Ratio = 1;    ///< V(b) / V(a)
  double Birth = 0;    ///< V(a)
  double Death = 0;    ///< V(b)
  int PairType = 0;    ///< index of a
};

struct SimplificationResult
{
  /// One flag per original node: false for the nodes of a cancelled pair.
  std::vector<bool> Survives;
  /// The simplified diagram, original node ids, sorted by (Lower, Upper). Arcs
  /// no cancellation touched keep their multiplicity; arcs a cancellation
  /// touched have multiplicity 1 (arcs that became even were removed). Arcs to
  /// the maximum at infinity are kept.
  std::vector<Arc> Arcs;
  /// In the order they were made (non-decreasing Ratio).
  std::vector<CancelledPair> Pairs;
  /// Owners of the stable manifold of each cancelled node, one row per node:
  /// the surviving nodes it was redistributed to, transitively, sorted (node i
  /// owns nothing and has no owner when it survives). May contain the maximum
  /// at infinity, and may be empty when Out(a) was {b} alone. Stored as the
  /// arrays OwnerOffsets and Owners (SimplificationConversion.h).
  CompressedRows<Id> Owners;

  /// One row per pair, in the order of Pairs: its direct owners, the successors
  /// of Lower other than Upper when the pair was cancelled (sorted).
  CompressedRows<Id> DirectOwners;
  /// When asked for (recordLowers), one row per pair: the lowers x != Lower of
  /// odd arcs x -> Upper when it was cancelled, for 1-2 pairs (rows of 2-3 pairs
  /// are empty). With DirectOwners, enough to replay the cancellations on a
  /// node whose In list was not known (DeferredPatches.h).
  CompressedRows<Id> Lowers;
  /// When asked for (recordUppers), one row per pair: the y != Upper with odd arcs Lower -> y
  /// when it was cancelled, for 2-3 pairs (rows of 1-2 pairs are empty): what
  /// an arc x -> Upper turned into then (DeferredFlowLines.h).
  CompressedRows<Id> Uppers;
  bool HasLowers = false; ///< whether Lowers were recorded
  bool HasUppers = false; ///< whether Uppers were recorded

  RowRange<Id> OwnerRow(Id node) const { return this->Owners.Row(node); }
  std::vector<Id> OwnersOf(Id node) const
  {
    const RowRange<Id> row = this->OwnerRow(node);
    return std::vector<Id>(row.begin(), row.end());
  }
};

/// Cancels, while the least ratio V(b)/V(a) over the candidate arcs (a, b) does
/// not exceed `persistenceThreshold`, the pair with that least ratio (ties by
/// lower id, then upper id). Candidates are arcs of odd multiplicity whose lower
/// node has index >= 1 and whose upper node is not the maximum at infinity.
/// Any threshold below 1 (the paper's t_p = 0) cancels nothing. Throws InputError for an inconsistent diagram or a NaN threshold,
/// Aborted when `progress` asks to stop.
SimplificationResult Simplify(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
  double persistenceThreshold, const Progress& progress);

/// The same, taking the arcs over: they are freed once the diagram is built,
/// which lowers the peak memory of large clouds (the arcs are left empty).
SimplificationResult Simplify(const std::vector<Node>& nodes, std::vector<Arc>&& arcs,
  double persistenceThreshold, const Progress& progress, bool recordLowers = false,
  bool recordUppers = false);

/// Recomputes Owners from DirectOwners plus `extra` direct
/// owners, (pair position, node) entries: the successors a replay found that
/// the diagram did not hold when the pair was cancelled (deferred patches).
void ResolveOwners(SimplificationResult& result, const std::vector<std::pair<Id, Id>>& extra);

} // namespace flowrecon

#endif
