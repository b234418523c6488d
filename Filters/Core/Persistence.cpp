#include "Persistence.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace flowrecon
{

std::vector<PersistencePair> ComputePersistence(
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
  std::sort(order.begin(), order.end(), [&](Id a, Id b) {
    const Node& x = nodes[a];
    const Node& y = nodes[b];
    if (x.Value != y.Value)
    {
      return x.Value < y.Value;
    }
    return x.Index != y.Index ? x.Index < y.Index : a < b;
  });
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
  std::vector<Id> pivotOwner(order.size(), -1); // row -> column whose low it is
  std::vector<Id> merged;
  for (std::size_t j = 0; j < columns.size(); ++j)
  {
    std::vector<Id>& col = columns[j];
    std::sort(col.begin(), col.end());
    while (!col.empty() && pivotOwner[col.back()] >= 0)
    {
      const std::vector<Id>& other = columns[pivotOwner[col.back()]];
      merged.clear();
      std::set_symmetric_difference(
        col.begin(), col.end(), other.begin(), other.end(), std::back_inserter(merged));
      col.swap(merged);
    }
    if (!col.empty())
    {
      pivotOwner[col.back()] = static_cast<Id>(j);
    }
  }
  std::vector<PersistencePair> pairs;
  std::vector<bool> killed(order.size(), false);
  for (std::size_t j = 0; j < columns.size(); ++j)
  {
    if (!columns[j].empty())
    {
      killed[columns[j].back()] = true;
      killed[j] = true; // a destroyer is not a creator
      PersistencePair p;
      p.Birth = order[columns[j].back()];
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
  std::sort(pairs.begin(), pairs.end(), [](const PersistencePair& a, const PersistencePair& b) {
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
  });
  return pairs;
}

} // namespace flowrecon
