// Invariants of every flow complex (docs/algorithm.md §8.1), as predicates: the
// core's tests CHECK them, the core's fuzzer aborts on them.
#ifndef flowrecon_Invariants_h
#define flowrecon_Invariants_h

#include "FlowComplex.h"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace invariants
{
using flowrecon::Arc;
using flowrecon::FlowComplex;
using flowrecon::Id;
using flowrecon::Node;

/// dd = 0 mod 2 over the odd arcs, with or without the arcs to the maximum at
/// infinity.
inline bool BoundaryOfBoundaryIsZero(
  const std::vector<Node>& nodes, const std::vector<Arc>& arcs, bool withInfinity)
{
  std::map<Id, std::vector<Id>> below;
  for (const Arc& a : arcs)
    if (a.Multiplicity % 2 == 1 && (withInfinity || !nodes[a.Upper].IsInfinity()))
      below[a.Upper].push_back(a.Lower);
  for (const auto& entry : below)
  {
    std::map<Id, int> parity;
    for (const Id b : entry.second)
    {
      const auto it = below.find(b);
      if (it != below.end())
        for (const Id bb : it->second)
          parity[bb] ^= 1;
    }
    for (const auto& p : parity)
      if (p.second != 0)
        return false;
  }
  return true;
}

/// For each node with a drawn patch, how many of its triangles use each edge.
using EdgeUse = std::map<Id, std::map<std::pair<Id, Id>, int>>;
inline EdgeUse PatchEdgeUse(const FlowComplex& fc)
{
  EdgeUse use;
  for (std::size_t t = 0; t < fc.Triangles.size(); ++t)
  {
    const auto& tr = fc.Triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      const Id a = std::min(tr[k], tr[(k + 1) % 3]), b = std::max(tr[k], tr[(k + 1) % 3]);
      ++use[fc.TriangleNode[t]][{ a, b }];
    }
  }
  return use;
}

/// The index-1 node of each Gabriel edge, by its two samples.
inline std::map<std::pair<Id, Id>, Id> GabrielNodes(const FlowComplex& fc)
{
  std::map<std::pair<Id, Id>, Id> gabriel;
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
    if (fc.Nodes[i].Index == 1)
      gabriel[{ fc.Nodes[i].Simplex[0], fc.Nodes[i].Simplex[1] }] = static_cast<Id>(i);
  return gabriel;
}

/// Every index-2 node has a patch; a patch's edges between samples are Gabriel
/// edges, each used as often as its arc's multiplicity, and its other edges are
/// shared by two of its triangles.
inline bool PatchesBoundedByGabrielEdges(const FlowComplex& fc, const EdgeUse& use)
{
  const auto gabriel = GabrielNodes(fc);
  std::map<std::pair<Id, Id>, int> multiplicity;
  for (const Arc& a : fc.Arcs)
    multiplicity[{ a.Lower, a.Upper }] = a.Multiplicity;
  for (const auto& patch : use)
    for (const auto& e : patch.second)
    {
      if (e.first.first < fc.NumberOfInputPoints && e.first.second < fc.NumberOfInputPoints)
      {
        const auto g = gabriel.find(e.first);
        if (g == gabriel.end() || multiplicity[{ g->second, patch.first }] != e.second)
          return false;
      }
      else if (e.second != 2)
        return false;
    }
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
    if (fc.Nodes[i].Index == 2 && use.count(static_cast<Id>(i)) != 1)
      return false;
  return true;
}

} // namespace invariants

#endif
