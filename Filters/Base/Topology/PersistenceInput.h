// The input of the fast persistence (Persistence.cpp): the finite nodes ranked
// in filtration order within each index, and the boundaries that H0, H1 and H2
// need, gathered from the arcs in parallel while checking what the fast path
// assumes. Internal to the core.
#ifndef flowrecon_PersistenceInput_h
#define flowrecon_PersistenceInput_h

#include "FlowComplex.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

namespace flowrecon
{
namespace persistence
{

using Int = std::int32_t;

/// Rank of a node among the finite nodes of its index; Index -1 for infinity.
struct Slot
{
  Int Rank = -1;
  Int Index = -1;
};

struct Ranking
{
  std::vector<Slot> Of;                 ///< per node
  std::array<std::vector<Int>, 4> Node; ///< Node[k][rank] = node id
  std::vector<Int> Index2ById;          ///< the index-2 nodes in id order
};

template <class Body>
void ParallelRange(std::size_t n, const Body& body)
{
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const auto& range) {
    for (std::size_t i = range.begin(); i < range.end(); ++i)
    {
      body(i);
    }
  });
}

/// Sorts the finite nodes of each index by (value, id), the filtration order
/// within an index. False if the fast path does not apply.
bool RankNodes(const std::vector<Node>& nodes, Ranking& r);

/// At most two ends per cell (lower ends of index-1 nodes, finite upper ends of
/// index-2 nodes). Relaxed atomics: Add for concurrent writers, Set for one.
struct TwoEnds
{
  explicit TwoEnds(std::size_t n)
    : Count(n)
    , At(2 * n)
  {
  }
  /// False when a third end arrives.
  bool Add(Int cell, Int end)
  {
    const Int c = this->Count[cell].fetch_add(1, std::memory_order_relaxed);
    if (c >= 2)
    {
      return false;
    }
    this->At[2 * static_cast<std::size_t>(cell) + c].store(end, std::memory_order_relaxed);
    return true;
  }
  void Set(Int cell, Int count, Int first, Int second)
  {
    this->Count[cell].store(count, std::memory_order_relaxed);
    this->At[2 * static_cast<std::size_t>(cell)].store(first, std::memory_order_relaxed);
    this->At[2 * static_cast<std::size_t>(cell) + 1].store(second, std::memory_order_relaxed);
  }
  Int Size(Int cell) const { return this->Count[cell].load(std::memory_order_relaxed); }
  Int End(Int cell, int k) const
  {
    return this->At[2 * static_cast<std::size_t>(cell) + k].load(std::memory_order_relaxed);
  }
  /// False when some cell has the same end twice (a repeated arc).
  bool Distinct() const
  {
    for (std::size_t c = 0; c < this->Count.size(); ++c)
    {
      const Int cell = static_cast<Int>(c);
      if (this->Size(cell) == 2 && this->End(cell, 0) == this->End(cell, 1))
      {
        return false;
      }
    }
    return true;
  }
  void Clear()
  {
    for (auto& c : this->Count)
    {
      c.store(0, std::memory_order_relaxed);
    }
  }

  std::vector<std::atomic<Int>> Count;
  std::vector<std::atomic<Int>> At;
};

/// What the fast path takes from the arcs of D (odd multiplicity, finite ends).
struct Boundaries
{
  explicit Boundaries(const std::array<std::size_t, 4>& n)
    : EdgeEnds(n[1])
    , FaceEnds(n[2])
    , Begin(n[2] + 1, 0)
    , Faces(n[2], 0)
  {
  }
  TwoEnds EdgeEnds; ///< index-0 ranks below each index-1 node
  TwoEnds FaceEnds; ///< finite index-3 ranks above each index-2 node
  /// The faces of index-2 node f: Rows[Begin[f] .. Begin[f] + Faces[f]), node ids
  /// when gathered by counting, else (Runs) the odd arcs of its run, arcs
  /// [RunBegin[f], RunBegin[f] + RunLength[f]); room for them in Rows.
  std::vector<std::int64_t> Begin;
  std::vector<Int> Faces;
  std::vector<Int> Rows;
  bool Runs = false;
  std::vector<std::atomic<std::int64_t>> RunBegin;
  std::vector<std::atomic<Int>> RunLength;
};

enum class Gathering
{
  Done,
  NotGrouped,  ///< some node's arcs are not consecutive: gather by counting
  Unusable,    ///< outside what the fast path assumes
  MissingNode, ///< an arc names a node that does not exist
};

/// What a parallel pass found: runs of arcs (GatherBoundaries), and whether the
/// fast path applies.
struct Tally
{
  std::size_t Runs[3] = { 0, 0, 0 }; ///< runs into index-1, into index-2, out of index-2 nodes
  bool Usable = true;
  bool MissingNode = false;
  void Join(const Tally& o)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Runs[k] += o.Runs[k];
    }
    this->Usable = this->Usable && o.Usable;
    this->MissingNode = this->MissingNode || o.MissingNode;
  }
};

/// Fills `b` from the arcs of D (odd multiplicity, finite ends): by runs when
/// each node's arcs are consecutive (as the flow complex lists them; `grouped`
/// says so), else by counting. Done, Unusable or MissingNode.
Gathering GatherBoundaries(const std::vector<Arc>& arcs, const Ranking& rank,
  const std::array<std::size_t, 4>& n, Boundaries& b, bool& grouped);

} // namespace persistence
} // namespace flowrecon

#endif
