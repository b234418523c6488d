#include "HasseDiagram.h"

#include "NodeIndices.h"
#include "Progress.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <limits>
#include <string>
#include <tuple>

namespace flowrecon
{

void ValidateArc(const std::vector<Node>& nodes, const Arc& a, std::size_t position)
{
  const Id n = static_cast<Id>(nodes.size());
  const auto where = [position] { return "Hasse diagram: arc " + std::to_string(position); };
  if (a.Lower < 0 || a.Lower >= n || a.Upper < 0 || a.Upper >= n)
  {
    throw InputError(where() + " refers to a node that does not exist");
  }
  if (nodes[a.Upper].Index != nodes[a.Lower].Index + 1)
  {
    throw InputError(where() + " does not go up by one index");
  }
  if (a.Multiplicity < 0)
  {
    throw InputError(where() + " has a negative multiplicity");
  }
}

HasseDiagram::HasseDiagram(const std::vector<Node>& nodes, const std::vector<Arc>& arcs)
  : InLists(nodes.size())
  , OutLists(nodes.size())
  , Removed(nodes.size(), 0)
{
  const Id n = static_cast<Id>(nodes.size());
  if (n > std::numeric_limits<std::int32_t>::max())
  {
    throw InputError("Hasse diagram: more than 2^31 nodes");
  }
  // The indices by themselves: every arc reads two, and a Node is 56 bytes.
  const std::vector<std::int8_t> index = NodeIndices(nodes);
  const auto valid = [&index](const Arc& a) { return IsValidArc(index, a); };
  // Lists laid out with the capacity of their first arcs (~3 a node).
  std::vector<std::uint32_t> inDegree(nodes.size(), 0), outDegree(nodes.size(), 0);
  std::size_t sampleArcs = 0;
  for (std::size_t i = 0; i < arcs.size(); ++i)
  {
    const Arc& a = arcs[i];
    if (!valid(a))
    {
      ValidateArc(nodes, a, i); // throws, naming what is wrong
      continue;
    }
    if (index[a.Lower] == 0)
    {
      ++sampleArcs;
      continue;
    }
    ++outDegree[a.Lower];
    ++inDegree[a.Upper];
  }
  LayOut(this->InLists, inDegree, this->InArena);
  LayOut(this->OutLists, outDegree, this->OutArena);
  this->SampleArcs.reserve(sampleArcs);
  for (const Arc& a : arcs)
  {
    if (a.Multiplicity > 0 && index[a.Lower] == 0)
    {
      this->SampleArcs.push_back(a);
    }
    else if (a.Multiplicity > 0)
    {
      this->Insert(a.Lower, a.Upper, a.Multiplicity);
    }
  }
  // Arcs in strictly increasing (Lower, Upper), as the builder and the
  // simplification write them, have no repeats to merge.
  const auto before = [](const Arc& a, const Arc& b) {
    return std::tie(a.Lower, a.Upper) < std::tie(b.Lower, b.Upper);
  };
  const bool increasing = std::adjacent_find(arcs.begin(), arcs.end(),
                            [&](const Arc& a, const Arc& b) { return !before(a, b); }) == arcs.end();
  if (!increasing)
  {
    // Repeats are merged next, their multiplicities summed: the order among
    // them, which a parallel sort does not fix, does not matter.
    tbb::parallel_sort(this->SampleArcs.begin(), this->SampleArcs.end(), before);
    this->MergeRepeatedArcs();
  }
}

void HasseDiagram::LayOut(
  std::vector<List>& lists, const std::vector<std::uint32_t>& degree, ListArena<HalfArc>& arena)
{
  std::size_t total = 0;
  for (const std::uint32_t d : degree)
  {
    total += d;
  }
  HalfArc* next = arena.Carve(total);
  for (std::size_t i = 0; i < lists.size(); ++i)
  {
    if (degree[i] > 0)
    {
      lists[i].Data = next;
      lists[i].Capacity = degree[i];
      next += degree[i];
    }
  }
}

void HasseDiagram::Push(List& list, const HalfArc& h, ListArena<HalfArc>& arena)
{
  if (list.Size == list.Capacity)
  {
    // Capacities are powers of two held in 32 bits (ListArena.h).
    if (list.Size >= (std::uint32_t(1) << 30))
    {
      throw InputError("Hasse diagram: a node with more than 2^30 arcs");
    }
    std::uint32_t capacity = 0;
    HalfArc* moved = arena.Allocate(std::max<std::uint32_t>(4, list.Size + (list.Size >> 1) + 1), capacity);
    std::copy(list.Data, list.Data + list.Size, moved);
    arena.Release(list.Data, list.Capacity);
    list.Data = moved;
    list.Capacity = capacity;
  }
  list.Data[list.Size++] = h;
}

void HasseDiagram::MergeRepeatedArcs()
{
  // Looking each arc up while inserting scanned lists as long as a tube-spanning
  // patch's boundary (measured: 4.9e8 entries for 2e7 arcs of 10^5 torus
  // points, 98 % of all lookups); sorting each Out list finds repeats in
  // O(d log d). Repeats are rare (a saved file may hold some): their
  // multiplicities go to the first copy, the others are erased.
  std::vector<std::pair<std::int32_t, std::uint32_t>> row; // (upper, position)
  std::vector<std::uint32_t> erase;
  std::vector<Arc>& sample = this->SampleArcs;
  std::size_t next = 0, kept = 0; // in SampleArcs, sorted: repeats are neighbours
  for (Id lower = 0; lower < this->NodeCount(); ++lower)
  {
    for (; next < sample.size() && sample[next].Lower == lower; ++next)
    {
      const Arc& a = sample[next];
      if (kept == 0 || sample[kept - 1].Lower != lower || sample[kept - 1].Upper != a.Upper)
      {
        sample[kept++] = a;
        continue;
      }
      Arc& keep = sample[kept - 1];
      if (a.Multiplicity > std::numeric_limits<std::int32_t>::max() - keep.Multiplicity)
      {
        throw InputError("Hasse diagram: the arc from node " + std::to_string(lower) +
          " to node " + std::to_string(keep.Upper) + " has too large a multiplicity");
      }
      keep.Multiplicity += a.Multiplicity;
    }
    const HalfArcs out = this->Out(lower);
    if (out.size() < 2)
    {
      continue;
    }
    row.clear();
    for (std::size_t k = 0; k < out.size(); ++k)
    {
      row.emplace_back(out[k].Node, static_cast<std::uint32_t>(k));
    }
    std::sort(row.begin(), row.end());
    erase.clear();
    for (std::size_t j = 1, first = 0; j < row.size(); ++j)
    {
      if (row[j].first != row[first].first)
      {
        first = j;
        continue;
      }
      HalfArc& keep = this->OutLists[lower].Data[row[first].second];
      const std::int32_t more = out[row[j].second].Multiplicity;
      if (more > std::numeric_limits<std::int32_t>::max() - keep.Multiplicity)
      {
        throw InputError("Hasse diagram: the arc from node " + std::to_string(lower) +
          " to node " + std::to_string(keep.Node) + " has too large a multiplicity");
      }
      keep.Multiplicity += more;
      this->InLists[keep.Node].Data[keep.Twin].Multiplicity = keep.Multiplicity;
      erase.push_back(row[j].second);
    }
    // From the back: swap-and-pop then only moves entries that are kept.
    std::sort(erase.rbegin(), erase.rend());
    for (const std::uint32_t k : erase)
    {
      this->EraseOut(lower, k);
    }
  }
  sample.resize(kept);
}

std::int64_t HasseDiagram::Find(Id lower, Id upper) const
{
  const HalfArcs out = this->Out(lower);
  const HalfArcs in = this->In(upper);
  if (out.size() <= in.size())
  {
    for (std::size_t k = 0; k < out.size(); ++k)
    {
      if (out[k].Node == upper)
      {
        return static_cast<std::int64_t>(k);
      }
    }
    return -1;
  }
  for (const HalfArc& h : in)
  {
    if (h.Node == lower)
    {
      return static_cast<std::int64_t>(h.Twin);
    }
  }
  return -1;
}

int HasseDiagram::Multiplicity(Id lower, Id upper) const
{
  const std::int64_t k = this->Find(lower, upper);
  return k < 0 ? 0 : this->OutLists[lower].Data[k].Multiplicity;
}

void HasseDiagram::Insert(Id lower, Id upper, int multiplicity)
{
  List& out = this->OutLists[lower];
  List& in = this->InLists[upper];
  Push(out, HalfArc{ static_cast<std::int32_t>(upper), static_cast<std::int32_t>(multiplicity), in.Size },
    this->OutArena);
  Push(in, HalfArc{ static_cast<std::int32_t>(lower), static_cast<std::int32_t>(multiplicity), out.Size - 1 },
    this->InArena);
}

void HasseDiagram::EraseOut(Id lower, std::size_t k)
{
  List& out = this->OutLists[lower];
  const Id upper = out.Data[k].Node;
  const std::size_t j = out.Data[k].Twin;
  // Swap-and-pop in both lists; the moved entries' mirrors learn where they
  // went (a removed node has no mirror left).
  if (k + 1 != out.Size)
  {
    const HalfArc& moved = out.Data[k] = out.Data[out.Size - 1];
    if (!this->Removed[moved.Node])
    {
      this->InLists[moved.Node].Data[moved.Twin].Twin = static_cast<std::uint32_t>(k);
    }
  }
  --out.Size;
  List& in = this->InLists[upper];
  if (j + 1 != in.Size)
  {
    const HalfArc& moved = in.Data[j] = in.Data[in.Size - 1];
    if (!this->Removed[moved.Node])
    {
      this->OutLists[moved.Node].Data[moved.Twin].Twin = static_cast<std::uint32_t>(j);
    }
  }
  --in.Size;
}

int HasseDiagram::FlipParity(Id lower, Id upper)
{
  const std::int64_t k = this->Find(lower, upper);
  if (k < 0)
  {
    this->Insert(lower, upper, 1);
    return 1;
  }
  HalfArc& out = this->OutLists[lower].Data[k];
  if (out.Multiplicity % 2 == 1)
  {
    this->EraseOut(lower, static_cast<std::size_t>(k));
    return 0;
  }
  out.Multiplicity = 1;
  this->InLists[upper].Data[out.Twin].Multiplicity = 1;
  return 1;
}

void HasseDiagram::Remove(Id node)
{
  this->Removed[node] = 1;
  this->InArena.Release(this->InLists[node].Data, this->InLists[node].Capacity);
  this->OutArena.Release(this->OutLists[node].Data, this->OutLists[node].Capacity);
  this->InLists[node] = List();
  this->OutLists[node] = List();
}

std::vector<Arc> HasseDiagram::TakeArcs()
{
  std::vector<List>().swap(this->InLists); // the Out lists hold every other arc
  this->InArena.Clear();
  std::vector<Arc> arcs;
  std::size_t count = this->SampleArcs.size();
  for (const List& out : this->OutLists)
  {
    count += out.Size; // an upper bound: entries of removed nodes are skipped
  }
  arcs.reserve(count);
  std::size_t next = 0;
  for (std::size_t lower = 0; lower < this->OutLists.size(); ++lower)
  {
    const std::size_t first = arcs.size();
    for (; next < this->SampleArcs.size() && this->SampleArcs[next].Lower == static_cast<Id>(lower); ++next)
    {
      if (!this->Removed[this->SampleArcs[next].Upper])
      {
        arcs.push_back(this->SampleArcs[next]);
      }
    }
    for (const HalfArc& h : this->Out(static_cast<Id>(lower)))
    {
      if (!this->Removed[h.Node])
      {
        arcs.push_back(Arc{ static_cast<Id>(lower), h.Node, h.Multiplicity });
      }
    }
    std::sort(arcs.begin() + static_cast<std::ptrdiff_t>(first), arcs.end(),
      [](const Arc& a, const Arc& b) { return a.Upper < b.Upper; });
  }
  std::vector<List>().swap(this->OutLists);
  this->OutArena.Clear();
  std::vector<char>().swap(this->Removed);
  std::vector<Arc>().swap(this->SampleArcs);
  return arcs;
}

} // namespace flowrecon
