#include "Persistence.h"

#include "PersistenceInput.h"
#include "UnionFind.h"
#include "Z2ColumnReduction.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <utility>

namespace flowrecon
{

namespace
{

/// The output order: dimension, birth value, death value, birth node (unique).
bool PairLess(const PersistencePair& a, const PersistencePair& b)
{
  if (a.Dimension != b.Dimension)
  {
    return a.Dimension < b.Dimension;
  }
  if (a.BirthValue != b.BirthValue)
  {
    return a.BirthValue < b.BirthValue;
  }
  if (a.DeathValue != b.DeathValue)
  {
    return a.DeathValue < b.DeathValue;
  }
  return a.Birth < b.Birth;
}

} // namespace

std::vector<PersistencePair> ComputePersistenceByReduction(
  const std::vector<Node>& nodes, const std::vector<Arc>& arcs)
{
  // Filtration order: by value, then index (a face enters before its cofaces
  // when values tie), then node id for determinism.
  std::vector<Id> order;
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    if (!nodes[i].IsInfinity())
    {
      order.push_back(static_cast<Id>(i));
    }
  }
  std::sort(order.begin(), order.end(), [&](Id a, Id b) { return FiltrationLess(nodes, a, b); });
  std::vector<Id> position(nodes.size(), -1);
  for (std::size_t p = 0; p < order.size(); ++p)
  {
    position[order[p]] = static_cast<Id>(p);
  }
  // Columns: sorted positions of the boundary (odd multiplicity arcs only).
  std::vector<std::vector<Id>> columns(order.size());
  for (const Arc& a : arcs)
  {
    if (a.Multiplicity % 2 == 1 && position[a.Lower] >= 0 && position[a.Upper] >= 0)
    {
      columns[position[a.Upper]].push_back(position[a.Lower]);
    }
  }
  // Each column freed once reduced: the pool holds the reduced ones.
  Z2ColumnReduction<Id> reduction(order.size(), Z2ColumnReduction<Id>::Pivot::Greatest);
  std::vector<Id> pivot(order.size(), -1);
  for (std::size_t j = 0; j < columns.size(); ++j)
  {
    std::sort(columns[j].begin(), columns[j].end());
    pivot[j] = reduction.Reduce(columns[j]);
    std::vector<Id>().swap(columns[j]);
  }
  std::vector<PersistencePair> pairs;
  std::vector<bool> killed(order.size(), false);
  for (std::size_t j = 0; j < columns.size(); ++j)
  {
    if (pivot[j] >= 0)
    {
      killed[pivot[j]] = true;
      killed[j] = true; // a destroyer is not a creator
      PersistencePair p;
      p.Birth = order[pivot[j]];
      p.Death = order[j];
      p.Dimension = nodes[p.Birth].Index;
      p.BirthValue = nodes[p.Birth].Value;
      p.DeathValue = nodes[p.Death].Value;
      pairs.push_back(p);
    }
  }
  for (std::size_t j = 0; j < columns.size(); ++j)
  {
    if (!killed[j])
    {
      PersistencePair p;
      p.Birth = order[j];
      p.Dimension = nodes[p.Birth].Index;
      p.BirthValue = nodes[p.Birth].Value;
      p.DeathValue = HUGE_VAL;
      pairs.push_back(p);
    }
  }
  std::sort(pairs.begin(), pairs.end(), PairLess);
  return pairs;
}

