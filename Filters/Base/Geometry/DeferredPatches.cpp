#include "DeferredPatches.h"

#include "Arithmetic.h"
#include "Retriangulation.h"
#include "StableManifold.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace flowrecon
{

DeferredPatches::DeferredPatches(const FlowComplex& fc, const SimplificationResult* simplification,
  const Retriangulation& retriangulation)
  : FC(fc)
  , S(simplification)
  , Re(retriangulation)
  , Deferred(fc.Nodes.size(), 0)
  , Walked(fc.Nodes.size(), 0)
{
  for (const Id y : fc.DeferredPatches)
  {
    if (y < retriangulation.Base2() || y >= retriangulation.Base3())
    {
      throw InputError("deferred patches: node " + std::to_string(y) + " is not an index-2 node");
    }
    this->Deferred[y] = 1;
  }
  if (!simplification)
  {
    return;
  }
  this->Replayer = std::make_unique<CancellationReplay>(fc.Nodes.size(), *simplification);
  for (const CancelledPair& pair : simplification->Pairs)
  {
    // A deferred node as the upper of a 1-2 pair means a threshold at or above
    // the deferral ratio: its lowers were never known.
    // So does any pair of ratio >= the deferral ratio (a stored file may say
    // so): such a cancellation could have used the arcs the complex lacks.
    if ((this->Deferred[pair.Upper] && pair.PairType == 1) || !(pair.Ratio < fc.DeferralRatio))
    {
      throw InputError("deferred patches: a cancellation at or above the deferral ratio");
    }
  }
}

std::vector<Arc> DeferredPatches::Walk(const std::vector<Id>& nodes, const Progress& progress)
{
  std::vector<Id> todo;
  for (const Id y : nodes)
  {
    if (y >= 0 && y < static_cast<Id>(this->Deferred.size()) && this->Deferred[y])
    {
      todo.push_back(y);
    }
  }
  std::sort(todo.begin(), todo.end());
  todo.erase(std::unique(todo.begin(), todo.end()), todo.end());
  const CriticalSimplices& cs = this->Re.Critical();
  const Id base1 = this->Re.Base2() - cs.Edges.ValueCount();
  std::vector<std::vector<Id>> arrivals(todo.size());
  std::vector<Id> fallbacks(todo.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, todo.size()),
    [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k)
      {
        const std::size_t f = static_cast<std::size_t>(todo[k] - this->Re.Base2());
        arrivals[k] = ComputeStableManifold(
          this->Re.Tri(), cs, f, false, fallbacks[k], this->Re.Options().ExactOnly)
                        .Arrivals;
        std::sort(arrivals[k].begin(), arrivals[k].end());
      }
    });
  progress(0.5, "deferred patches");
  std::vector<Arc> arcs;
  std::vector<std::pair<Id, int>> in;
  for (std::size_t k = 0; k < todo.size(); ++k)
  {
    const Id y = todo[k];
    const std::size_t f = static_cast<std::size_t>(y - this->Re.Base2());
    const Id v[3] = { cs.Facets[f].Vertices[0], cs.Facets[f].Vertices[1], cs.Facets[f].Vertices[2] };
    if (!this->Re.SameSimplex(this->FC, y, v, 3))
    {
      throw InputError(Retriangulation::Mismatch());
    }
    in.clear();
    for (const Id e : arrivals[k])
    {
      if (!in.empty() && in.back().first == base1 + e)
      {
        ++in.back().second;
      }
      else
      {
        in.emplace_back(base1 + e, 1);
      }
    }
    if (this->Replayer)
    {
      std::vector<std::pair<Id, Id>> again;
      this->Replayer->Replay(y, in, this->Walked[y] ? again : this->Owners);
    }
    this->Walked[y] = 1;
    if (this->S && !this->S->Survives[y])
    {
      continue;
    }
    std::sort(in.begin(), in.end());
    for (const auto& e : in)
    {
      arcs.emplace_back(e.first, y, e.second);
    }
  }
  progress(1.0, "deferred patches");
  return arcs;
}

std::vector<std::pair<Id, Id>> DeferredPatches::ExtraOwners() const
{
  std::vector<std::pair<Id, Id>> owners(this->Owners);
  std::sort(owners.begin(), owners.end());
  owners.erase(std::unique(owners.begin(), owners.end()), owners.end());
  return owners;
}

void WalkEveryDeferredPatch(FlowComplex& fc, const Progress& progress, const std::string& advice)
{
  if (fc.DeferredPatches.empty())
  {
    return;
  }
  const std::unique_ptr<Retriangulation> re =
    Retriangulation::OfStoredComplex(fc, progress.Range(0, 0.5), advice);
  DeferredPatches walker(fc, nullptr, *re);
  std::vector<Arc> more;
  try
  {
    more = walker.Walk(fc.DeferredPatches, progress.Range(0.5, 1));
  }
  catch (const Degenerate&)
  {
    // The build perturbs on a tie, but it never walked this patch: the stored
    // complex cannot be completed as it is.
    throw InputError("a deferred patch met a tie the flow complex did not see: build the "
                     "flow complex again with Defer Patches Above set to 0, or from the cloud");
  }
  fc.Arcs.insert(fc.Arcs.end(), more.begin(), more.end());
  fc.DeferredPatches.clear();
  fc.DeferralRatio = HUGE_VAL;
}

} // namespace flowrecon
