// The replay of the 1-2 cancellations on In lists the simplification never saw
// (CancellationReplay.h), against the simplification of the complete diagram
// as its oracle. On real flow complexes, the index-2 nodes y with V(y) > t_p * L
// (L the largest Gabriel-edge value: no 1-2 arc into y can ever be a candidate,
// the deferral rule of DeferredPatches.h) lose their 1-2 arcs; the partial
// diagram is simplified, each y replayed from its original In list, and then:
// the same pairs in the same order, every simplified arc into a surviving y,
// every other arc unchanged, and the owners of every cancelled node equal to
// the complete run's once the replays' owners are added.
#include "Check.h"
#include "Clouds.h"
#include "ReconFixtures.h"

#include "CancellationReplay.h"
#include "FlowComplexBuilder.h"
#include "Simplification.h"

#include <algorithm>
#include <iostream>
#include <map>
#include <string>

using namespace flowrecon;

namespace
{

struct Exercised
{
  long Replays = 0, Changed = 0, Owners = 0, Removed = 0;
};

void Compare(const std::string& name, const FlowComplex& fc, double tp, Exercised& seen)
{
  const std::vector<Node>& nodes = fc.Nodes;
  double largest = 0;
  for (const Node& n : nodes)
  {
    if (n.Index == 1 && !n.IsInfinity())
    {
      largest = std::max(largest, n.Value);
    }
  }
  std::vector<char> hidden(nodes.size(), 0);
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    hidden[i] = nodes[i].Index == 2 && !nodes[i].IsInfinity() && nodes[i].Value / largest > tp;
  }
  std::vector<Arc> partial;
  std::map<Id, std::vector<std::pair<Id, int>>> original;
  for (const Arc& a : fc.Arcs)
  {
    if (hidden[a.Upper] && nodes[a.Lower].Index == 1)
    {
      original[a.Upper].emplace_back(a.Lower, a.Multiplicity);
    }
    else
    {
      partial.push_back(a);
    }
  }
  const SimplificationResult eager = Simplify(nodes, fc.Arcs, tp, Progress());
  SimplificationResult lazy = Simplify(nodes, std::vector<Arc>(partial), tp, Progress(), true);
  const long hiddenCount = static_cast<long>(std::count(hidden.begin(), hidden.end(), 1));
  std::cout << name << ", t_p " << tp << ": " << eager.Pairs.size() << " pairs, " << hiddenCount
            << " hidden In lists\n";

  CHECK(eager.Pairs.size() == lazy.Pairs.size());
  bool samePairs = eager.Pairs.size() == lazy.Pairs.size();
  for (std::size_t p = 0; samePairs && p < eager.Pairs.size(); ++p)
  {
    samePairs = eager.Pairs[p].Lower == lazy.Pairs[p].Lower && eager.Pairs[p].Upper == lazy.Pairs[p].Upper;
  }
  CHECK(samePairs);
  CHECK(eager.Survives == lazy.Survives);
  if (!samePairs)
  {
    return;
  }

  const CancellationReplay replay(nodes.size(), lazy);
  std::vector<std::pair<Id, Id>> owners;
  std::map<std::pair<Id, Id>, int> replayed;
  for (auto& [y, in] : original)
  {
    std::vector<std::pair<Id, int>> list = in;
    std::sort(list.begin(), list.end());
    replay.Replay(y, list, owners);
    std::sort(list.begin(), list.end());
    ++seen.Replays;
    seen.Changed += list != in ? 1 : 0;
    if (lazy.Survives[y])
    {
      for (const auto& e : list)
      {
        replayed[{ e.first, y }] += e.second;
      }
    }
    else
    {
      ++seen.Removed;
    }
  }
  seen.Owners += static_cast<long>(owners.size());

  // Arcs: the complete run's arcs into hidden nodes are the replayed ones, and
  // the rest is what the partial run kept.
  std::map<std::pair<Id, Id>, int> expectedHidden, expectedRest;
  for (const Arc& a : eager.Arcs)
  {
    auto& m = hidden[a.Upper] && nodes[a.Lower].Index == 1 ? expectedHidden : expectedRest;
    m[{ a.Lower, a.Upper }] += a.Multiplicity;
  }
  CHECK(replayed == expectedHidden);
  CHECK(fixtures::ArcMap(lazy.Arcs) == expectedRest);

  // Owners: complete only with the replays' share.
  ResolveOwners(lazy, owners);
  CHECK(lazy.Owners.Offsets == eager.Owners.Offsets);
  CHECK(lazy.Owners.Values == eager.Owners.Values);
}

} // namespace

int main()
{
  struct Cloud
  {
    std::string Name;
    std::vector<Point3> Points;
  };
  const std::vector<Cloud> clouds = { { "cube", clouds::Cube(700, 3) },
    { "sphere", clouds::Sphere(900, 4) }, { "torus", clouds::Torus(1600, 5) },
    { "torus, denser", clouds::Torus(4000, 6) } };
  Exercised seen;
  for (const Cloud& c : clouds)
  {
    BuildOptions options;
    options.StableManifolds = false;
    options.UnstableManifolds = false;
    const FlowComplex fc = BuildFlowComplex(c.Points, options, Progress());
    for (const double tp : { 1.05, 1.3, 2.0, 4.0 })
    {
      Compare(c.Name, fc, tp, seen);
    }
  }
  std::cout << seen.Replays << " replays, " << seen.Changed << " changed lists, " << seen.Removed
            << " of cancelled nodes, " << seen.Owners << " owners found\n";
  // The oracle compares something only if the replays did work.
  CHECK(seen.Changed > 100 && seen.Owners > 100 && seen.Removed > 10);
  return check::Finish("TestCancellationReplay");
}