// The fast path. Only cells of one index are ever compared with each other (a
// column's pivot is its latest face; columns are reduced in order), so each index
// gets its own ranks. With D the boundary matrix (finite nodes, odd arcs):
// - H0: the columns of index-1 nodes are edges of a graph on the index-0 nodes;
//   their reduction is Kruskal's union-find with the elder rule. An edge with a
//   single lower end is an edge to a virtual vertex older than all (a row above
//   every other one, which a reduced graph column never has as its pivot).
// - H2: reducing D's anti-transpose (the coboundary matrix with both orders
//   reversed) gives the same pairs (de Silva, Morozov, Vejdemo-Johansson 2011). Its
//   columns for index-2 nodes, taken in decreasing filtration order, are edges of
//   the dual graph on the maxima, whose age is their filtration position read
//   backwards; an upper end at infinity is left out of D and becomes the other end
//   of the dual edge, the maximum at infinity, older than every maximum (so it
//   never dies). A dual edge joining two components pairs the index-2 node (birth)
//   with the younger component's oldest maximum, the latest one in the filtration
//   (death): the union-find of the alpha-complex world.
// - H1: clearing. An index-2 node that creates an H2 class has a zero reduced
//   column, and an index-1 node that kills an H0 class is never the pivot of a
//   reduced column (both because the boundary of a boundary is zero), so only the
//   other index-2 nodes are reduced, without the rows of H0 killers.
// The boundary of a boundary is checked (by random signatures: every finite node
// gets a pseudo-random 64-bit word, a cell's signature is the XOR of its faces'
// and must vanish two levels up), like everything else the fast path assumes
// (PersistenceInput checks the rest); anything else is handed to the reference.
namespace
{

using namespace persistence;

/// Insertion sort for the few faces of a node, std::sort beyond.
template <class T>
void SmallSort(T* first, T* last)
{
  if (last - first < 2)
  {
    return;
  }
  if (last - first > 24)
  {
    std::sort(first, last);
    return;
  }
  for (T* i = first + 1; i < last; ++i)
  {
    const T x = *i;
    T* j = i;
    for (; j > first && x < j[-1]; --j)
    {
      *j = j[-1];
    }
    *j = x;
  }
}

/// A pseudo-random word per (level, rank): splitmix64.
std::uint64_t Signature(std::uint64_t level, std::uint64_t rank)
{
  std::uint64_t z = rank * 4 + level + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return (z ^ (z >> 31)) | 1; // never zero
}

/// The (birth node, death node) pairs as they are found.
using FoundPairs = std::vector<std::pair<Int, Int>>;

/// H0: union-find over the index-1 nodes in filtration order. Element 0 is the
/// virtual vertex, element r + 1 the index-0 node of rank r. Returns, per
/// index-1 node, whether it kills an H0 class.
std::vector<std::uint8_t> PairComponents(const TwoEnds& edgeEnds, const Ranking& rank,
  const std::array<std::size_t, 4>& n, FoundPairs& paired)
{
  std::vector<std::uint8_t> killsH0(n[1], 0);
  UnionFind components(n[0] + 1);
  for (std::size_t e = 0; e < n[1]; ++e)
  {
    const Int ends = edgeEnds.Size(static_cast<Int>(e));
    if (ends == 0)
    {
      continue;
    }
    const Int a = edgeEnds.End(static_cast<Int>(e), 0) + 1;
    const Int b = ends == 2 ? edgeEnds.End(static_cast<Int>(e), 1) + 1 : 0;
    const Int younger = components.Merge(a, b);
    if (younger > 0)
    {
      paired.emplace_back(rank.Node[0][younger - 1], rank.Node[1][e]);
      killsH0[e] = 1;
    }
  }
  return killsH0;
}

/// H2: union-find on the dual graph, index-2 nodes in decreasing filtration
/// order. Element 0 is the maximum at infinity, element n3 - r the maximum of
/// rank r (the later a maximum, the older it is here). Returns, per index-2
/// node, whether it creates an H2 class (that dies).
std::vector<std::uint8_t> PairVoids(const TwoEnds& faceEnds, const Ranking& rank,
  const std::array<std::size_t, 4>& n, FoundPairs& paired)
{
  const Int n3 = static_cast<Int>(n[3]);
  std::vector<std::uint8_t> createsH2(n[2], 0);
  UnionFind regions(n[3] + 1);
  for (std::size_t f = n[2]; f-- > 0;)
  {
    const Int ends = faceEnds.Size(static_cast<Int>(f));
    if (ends == 0)
    {
      continue;
    }
    const Int a = n3 - faceEnds.End(static_cast<Int>(f), 0);
    const Int b = ends == 2 ? n3 - faceEnds.End(static_cast<Int>(f), 1) : 0;
    const Int younger = regions.Merge(a, b);
    if (younger > 0)
    {
      paired.emplace_back(rank.Node[2][f], rank.Node[3][n3 - younger]);
      createsH2[f] = 1;
    }
  }
  return createsH2;
}

/// Per index-2 node, in id order (the flow complex lists neighbours together):
/// its faces, checked (repeated arcs; boundary of boundary zero), sorted, and
/// cut down to the rows H1 needs (none for H2 creators, no H0 killers). The
/// signature of its boundary goes to `signature`, for the check one level up.
Tally TrimFaces(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
  const Ranking& rank, const std::array<std::size_t, 4>& n,
  const std::vector<std::uint8_t>& killsH0, const std::vector<std::uint8_t>& createsH2,
  Boundaries& boundaries, std::vector<std::uint64_t>& signature)
{
  const std::vector<Slot>& of = rank.Of;
  const TwoEnds& edgeEnds = boundaries.EdgeEnds;
  std::vector<std::int64_t>& begin = boundaries.Begin;
  std::vector<Int>& faces = boundaries.Faces;
  std::vector<Int>& rows = boundaries.Rows;
  // Per index-1 node id: the signature of its boundary, bit 0 set when it
  // kills an H0 class.
  std::unique_ptr<std::uint64_t[]> edgeInfo(new std::uint64_t[nodes.size()]);
  ParallelRange(n[1], [&](std::size_t e) {
    std::uint64_t sig = 0;
    for (int k = 0; k < edgeEnds.Size(static_cast<Int>(e)); ++k)
    {
      sig ^= Signature(0, static_cast<std::uint64_t>(edgeEnds.End(static_cast<Int>(e), k)));
    }
    edgeInfo[rank.Node[1][e]] = (sig & ~std::uint64_t(1)) | killsH0[e];
  });
  signature.assign(n[2], 0);
  const Id nodeCount = static_cast<Id>(nodes.size());
  return tbb::parallel_reduce(
    tbb::blocked_range<std::size_t>(0, n[2], 1024), Tally(),
    [&](const tbb::blocked_range<std::size_t>& r, Tally t) {
      std::vector<std::uint32_t> face; // rank * 2 + (kills H0)
      std::uint64_t twoDown = 0, oneDown = 0;
      auto add = [&](Id id) {
        const std::uint64_t info = edgeInfo[id];
        const Int e = of[id].Rank;
        twoDown ^= info & ~std::uint64_t(1);
        oneDown ^= Signature(1, static_cast<std::uint64_t>(e));
        face.push_back(static_cast<std::uint32_t>(e) * 2 + static_cast<std::uint32_t>(info & 1));
      };
      for (std::size_t p = r.begin(); p < r.end(); ++p)
      {
        const Int f = of[rank.Index2ById[p]].Rank;
        face.clear();
        twoDown = oneDown = 0;
        if (boundaries.Runs)
        {
          const std::int64_t first = boundaries.RunBegin[f].load(std::memory_order_relaxed);
          const std::int64_t last = first + boundaries.RunLength[f].load(std::memory_order_relaxed);
          for (std::int64_t i = first; i < last; ++i)
          {
            const Arc& a = arcs[i];
            if (a.Multiplicity % 2 != 1)
            {
              continue;
            }
            if (a.Lower < 0 || a.Lower >= nodeCount)
            {
              t.MissingNode = true;
              continue;
            }
            const Int index = of[a.Lower].Index;
            if (index == 1)
            {
              add(a.Lower);
            }
            t.Usable = t.Usable && (index == 1 || index == -1); // -1: infinity, not in D
          }
        }
        else
        {
          std::for_each(rows.data() + begin[f], rows.data() + begin[f] + faces[f], add);
        }
        SmallSort(face.data(), face.data() + face.size());
        Int* kept = rows.data() + begin[f];
        for (std::size_t k = 0; k < face.size(); ++k)
        {
          t.Usable = t.Usable && (k == 0 || face[k] / 2 != face[k - 1] / 2); // repeated arc
          if (!createsH2[f] && face[k] % 2 == 0)
          {
            *kept++ = static_cast<Int>(face[k] / 2);
          }
        }
        t.Usable = t.Usable && twoDown == 0;
        faces[f] = static_cast<Int>(kept - (rows.data() + begin[f]));
        signature[f] = oneDown;
      }
      return t;
    },
    [](Tally x, const Tally& y) {
      x.Join(y);
      return x;
    });
}

/// The boundary of the boundary of each maximum vanishes: the signatures of
/// its faces' boundaries cancel.
bool BoundaryOfBoundaryOfMaximaVanishes(const TwoEnds& faceEnds,
  const std::array<std::size_t, 4>& n, const std::vector<std::uint64_t>& signature)
{
  std::vector<std::uint64_t> threeDown(n[3], 0);
  for (std::size_t f = 0; f < n[2]; ++f)
  {
    for (int k = 0; k < faceEnds.Size(static_cast<Int>(f)); ++k)
    {
      threeDown[faceEnds.End(static_cast<Int>(f), k)] ^= signature[f];
    }
  }
  return std::none_of(threeDown.begin(), threeDown.end(), [](std::uint64_t x) { return x != 0; });
}

/// H1: column reduction of the remaining index-2 nodes in filtration order,
/// their trimmed boundaries in `boundaries.Rows`, where the reduced columns go
/// too.
void PairLoops(Boundaries& boundaries, const Ranking& rank, const std::array<std::size_t, 4>& n,
  FoundPairs& paired, PersistenceReport& done)
{
  using Reduction = Z2ColumnReduction<Int>;
  Reduction reduction(n[1], Reduction::Pivot::Greatest, &boundaries.Rows);
  for (std::size_t f = 0; f < n[2]; ++f)
  {
    if (boundaries.Faces[f] == 0)
    {
      continue; // an H2 creator (cleared), or an essential H2 class
    }
    const Int low = reduction.ReducePooled(boundaries.Begin[f], boundaries.Faces[f]);
    if (low >= 0) // else a creator of an essential H2 class
    {
      paired.emplace_back(rank.Node[1][low], rank.Node[2][f]);
    }
  }
  done.ReducedColumns = reduction.NumberOfReducedColumns();
  done.ColumnAdditions = reduction.NumberOfAdditions();
}

/// The pairs in their final order, dimension after dimension: births in
/// filtration order (value, then id), then equal birth values by death value
/// and birth id.
std::vector<PersistencePair> SortedPairs(const std::vector<Node>& nodes, const Ranking& rank,
  const std::array<std::size_t, 4>& n, FoundPairs& paired)
{
  const std::vector<Slot>& of = rank.Of;
  // deathOf[k][r]: what kills the class born at the index-k node of rank r (a
  // node id; -1: nothing, an essential class; -2: this node kills).
  std::array<std::vector<Int>, 4> deathOf;
  for (int k = 0; k < 4; ++k)
  {
    deathOf[k].assign(n[k], -1);
  }
  for (const auto& p : paired)
  {
    deathOf[of[p.first].Index][of[p.first].Rank] = p.second;
    deathOf[of[p.second].Index][of[p.second].Rank] = -2;
  }
  FoundPairs().swap(paired);
  constexpr std::size_t Block = 1 << 16;
  std::array<std::vector<std::size_t>, 4> at; // output position of each block of ranks
  std::size_t total = 0;
  for (int k = 0; k < 4; ++k)
  {
    const std::size_t blocks = (n[k] + Block - 1) / Block;
    at[k].assign(blocks + 1, 0);
    ParallelRange(blocks, [&](std::size_t b) {
      at[k][b + 1] = static_cast<std::size_t>(std::count_if(deathOf[k].begin() + b * Block,
        deathOf[k].begin() + std::min(n[k], (b + 1) * Block), [](Int d) { return d != -2; }));
    });
    at[k][0] = total;
    for (std::size_t b = 0; b < blocks; ++b)
    {
      at[k][b + 1] += at[k][b];
    }
    total = at[k][blocks];
  }
  std::vector<PersistencePair> pairs(total);
  for (int k = 0; k < 4; ++k)
  {
    ParallelRange(at[k].size() - 1, [&](std::size_t b) {
      std::size_t o = at[k][b];
      for (std::size_t r = b * Block; r < std::min(n[k], (b + 1) * Block); ++r)
      {
        const Int death = deathOf[k][r];
        if (death == -2)
        {
          continue;
        }
        PersistencePair& p = pairs[o++];
        p.Dimension = k;
        p.Birth = rank.Node[k][r];
        p.Death = death;
        p.BirthValue = nodes[p.Birth].Value;
        p.DeathValue = death >= 0 ? nodes[death].Value : HUGE_VAL;
      }
    });
  }
  // Equal birth values (all of H0 in a flow complex): by death value, birth id.
  for (std::size_t i = 0; i < pairs.size();)
  {
    std::size_t j = i + 1;
    while (j < pairs.size() && pairs[j].Dimension == pairs[i].Dimension &&
      pairs[j].BirthValue == pairs[i].BirthValue)
    {
      ++j;
    }
    if (j - i > Block)
    {
      tbb::parallel_sort(pairs.begin() + i, pairs.begin() + j, PairLess);
    }
    else if (j - i > 1)
    {
      std::sort(pairs.begin() + i, pairs.begin() + j, PairLess);
    }
    i = j;
  }
  return pairs;
}

} // namespace

