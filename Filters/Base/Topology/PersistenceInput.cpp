#include "PersistenceInput.h"

#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

namespace flowrecon
{
namespace persistence
{

namespace
{

/// Doubles as unsigned integers in the same order (-0 and +0 equal; no NaN).
std::uint64_t OrderedBits(double v)
{
  if (v == 0)
  {
    return std::uint64_t(1) << 63;
  }
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  return (bits >> 63) ? ~bits : bits | (std::uint64_t(1) << 63);
}

struct SortKey
{
  std::uint64_t Value; ///< OrderedBits of the value
  Int Id;
};

/// Sorts keys that come in increasing Id by (Value, Id): a stable LSD radix sort
/// on Value, 16 bits at a time, skipping the digits all keys share.
void RadixSort(std::vector<SortKey>& keys)
{
  constexpr int Digits = 4;
  constexpr std::size_t Buckets = std::size_t(1) << 16;
  std::vector<std::size_t> count(Digits * Buckets, 0);
  for (const SortKey& k : keys)
  {
    for (int d = 0; d < Digits; ++d)
    {
      ++count[d * Buckets + ((k.Value >> (16 * d)) & 0xffff)];
    }
  }
  std::vector<SortKey> other;
  for (int d = 0; d < Digits; ++d)
  {
    std::size_t* c = count.data() + d * Buckets;
    if (std::any_of(c, c + Buckets, [&](std::size_t x) { return x == keys.size(); }))
    {
      continue; // one digit for all: already in order
    }
    std::size_t sum = 0;
    for (std::size_t b = 0; b < Buckets; ++b)
    {
      sum += c[b];
      c[b] = sum - c[b];
    }
    other.resize(keys.size());
    for (const SortKey& k : keys)
    {
      other[c[(k.Value >> (16 * d)) & 0xffff]++] = k;
    }
    keys.swap(other);
  }
}

} // namespace

/// Sorts the finite nodes of each index by (value, id), the filtration order
/// within an index. False if the fast path does not apply.
bool RankNodes(const std::vector<Node>& nodes, Ranking& r)
{
  if (nodes.size() >= static_cast<std::size_t>(std::numeric_limits<Int>::max()))
  {
    return false;
  }
  // Blocks of nodes count their nodes of each index, then write their keys at
  // their place: the keys of an index come in id order.
  const std::size_t n = nodes.size();
  const std::size_t blocks = std::max<std::size_t>(1, std::min<std::size_t>(256, n / 65536));
  std::vector<std::array<std::size_t, 4>> count(blocks + 1, { { 0, 0, 0, 0 } });
  std::atomic<bool> ok{ true };
  auto blockRange = [&](std::size_t b) {
    return std::make_pair(n * b / blocks, n * (b + 1) / blocks);
  };
  ParallelRange(blocks, [&](std::size_t b) {
    const auto range = blockRange(b);
    for (std::size_t i = range.first; i < range.second; ++i)
    {
      const Node& x = nodes[i];
      if (!x.IsInfinity())
      {
        if (x.Index < 0 || x.Index > 3 || std::isnan(x.Value))
        {
          ok = false;
          return;
        }
        ++count[b + 1][x.Index];
      }
    }
  });
  if (!ok)
  {
    return false;
  }
  for (std::size_t b = 0; b < blocks; ++b)
  {
    for (int k = 0; k < 4; ++k)
    {
      count[b + 1][k] += count[b][k];
    }
  }
  std::array<std::vector<SortKey>, 4> keys;
  for (int k = 0; k < 4; ++k)
  {
    keys[k].resize(count[blocks][k]);
  }
  r.Of.assign(n, Slot{});
  ParallelRange(blocks, [&](std::size_t b) {
    std::array<std::size_t, 4> at = count[b];
    const auto range = blockRange(b);
    for (std::size_t i = range.first; i < range.second; ++i)
    {
      const Node& x = nodes[i];
      if (!x.IsInfinity())
      {
        keys[x.Index][at[x.Index]++] = { OrderedBits(x.Value), static_cast<Int>(i) };
      }
    }
  });
  r.Index2ById.resize(keys[2].size());
  ParallelRange(keys[2].size(), [&](std::size_t j) { r.Index2ById[j] = keys[2][j].Id; });
  tbb::parallel_for(0, 4, [&](int k) {
    std::vector<SortKey>& key = keys[k];
    RadixSort(key);
    r.Node[k].resize(key.size());
    ParallelRange(key.size(), [&](std::size_t j) {
      r.Node[k][j] = key[j].Id;
      r.Of[key[j].Id] = { static_cast<Int>(j), k };
    });
    std::vector<SortKey>().swap(key);
  });
  return true;
}

namespace
{

/// Checks arc i alone: a D arc (odd, finite ends) goes from index k to k + 1.
void CheckArc(const Arc& a, Id nodeCount, const std::vector<Slot>& of, Tally& t)
{
  if (a.Multiplicity % 2 != 1)
  {
    return;
  }
  if (a.Lower < 0 || a.Lower >= nodeCount || a.Upper < 0 || a.Upper >= nodeCount)
  {
    t.MissingNode = true;
    return;
  }
  const Slot lo = of[a.Lower], up = of[a.Upper];
  if (lo.Index >= 0 && up.Index >= 0 && up.Index != lo.Index + 1)
  {
    t.Usable = false;
  }
}

bool Odd(const Arc& a)
{
  return a.Multiplicity % 2 == 1;
}

std::size_t CountSet(const std::vector<std::atomic<std::uint8_t>>& v)
{
  return static_cast<std::size_t>(std::count_if(v.begin(), v.end(),
    [](const std::atomic<std::uint8_t>& x) { return x.load(std::memory_order_relaxed) != 0; }));
}

/// The flow complex lists the arcs of a node together: the arcs into an index-1
/// node, into an index-2 node, out of an index-2 node. Each such run of arcs is
/// read by the thread that meets its first arc, with no atomic read-modify-write;
/// each node must have at most one run of each kind (else NotGrouped). An arc is
/// checked with its run (into index 1 or 2) or alone (the others).
class RunReader
{
public:
  RunReader(const std::vector<Arc>& arcs, const std::vector<Slot>& of,
    const std::array<std::size_t, 4>& n, Boundaries& b)
    : Arcs(arcs)
    , Of(of)
    , B(b)
    , NodeCount(static_cast<Id>(of.size()))
    , SeenIn1(n[1])
    , SeenOut2(n[2])
  {
  }

