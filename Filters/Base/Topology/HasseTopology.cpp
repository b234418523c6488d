#include "HasseTopology.h"

#include "UnionFind.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

namespace flowrecon
{

namespace
{

using Int = std::int32_t;

[[noreturn]] void NotClosed(const std::string& what)
{
  throw InputError("topology from the Hasse diagram: " + what);
}

/// Up to two odd-multiplicity neighbours of each inserted node (by position):
/// the ends of an edge (0-1 arcs) or the sides of a 2-cell (2-3 arcs).
std::vector<Int> PairsOf(const std::vector<std::int8_t>& index, const std::vector<Arc>& arcs,
  const std::vector<Int>& pos, int lowerIndex, std::size_t inserted)
{
  std::vector<Int> ends(2 * inserted, -1);
  for (const Arc& a : arcs)
  {
    if (a.Multiplicity % 2 == 0)
    {
      continue;
    }
    // Edges are found from their ends (the upper), 2-cells from themselves.
    const Id cell = lowerIndex == 0 ? a.Upper : a.Lower;
    const Id other = lowerIndex == 0 ? a.Lower : a.Upper;
    if (index[a.Lower] != lowerIndex || pos[cell] < 0)
    {
      continue;
    }
    Int* slot = &ends[2 * static_cast<std::size_t>(pos[cell])];
    if (slot[1] >= 0)
    {
      NotClosed("node " + std::to_string(cell) + " has more than two " +
        (lowerIndex == 0 ? "ends" : "sides"));
    }
    slot[slot[0] >= 0 ? 1 : 0] = static_cast<Int>(other);
  }
  return ends;
}

/// The nodes' indices side by side: the passes over the arcs read them at
/// random, and a node is 56 bytes (at 10^6 points the nodes are 200 MB).
std::vector<std::int8_t> Indices(const std::vector<Node>& nodes)
{
  std::vector<std::int8_t> index(nodes.size());
  tbb::parallel_for(std::size_t(0), nodes.size(),
    [&](std::size_t v) { index[v] = static_cast<std::int8_t>(nodes[v].Index); });
  return index;
}

} // namespace

std::vector<double> PresenceTimes(const std::vector<Node>& nodes, const std::vector<Arc>& rawArcs,
  const std::vector<Id>& carriers, const ReconstructionResult& run)
{
  const std::size_t n = nodes.size();
  if (carriers.size() != n || run.Nodes.size() != n)
  {
    NotClosed("the carriers, the run and the diagram have different nodes");
  }
  std::vector<double> presence(n, HUGE_VAL);
  for (std::size_t v = 0; v < n; ++v)
  {
    if (carriers[v] >= 0)
    {
      presence[v] = run.Nodes[carriers[v]].Threshold;
    }
  }
  // Every face of a drawn cell is drawn with it: from the maxima down.
  const std::vector<std::int8_t> index = Indices(nodes);
  for (int upper = 3; upper >= 1; --upper)
  {
    for (const Arc& a : rawArcs)
    {
      if (index[a.Upper] == upper)
      {
        presence[a.Lower] = std::min(presence[a.Lower], presence[a.Upper]);
      }
    }
  }
  return presence;
}

std::vector<Bar> HasseBarcode(const std::vector<Node>& nodes, const std::vector<Arc>& rawArcs,
  const std::vector<double>& presence, const std::vector<std::pair<Id, Id>>& joined)
{
  const std::vector<Arc>& arcs = rawArcs;
  const std::size_t n = nodes.size();
  const std::vector<std::int8_t> index = Indices(nodes);
  if (presence.size() != n)
  {
    NotClosed("the presence times and the diagram have different nodes");
  }
  // The filtration: by presence, faces before cofaces, then by node id (keys
  // side by side: the sort is most of this function's time at 10^6 points).
  struct Key
  {
    double Presence;
    Int Index, Node;
    bool operator<(const Key& o) const
    {
      return std::tie(this->Presence, this->Index, this->Node) < std::tie(o.Presence, o.Index, o.Node);
    }
  };
  std::vector<Key> keys;
  for (std::size_t v = 0; v < n; ++v)
  {
    if (presence[v] < HUGE_VAL)
    {
      keys.push_back(Key{ presence[v], index[v], static_cast<Int>(v) });
    }
  }
  tbb::parallel_sort(keys.begin(), keys.end());
  std::vector<Int> order(keys.size());
  for (std::size_t p = 0; p < keys.size(); ++p)
  {
    order[p] = keys[p].Node;
  }
  std::vector<Key>().swap(keys);
  std::vector<Int> pos(n, -1);
  for (std::size_t p = 0; p < order.size(); ++p)
  {
    pos[order[p]] = static_cast<Int>(p);
  }
  auto tau = [&](Int v) { return presence[v]; };
  std::vector<Bar> bars;
  // Most classes die where they are born: only bars of positive length are made.
  auto make = [&](int dimension, Int birth, Int death) {
    if (tau(birth) < (death >= 0 ? tau(death) : HUGE_VAL))
    {
      Bar bar;
      bar.Dimension = dimension;
      bar.Birth = tau(birth);
      bar.BirthCell = birth;
      bar.Death = death >= 0 ? tau(death) : HUGE_VAL;
      bar.DeathCell = death;
      bars.push_back(bar);
    }
  };

  // Backwards, on the complement: maxima outside K_t joined by index-2 nodes
  // outside it. Elements are maxima by age in that direction: never inserted
  // first, then by decreasing position.
  std::vector<Int> elementOf(n, -1), nodeOf;
  for (std::size_t v = 0; v < n; ++v)
  {
    if (index[v] == 3 && pos[v] < 0)
    {
      elementOf[v] = static_cast<Int>(nodeOf.size());
      nodeOf.push_back(static_cast<Int>(v));
    }
  }
  for (std::size_t p = order.size(); p-- > 0;)
  {
    if (index[order[p]] == 3)
    {
      elementOf[order[p]] = static_cast<Int>(nodeOf.size());
      nodeOf.push_back(order[p]);
    }
  }
  UnionFind outside(nodeOf.size());
  for (const auto& [a, b] : joined)
  {
    if (a < 0 || b < 0 || a >= static_cast<Id>(n) || b >= static_cast<Id>(n) ||
      index[a] != 3 || index[b] != 3 || pos[a] >= 0 || pos[b] >= 0)
    {
      NotClosed("joined nodes that are not maxima outside every reconstruction");
    }
    outside.Merge(elementOf[a], elementOf[b]);
  }
  // Index-2 nodes never present: outside at every threshold.
  for (std::size_t k = 0; k < arcs.size();)
  {
    const Id s = arcs[k].Lower;
    Int sides[3] = { -1, -1, -1 };
    int count = 0;
    for (; k < arcs.size() && arcs[k].Lower == s; ++k)
    {
      if (index[s] == 2 && arcs[k].Multiplicity % 2 != 0)
      {
        sides[std::min(count++, 2)] = arcs[k].Upper;
      }
    }
    if (index[s] != 2 || pos[s] >= 0 || count == 0)
    {
      continue;
    }
    if (count != 2)
    {
      NotClosed("index-2 node " + std::to_string(s) + " has " + std::to_string(count) +
        " sides (its 2-3 arcs are incomplete or not grouped by lower node)");
    }
    if (pos[sides[0]] >= 0 || pos[sides[1]] >= 0)
    {
      NotClosed("a maximum is inserted before its boundary node " + std::to_string(s));
    }
    outside.Merge(elementOf[sides[0]], elementOf[sides[1]]);
  }
  const std::vector<Int> sides = PairsOf(index, arcs, pos, 2, order.size());
  std::vector<char> separates(order.size(), 0);
  for (std::size_t p = order.size(); p-- > 0;)
  {
    const Int s = order[p];
    if (index[s] != 2)
    {
      continue;
    }
    const Int a = sides[2 * p], b = sides[2 * p + 1];
    if ((a >= 0) != (b >= 0))
    {
      NotClosed("index-2 node " + std::to_string(s) + " has one side");
    }
    if (a < 0)
    {
      continue; // both sides in one maximum: the arcs cancelled mod 2
    }
    if ((pos[a] >= 0 && pos[a] < static_cast<Int>(p)) || (pos[b] >= 0 && pos[b] < static_cast<Int>(p)))
    {
      NotClosed("a maximum is inserted before its boundary node " + std::to_string(s));
    }
    const Int dies = outside.Merge(elementOf[a], elementOf[b]);
    if (dies >= 0)
    {
      separates[p] = 1;
      const Int m = nodeOf[dies];
      make(2, s, pos[m] >= 0 ? m : -1);
    }
  }

  // Forwards: components by union-find over the edges' ends, loops as they
  // close, and the 2-cells that do not separate fill a loop each.
  const std::vector<Int> ends = PairsOf(index, arcs, pos, 0, order.size());
  UnionFind inside(order.size());
  std::vector<Int> loops; // edges of the open loops, latest last
  for (std::size_t p = 0; p < order.size(); ++p)
  {
    const Int v = order[p];
    const int dimension = index[v];
    if (dimension == 1)
    {
      const Int a = ends[2 * p], b = ends[2 * p + 1];
      if ((a >= 0) != (b >= 0) || (a >= 0 && (pos[a] < 0 || pos[b] < 0 ||
                                               pos[a] > static_cast<Int>(p) || pos[b] > static_cast<Int>(p))))
      {
        NotClosed("edge " + std::to_string(v) + " is inserted before its ends");
      }
      // A component is named by its oldest vertex: the younger one dies.
      const Int dies = a >= 0 ? inside.Merge(pos[a], pos[b]) : -1;
      if (dies >= 0)
      {
        make(0, order[dies], v);
      }
      else
      {
        loops.push_back(v);
      }
    }
    else if (dimension == 2 && !separates[p])
    {
      if (loops.empty())
      {
        NotClosed("2-cell " + std::to_string(v) + " fills no loop");
      }
      make(1, loops.back(), v);
      loops.pop_back();
    }
  }
  for (std::size_t p = 0; p < order.size(); ++p)
  {
    if (index[order[p]] == 0 && inside.Find(static_cast<Int>(p)) == static_cast<Int>(p))
    {
      make(0, order[p], -1);
    }
  }
  for (const Int e : loops)
  {
    make(1, e, -1);
  }
  return bars;
}

} // namespace flowrecon