std::vector<PersistencePair> ComputePersistence(
  const std::vector<Node>& nodes, const std::vector<Arc>& arcs, PersistenceReport* report)
{
  PersistenceReport unused;
  PersistenceReport& done = report ? *report : unused;
  done = PersistenceReport();
  Ranking rank;
  if (!RankNodes(nodes, rank))
  {
    return ComputePersistenceByReduction(nodes, arcs);
  }
  const std::array<std::size_t, 4> n{ { rank.Node[0].size(), rank.Node[1].size(),
    rank.Node[2].size(), rank.Node[3].size() } };

  // The boundaries, from one or two parallel passes over the arcs.
  Boundaries boundaries(n);
  const Gathering gathered = GatherBoundaries(arcs, rank, n, boundaries, done.GroupedArcs);
  if (gathered == Gathering::MissingNode)
  {
    throw std::out_of_range("persistence: an arc names a node that does not exist");
  }
  if (gathered != Gathering::Done || !boundaries.EdgeEnds.Distinct() ||
    !boundaries.FaceEnds.Distinct())
  {
    return ComputePersistenceByReduction(nodes, arcs);
  }

  FoundPairs paired;
  paired.reserve(n[0] + n[2] + n[3]);
  const std::vector<std::uint8_t> killsH0 = PairComponents(boundaries.EdgeEnds, rank, n, paired);
  const std::vector<std::uint8_t> createsH2 = PairVoids(boundaries.FaceEnds, rank, n, paired);
  {
    std::vector<std::uint64_t> signature;
    const Tally checked =
      TrimFaces(nodes, arcs, rank, n, killsH0, createsH2, boundaries, signature);
    if (checked.MissingNode)
    {
      throw std::out_of_range("persistence: an arc names a node that does not exist");
    }
    if (!checked.Usable ||
      !BoundaryOfBoundaryOfMaximaVanishes(boundaries.FaceEnds, n, signature))
    {
      return ComputePersistenceByReduction(nodes, arcs);
    }
  }
  PairLoops(boundaries, rank, n, paired, done);
  done.FastPath = true;
  return SortedPairs(nodes, rank, n, paired);
}

} // namespace flowrecon