  /// Arc i: the run it starts, or the arc alone.
  void Read(std::size_t i, Tally& t)
  {
    const Arc& a = this->Arcs[i];
    const Slot up = this->Valid(a.Upper) ? this->Of[a.Upper] : Slot{ -1, -2 };
    if (up.Index == 1 || up.Index == 2)
    {
      if (i == 0 || this->Arcs[i - 1].Upper != a.Upper) // else read with its run
      {
        this->ReadRunInto(i, up, t);
      }
      return;
    }
    // An arc into index 0, 3, infinity, or a node that does not exist.
    if (Odd(a))
    {
      if (up.Index == -2 || !this->Valid(a.Lower))
      {
        t.MissingNode = true;
        return;
      }
      const Slot lo = this->Of[a.Lower];
      t.Usable = t.Usable && (lo.Index < 0 || up.Index < 0 || up.Index == lo.Index + 1);
    }
    if (this->Valid(a.Lower) && (i == 0 || this->Arcs[i - 1].Lower != a.Lower) &&
      this->Of[a.Lower].Index == 2)
    {
      // The arcs out of an index-2 node (an arc into index 1 or 2 out of it
      // is wrong, and found with the runs into those nodes).
      this->ReadRunOutOf(i, this->Of[a.Lower].Rank, t);
    }
  }

