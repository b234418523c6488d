#include "HasseTopology.h"

#include "PersistenceUnionFind.h"

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
std::vector<Int> PairsOf(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
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
    if (nodes[a.Lower].Index != lowerIndex || pos[cell] < 0)
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
  for (int upper = 3; upper >= 1; --upper)
  {
    for (const Arc& a : rawArcs)
    {
      if (nodes[a.Upper].Index == upper)
      {
        presence[a.Lower] = std::min(presence[a.Lower], presence[a.Upper]);
      }
    }
  }
  return presence;
}

std::vector<Bar> HasseBarcode(
  const std::vector<Node>& nodes, const std::vector<Arc>& rawArcs, const std::vector<double>& presence)
{
  const std::vector<Arc>& arcs = rawArcs;
  const std::size_t n = nodes.size();
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
      keys.push_back(Key{ presence[v], nodes[v].Index, static_cast<Int>(v) });
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

  // Backwards, on the complement: maxima outside K_t joined by index-2 nodes
  // outside it. Elements are maxima by age in that direction: never inserted
  // first, then by decreasing position.
  std::vector<Int> elementOf(n, -1), nodeOf;
  for (std::size_t v = 0; v < n; ++v)
  {
    if (nodes[v].Index == 3 && pos[v] < 0)
    {
      elementOf[v] = static_cast<Int>(nodeOf.size());
      nodeOf.push_back(static_cast<Int>(v));
    }
  }
  for (std::size_t p = order.size(); p-- > 0;)
  {
    if (nodes[order[p]].Index == 3)
    {
      elementOf[order[p]] = static_cast<Int>(nodeOf.size());
      nodeOf.push_back(order[p]);
    }
  }
  ElderUnionFind outside(nodeOf.size());
  // Index-2 nodes never present: outside at every threshold.
  for (std::size_t k = 0; k < arcs.size();)
  {
    const Id s = arcs[k].Lower;
    Int sides[3] = { -1, -1, -1 };
    int count = 0;
    for (; k < arcs.size() && arcs[k].Lower == s; ++k)
    {
      if (nodes[s].Index == 2 && arcs[k].Multiplicity % 2 != 0)
      {
        sides[std::min(count++, 2)] = arcs[k].Upper;
      }
    }
    if (nodes[s].Index != 2 || pos[s] >= 0 || count == 0)
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
  const std::vector<Int> sides = PairsOf(nodes, arcs, pos, 2, order.size());
  std::vector<char> separates(order.size(), 0);
  for (std::size_t p = order.size(); p-- > 0;)
  {
    const Int s = order[p];
    if (nodes[s].Index != 2)
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
      Bar bar;
      bar.Dimension = 2;
      bar.Birth = tau(s);
      bar.BirthCell = s;
      bar.Death = pos[m] >= 0 ? tau(m) : HUGE_VAL;
      bar.DeathCell = pos[m] >= 0 ? m : -1;
      bars.push_back(bar);
    }
  }

  // Forwards: components by union-find over the edges' ends, loops as they
  // close, and the 2-cells that do not separate fill a loop each.
  const std::vector<Int> ends = PairsOf(nodes, arcs, pos, 0, order.size());
  ElderUnionFind inside(order.size());
  std::vector<std::size_t> barOfVertex(order.size(), 0);
  std::vector<std::size_t> loops; // open 1-bars, latest last
  auto open = [&](int dimension, Int v) {
    Bar bar;
    bar.Dimension = dimension;
    bar.Birth = tau(v);
    bar.BirthCell = v;
    bar.Death = HUGE_VAL;
    bars.push_back(bar);
    return bars.size() - 1;
  };
  for (std::size_t p = 0; p < order.size(); ++p)
  {
    const Int v = order[p];
    const int index = nodes[v].Index;
    if (index == 0)
    {
      barOfVertex[p] = open(0, v);
    }
    else if (index == 1)
    {
      const Int a = ends[2 * p], b = ends[2 * p + 1];
      if ((a >= 0) != (b >= 0) || (a >= 0 && (pos[a] < 0 || pos[b] < 0 ||
                                               pos[a] > static_cast<Int>(p) || pos[b] > static_cast<Int>(p))))
      {
        NotClosed("edge " + std::to_string(v) + " is inserted before its ends");
      }
      const Int dies = a >= 0 ? inside.Merge(pos[a], pos[b]) : -1;
      if (dies >= 0)
      {
        Bar& bar = bars[barOfVertex[dies]];
        bar.Death = tau(v);
        bar.DeathCell = v;
      }
      else
      {
        loops.push_back(open(1, v));
      }
    }
    else if (index == 2 && !separates[p])
    {
      if (loops.empty())
      {
        NotClosed("2-cell " + std::to_string(v) + " fills no loop");
      }
      Bar& bar = bars[loops.back()];
      loops.pop_back();
      bar.Death = tau(v);
      bar.DeathCell = v;
    }
  }
  bars.erase(std::remove_if(bars.begin(), bars.end(),
               [](const Bar& b) { return !(b.Birth < b.Death); }),
    bars.end());
  return bars;
}

} // namespace flowrecon
