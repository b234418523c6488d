#include "DeferredReconstruction.h"

#include "DeferredFlowLines.h"
#include "DeferredPatches.h"

#include <algorithm>
#include <optional>
#include <tuple>

namespace flowrecon
{

DeferredReconstruction ReconstructDeferred(FlowComplex& fc, SimplificationResult* s,
  const Retriangulation& re, const std::vector<Id>& init, double cap, const Progress& progress,
  DeferredFlowLines* lines)
{
  if (!(cap <= fc.DeferralRatio))
  {
    throw InputError("the reconstruction's cap is above the ratio the flow complex deferred "
                     "its patches from");
  }
  DeferredReconstruction r;
  const std::vector<bool> survives = s ? s->Survives : std::vector<bool>(fc.Nodes.size(), true);
  // Without deferred patches (deferred flow lines only) the replay is not needed.
  std::optional<DeferredPatches> deferred;
  if (!fc.DeferredPatches.empty())
  {
    deferred.emplace(fc, s, re);
  }
  std::vector<Arc> walked;
  Progress quiet;
  quiet.ShouldAbort = progress.ShouldAbort;
  LateArcs late;
  late.Deferred = deferred ? deferred->Flags() : std::vector<char>(fc.Nodes.size(), 0);
  late.Ratio = fc.DeferralRatio;
  late.Walk = [&](const std::vector<Id>& nodes) {
    std::vector<Arc> arcs = deferred ? deferred->Walk(nodes, quiet) : std::vector<Arc>();
    walked.insert(walked.end(), arcs.begin(), arcs.end());
    r.WalkedLate += static_cast<Id>(nodes.size());
    return arcs;
  };
  if (lines)
  {
    late.FlowLinesInto = [&](Id maximum, const std::vector<Insertion>& run) {
      return lines->InChangesUpTo(fc.Nodes[maximum].Value, fc.Arcs, &run);
    };
  }
  r.Run = Reconstruct(fc.Nodes, fc.Arcs, survives, init, cap, progress, late);
  r.Carriers = CellCarriers(r.Run, s);
  if (s && !fc.DeferredPatches.empty())
  {
    // A 1-2 cancellation hands its cells to every successor of its lower, the
    // deferred ones too. They matter where they carry cells below the cap: the
    // inserted ones (walked above) and the cancelled ones whose own owners
    // (maxima, known) are inserted. Replaying those completes the owners.
    std::vector<Id> carried;
    for (const Id y : fc.DeferredPatches)
    {
      if (!s->Survives[y] && r.Carriers[y] >= 0)
      {
        carried.push_back(y);
      }
    }
    deferred->Walk(carried, quiet);
    r.WalkedLate += static_cast<Id>(carried.size());
    const std::vector<std::pair<Id, Id>> extra = deferred->ExtraOwners();
    r.ReplayedOwners = static_cast<Id>(extra.size());
    ResolveOwners(*s, extra);
    r.Carriers = CellCarriers(r.Run, s);
  }
  if (!walked.empty())
  {
    fc.Arcs.insert(fc.Arcs.end(), walked.begin(), walked.end());
    std::sort(fc.Arcs.begin(), fc.Arcs.end(), [](const Arc& a, const Arc& b) {
      return std::tie(a.Lower, a.Upper) < std::tie(b.Lower, b.Upper);
    });
  }
  return r;
}

} // namespace flowrecon