  /// Whether every node met had one run of each kind.
  bool Grouped(const Tally& t) const
  {
    const std::size_t runsIn2 =
      static_cast<std::size_t>(std::count_if(this->B.RunLength.begin(), this->B.RunLength.end(),
        [](const std::atomic<Int>& x) { return x.load(std::memory_order_relaxed) > 0; }));
    return t.Runs[0] == CountSet(this->SeenIn1) && t.Runs[1] == runsIn2 &&
      t.Runs[2] == CountSet(this->SeenOut2);
  }

private:
  bool Valid(Id node) const { return node >= 0 && node < this->NodeCount; }

  /// The run into index-1 or index-2 node `up` that starts at arc i.
  void ReadRunInto(std::size_t i, Slot up, Tally& t)
  {
    const Id upper = this->Arcs[i].Upper;
    std::size_t j = i + 1;
    while (j < this->Arcs.size() && this->Arcs[j].Upper == upper)
    {
      ++j;
    }
    if (up.Index == 2)
    {
      this->B.RunBegin[up.Rank].store(static_cast<std::int64_t>(i), std::memory_order_relaxed);
      this->B.RunLength[up.Rank].store(static_cast<Int>(j - i), std::memory_order_relaxed);
      ++t.Runs[1];
      return; // its arcs are read and checked with the faces
    }
    Int ends[2] = { -1, -1 }, count = 0;
    for (std::size_t k = i; k < j; ++k)
    {
      const Arc& e = this->Arcs[k];
      if (!Odd(e))
      {
        continue;
      }
      if (!this->Valid(e.Lower))
      {
        t.MissingNode = true;
        continue;
      }
      const Slot lo = this->Of[e.Lower];
      if (lo.Index == 0 && count < 2)
      {
        ends[count] = lo.Rank;
      }
      count += lo.Index == 0 ? 1 : 0;
      t.Usable = t.Usable && (lo.Index == 0 || lo.Index == -1);
    }
    t.Usable = t.Usable && count <= 2;
    this->B.EdgeEnds.Set(up.Rank, std::min<Int>(count, 2), ends[0], ends[1]);
    this->SeenIn1[up.Rank].store(1, std::memory_order_relaxed);
    ++t.Runs[0];
  }

  /// The run out of index-2 node of rank f that starts at arc i.
  void ReadRunOutOf(std::size_t i, Int f, Tally& t)
  {
    const Id lower = this->Arcs[i].Lower;
    Int ends[2] = { -1, -1 }, count = 0;
    for (std::size_t k = i; k < this->Arcs.size() && this->Arcs[k].Lower == lower; ++k)
    {
      const Arc& e = this->Arcs[k];
      if (Odd(e) && this->Valid(e.Upper) && this->Of[e.Upper].Index == 3)
      {
        if (count < 2)
        {
          ends[count] = this->Of[e.Upper].Rank;
        }
        ++count;
      }
    }
    t.Usable = t.Usable && count <= 2;
    this->B.FaceEnds.Set(f, std::min<Int>(count, 2), ends[0], ends[1]);
    this->SeenOut2[f].store(1, std::memory_order_relaxed);
    ++t.Runs[2];
  }

