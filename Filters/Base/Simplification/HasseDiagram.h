// A mutable Hasse diagram: In/Out lists with integer multiplicities, edited by
// cancellations (Simplification.h). Plain data, no VTK.
#ifndef flowrecon_HasseDiagram_h
#define flowrecon_HasseDiagram_h

#include "CompressedRows.h" // RowRange
#include "FlowComplex.h"
#include "ListArena.h"

#include <cstdint>
#include <vector>

namespace flowrecon
{

/// Throws InputError (naming arc `position`) unless `arc` joins two existing
/// nodes, goes up by one index and has a non-negative multiplicity.
void ValidateArc(const std::vector<Node>& nodes, const Arc& arc, std::size_t position);

/// ValidateArc's test without its message, on the nodes' indices by themselves
/// (NodeIndices.h): the passes over millions of arcs run it first.
inline bool IsValidArc(const std::vector<std::int8_t>& index, const Arc& a)
{
  const Id n = static_cast<Id>(index.size());
  return a.Lower >= 0 && a.Lower < n && a.Upper >= 0 && a.Upper < n &&
    index[static_cast<std::size_t>(a.Upper)] == index[static_cast<std::size_t>(a.Lower)] + 1 &&
    a.Multiplicity >= 0;
}

/// Every arc is stored twice, in Out(lower) and in In(upper), each copy knowing
/// where the other one is (while both ends exist). Removing an arc is then O(1) (swap-and-pop in both
/// lists), however large a degree grows: merged maxima and the maximum at
/// infinity collect thousands of arcs, and sorted lists would make
/// simplification quadratic. Lists are unordered. Finding an arc scans the
/// shorter of the two lists, which is short in flow complexes (a few entries)
/// even when the other one is huge.
///
/// The arcs out of index-0 nodes (from samples to their Gabriel edges, some
/// half of all arcs) are kept aside in one sorted list, not in In and Out: no
/// cancellation reads them or makes one (index-0 nodes are never cancelled),
/// and an edge's go with it.
class HasseDiagram
{
public:
  /// 12 bytes: flow complexes are limited to 2^31 nodes (FlowComplexBuilder).
  struct HalfArc
  {
    std::int32_t Node;           ///< the other end
    std::int32_t Multiplicity;
    std::uint32_t Twin;          ///< position of the mirror entry in the other end's list
  };
  using HalfArcs = RowRange<HalfArc>;

  /// Validates the arcs against `nodes` (ids in range, index goes up by one,
  /// multiplicity >= 0; duplicate arcs are merged by adding multiplicities) and
  /// throws InputError with a one-line message otherwise.
  HasseDiagram(const std::vector<Node>& nodes, const std::vector<Arc>& arcs);

  Id NodeCount() const { return static_cast<Id>(this->InLists.size()); }
  /// Ancestors / successors of `node` with multiplicities, in no particular
  /// order, but for the arcs out of index-0 nodes. The lists may still hold
  /// entries of removed nodes: skip them (IsRemoved).
  HalfArcs In(Id node) const { return Range(this->InLists[node]); }
  HalfArcs Out(Id node) const { return Range(this->OutLists[node]); }
  bool IsRemoved(Id node) const { return this->Removed[node] != 0; }
  /// 0 when there is no arc. Both nodes must not be removed.
  int Multiplicity(Id lower, Id upper) const;

  /// Adds one to the Z/2 incidence of (lower, upper): an arc of odd multiplicity
  /// disappears, an absent or even one becomes an arc of multiplicity 1 (the
  /// paper's "counting multiplicities modulo 2"). Returns the new multiplicity.
  /// Both nodes must not be removed.
  int FlipParity(Id lower, Id upper);
  /// Removes `node` and its arcs. Its lists are freed at once; the mirror
  /// entries in its neighbours' lists are left in place and skipped: erasing
  /// them one by one cost a cache miss per arc, and cancelled maxima and
  /// tube-spanning patches have thousands (measured: 13 M erasures, 40 % of
  /// the simplification of 10^5 torus-surface points).
  void Remove(Id node);

  /// Every arc, sorted by (Lower, Upper). Empties the diagram: its lists are
  /// freed while the arcs are made, so that the two do not add up.
  std::vector<Arc> TakeArcs();

private:
  /// A list in its arena (ListArena.h): 16 bytes a list, not a vector's 24 and
  /// a malloc'd block.
  struct List
  {
    HalfArc* Data = nullptr;
    std::uint32_t Size = 0, Capacity = 0;
  };
  static HalfArcs Range(const List& l) { return HalfArcs(l.Data, l.Data + l.Size); }
  /// Appends `h` to `list`, moving it to a larger block when full.
  static void Push(List& list, const HalfArc& h, ListArena<HalfArc>& arena);
  /// Lays each list out back to back with the capacity of its first arcs.
  static void LayOut(std::vector<List>& lists, const std::vector<std::uint32_t>& degree,
    ListArena<HalfArc>& arena);

  /// Position of `upper` in Out(lower), or -1.
  std::int64_t Find(Id lower, Id upper) const;
  void Insert(Id lower, Id upper, int multiplicity);
  /// Removes the arc at position `k` of Out(lower).
  void EraseOut(Id lower, std::size_t k);
  /// Merges arcs given more than once (adding their multiplicities).
  void MergeRepeatedArcs();

  // Two arenas: the In lists can be freed on their own (TakeArcs).
  ListArena<HalfArc> InArena, OutArena;
  std::vector<List> InLists, OutLists;
  std::vector<char> Removed;
  std::vector<Arc> SampleArcs; ///< the arcs out of index-0 nodes, sorted, repeats merged
};

} // namespace flowrecon

#endif
