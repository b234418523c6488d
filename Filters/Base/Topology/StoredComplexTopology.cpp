#include "StoredComplexTopology.h"

#include "AutomaticThresholds.h"
#include "DeferredPatches.h"
#include "DeferredReconstruction.h"
#include "HasseTopology.h"
#include "Reconstruction.h"
#include "Simplification.h"

#include <cmath>

namespace flowrecon
{

StoredTopology TopologyOfStoredComplex(const FlowComplex& fc, double tp, double cap,
  const Retriangulation* re, const Progress& progress)
{
  StoredTopology t;
  t.PersistenceThreshold = tp;
  const bool deferred = !fc.DeferredPatches.empty();
  if (deferred && !(cap <= fc.DeferralRatio && tp < fc.DeferralRatio))
  {
    throw InputError("the thresholds searched (up to " + std::to_string(cap) +
      ") must not exceed the ratio the flow complex deferred its patches from (" +
      std::to_string(fc.DeferralRatio) + ")");
  }
  if (deferred && !re)
  {
    throw InputError("the deferred patches need the triangulation of the samples");
  }
  const bool simplified = tp >= 1;
  SimplificationResult s;
  if (simplified)
  {
    s = Simplify(fc.Nodes, std::vector<Arc>(fc.Arcs), tp, progress.Range(0, 0.3), deferred);
  }
  const std::vector<Id> init = InitializationEdgesFromDiagram(fc.Nodes, fc.Arcs);
  ReconstructionResult run;
  std::vector<Id> carriers;
  if (!deferred)
  {
    run = Reconstruct(fc.Nodes, simplified ? s.Arcs : fc.Arcs,
      simplified ? s.Survives : std::vector<bool>(fc.Nodes.size(), true), init, HUGE_VAL,
      progress.Range(0.3, 0.7));
    carriers = CellCarriers(run, simplified ? &s : nullptr);
  }
  else
  {
    // The run walks the patches it needs on its own copy of the diagram.
    FlowComplex diagram = fc;
    if (simplified)
    {
      diagram.Arcs = std::move(s.Arcs);
    }
    DeferredReconstruction late = ReconstructDeferred(
      diagram, simplified ? &s : nullptr, *re, init, cap, progress.Range(0.3, 0.7));
    run = std::move(late.Run);
    carriers = std::move(late.Carriers);
  }
  t.MaximumThresholds = MaximumThresholds(fc.Nodes, carriers, run);
  try
  {
    t.Bars = BarsOfStoredRun(fc, carriers, run, re, progress.Range(0.7, 1));
    t.Profile = TopologyProfile(t.Bars, 1, cap);
  }
  catch (const InputError& e)
  {
    t.Error = e.what();
  }
  return t;
}

std::vector<Bar> BarsOfStoredRun(const FlowComplex& fc, const std::vector<Id>& carriers,
  const ReconstructionResult& run, const Retriangulation* re, const Progress& progress)
{
  // The raw diagram: the stored arcs, and those of the deferred patches drawn
  // (theirs, or a maximum's over them) that no run walked yet, unsimplified.
  std::vector<Arc> raw = fc.Arcs;
  if (!fc.DeferredPatches.empty())
  {
    if (!re)
    {
      throw InputError("the deferred patches need the triangulation of the samples");
    }
    // A walked patch has its 1-2 arcs (a 2-cell is bounded by edges).
    std::vector<char> walked(fc.Nodes.size(), 0);
    for (const Arc& a : raw)
    {
      if (fc.Nodes[a.Upper].Index == 2)
      {
        walked[a.Upper] = 1;
      }
    }
    const std::vector<double> before = PresenceTimes(fc.Nodes, raw, carriers, run);
    std::vector<Id> drawn;
    for (const Id y : fc.DeferredPatches)
    {
      if (before[y] < HUGE_VAL && !walked[y])
      {
        drawn.push_back(y);
      }
    }
    DeferredPatches walker(fc, nullptr, *re);
    const std::vector<Arc> more = walker.Walk(drawn, progress.Range(0, 0.6));
    raw.insert(raw.end(), more.begin(), more.end());
  }
  progress(0.6, "Betti numbers");
  return HasseBarcode(fc.Nodes, raw, PresenceTimes(fc.Nodes, raw, carriers, run));
}

} // namespace flowrecon