  const std::vector<Arc>& Arcs;
  const std::vector<Slot>& Of;
  Boundaries& B;
  const Id NodeCount;
  std::vector<std::atomic<std::uint8_t>> SeenIn1, SeenOut2; ///< runs met, per node
};

/// Gathers by runs (RunReader), or says why not.
Gathering GatherByRuns(const std::vector<Arc>& arcs, const std::vector<Slot>& of,
  const std::vector<Int>& index2ById, const std::array<std::size_t, 4>& n, Boundaries& b)
{
  RunReader reader(arcs, of, n, b);
  std::vector<std::atomic<std::int64_t>>(n[2]).swap(b.RunBegin);
  std::vector<std::atomic<Int>>(n[2]).swap(b.RunLength); // arcs into each index-2 node
  const Tally tally = tbb::parallel_reduce(
    tbb::blocked_range<std::size_t>(0, arcs.size(), 4096), Tally(),
    [&](const tbb::blocked_range<std::size_t>& r, Tally t) {
      for (std::size_t i = r.begin(); i < r.end(); ++i)
      {
        reader.Read(i, t);
      }
      return t;
    },
    [](Tally x, const Tally& y) {
      x.Join(y);
      return x;
    });
  if (tally.MissingNode)
  {
    return Gathering::MissingNode;
  }
  if (!tally.Usable)
  {
    return Gathering::Unusable;
  }
  if (!reader.Grouped(tally))
  {
    return Gathering::NotGrouped;
  }
  // Room for the faces, node after node in id order (the order they are read).
  std::int64_t at = 0;
  for (const Int id : index2ById)
  {
    const Int f = of[id].Rank;
    b.Begin[f] = at;
    at += b.RunLength[f].load(std::memory_order_relaxed);
  }
  b.Rows.resize(static_cast<std::size_t>(at));
  b.Runs = true;
  return Gathering::Done;
}

/// The general way: atomic counters per node, and a second pass for the face ids.
Gathering GatherByCounting(const std::vector<Arc>& arcs, const std::vector<Slot>& of,
  const std::array<std::size_t, 4>& n, Boundaries& b)
{
  const Id nodeCount = static_cast<Id>(of.size());
  b.EdgeEnds.Clear();
  b.FaceEnds.Clear();
  std::vector<std::atomic<Int>> count(n[2]);
  // Calls body(lower slot, upper slot) for every arc of D.
  auto forEachArc = [&](const auto& body) {
    return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, arcs.size(), 4096), Tally(),
      [&](const tbb::blocked_range<std::size_t>& r, Tally t) {
        for (std::size_t i = r.begin(); i < r.end(); ++i)
        {
          const Arc& a = arcs[i];
          CheckArc(a, nodeCount, of, t);
          if (a.Multiplicity % 2 == 1 && a.Lower >= 0 && a.Lower < nodeCount && a.Upper >= 0 &&
            a.Upper < nodeCount && of[a.Lower].Index >= 0 &&
            of[a.Upper].Index == of[a.Lower].Index + 1)
          {
            t.Usable = body(of[a.Lower], of[a.Upper]) && t.Usable;
          }
        }
        return t;
      },
      [](Tally x, const Tally& y) {
        x.Join(y);
        return x;
      });
  };
  const Tally tally = forEachArc([&](Slot lo, Slot up) {
    switch (lo.Index)
    {
      case 0:
        return b.EdgeEnds.Add(up.Rank, lo.Rank);
      case 1:
        count[up.Rank].fetch_add(1, std::memory_order_relaxed);
        return true;
      default:
        return b.FaceEnds.Add(lo.Rank, up.Rank);
    }
  });
  if (tally.MissingNode)
  {
    return Gathering::MissingNode;
  }
  if (!tally.Usable)
  {
    return Gathering::Unusable;
  }
  for (std::size_t f = 0; f < n[2]; ++f)
  {
    b.Faces[f] = count[f].load(std::memory_order_relaxed);
    b.Begin[f + 1] = b.Begin[f] + b.Faces[f];
    count[f].store(0, std::memory_order_relaxed);
  }
  b.Rows.resize(static_cast<std::size_t>(b.Begin[n[2]]));
  // The face ids (forEachArc passes slots: a second look at the arcs here).
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, arcs.size(), 4096), [&](const auto& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i)
    {
      const Arc& a = arcs[i];
      if (a.Multiplicity % 2 == 1 && of[a.Lower].Index == 1 && of[a.Upper].Index == 2)
      {
        const Int f = of[a.Upper].Rank;
        b.Rows[b.Begin[f] + count[f].fetch_add(1, std::memory_order_relaxed)] = a.Lower;
      }
    }
  });
  return Gathering::Done;
}
} // namespace

Gathering GatherBoundaries(const std::vector<Arc>& arcs, const Ranking& rank,
  const std::array<std::size_t, 4>& n, Boundaries& b, bool& grouped)
{
  Gathering gathered = GatherByRuns(arcs, rank.Of, rank.Index2ById, n, b);
  grouped = gathered == Gathering::Done;
  if (gathered == Gathering::NotGrouped)
  {
    gathered = GatherByCounting(arcs, rank.Of, n, b);
  }
  return gathered;
}

} // namespace persistence
} // namespace flowrecon
