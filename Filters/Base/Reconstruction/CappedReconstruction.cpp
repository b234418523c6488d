#include "CappedReconstruction.h"

#include "DeferredPatches.h"
#include "DeferredReconstruction.h"
#include "HasseTopology.h"
#include "MemoryGuard.h"
#include "NodeIndices.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>

namespace flowrecon
{

namespace
{

CappedBuild Build(const std::vector<Point3>& points, const BuildOptions& options,
  double tpMax, double cap, bool defer, const Progress& progress, bool keepRaw)
{
  CappedBuild b;
  BuildOptions build = options;
  build.StableManifolds = false;
  build.UnstableManifolds = false;
  build.DeferPatchesAboveRatio = defer ? cap : HUGE_VAL;
  build.DeferFlowLinesAboveRatio = defer ? FlowLineDeferralRatio(cap, tpMax) : HUGE_VAL;
  // The build's triangulation is kept: the deferred patches and the drawing
  // walk on it (computing it again cost a quarter of a torus's run).
  std::unique_ptr<Retriangulation> triangulation;
  b.Complex = BuildFlowComplex(points, build, progress, &triangulation);
  b.Triangulation = std::move(triangulation);
  b.KeepRawPatchArcs = keepRaw;
  b.Cap = cap;
  b.PersistenceThreshold = tpMax;
  b.Deferred = defer;
  return b;
}

/// The build's complex for one run, copied or taken (`take`), with the 2-3 arcs
/// and (for the topology) the 1-2 arcs as built, out of the build's arcs: the
/// build does not hold them a second time.
void TakeBuild(CappedBuild& b, bool take, CappedReconstruction& r)
{
  // The indices by themselves: every arc reads its lower node's, at random,
  // and a Node is 56 bytes.
  const std::vector<std::int8_t> index = NodeIndices(b.Complex.Nodes);
  const auto lowerIndex = [&index](const Arc& a) { return index[static_cast<std::size_t>(a.Lower)]; };
  std::size_t cones = 0, raw = 0;
  for (const Arc& a : b.Complex.Arcs)
  {
    cones += lowerIndex(a) == 2 ? 1 : 0;
    raw += b.KeepRawPatchArcs && lowerIndex(a) == 1 ? 1 : 0;
  }
  if (!take)
  {
    // The nodes are lent, not copied (MoveNodes).
    const double bytes = static_cast<double>(sizeof(Arc)) *
      static_cast<double>(b.Complex.Arcs.size() + cones + raw);
    // The message counts the samples, a pass over every node: only when it
    // may be needed.
    if (bytes > AvailableMemory())
    {
      RequireMemory(bytes,
        "a copy of the flow complex of a " + std::to_string(b.Complex.CountByIndex()[0]) +
          "-point cloud for a second t_p",
        "give t_p a value (one run), or use fewer points");
    }
  }
  r.Cones.reserve(cones);
  r.RawPatchArcs.reserve(raw);
  for (const Arc& a : b.Complex.Arcs)
  {
    if (lowerIndex(a) == 2)
    {
      r.Cones.push_back(a);
    }
    else if (b.KeepRawPatchArcs && lowerIndex(a) == 1)
    {
      r.RawPatchArcs.push_back(a);
    }
  }
  if (!take)
  {
    FlowComplex lent;
    MoveNodes(b.Complex, lent);
    r.Complex = b.Complex;
    MoveNodes(lent, r.Complex);
  }
  else
  {
    r.Complex = std::move(b.Complex);
  }
  r.Triangulation = b.Triangulation;
  r.DeferredPatches = static_cast<Id>(r.Complex.DeferredPatches.size());
}

/// The flow lines the build stopped, and before a simplification those its
/// 2-3 cancellations will likely need.
void DeferLines(CappedReconstruction& r, double tp)
{
  FlowComplex& fc = r.Complex;
  if (fc.PendingFlowLines.empty())
  {
    return;
  }
  r.Lines = std::make_unique<DeferredFlowLines>(fc, r.Cones, *r.Triangulation);
  std::vector<PendingFlowLine>().swap(fc.PendingFlowLines);
  if (r.Simplified)
  {
    // The likely lowers of 2-3 cancellations: their Out lists move (see
    // DeferredFlowLines.h). Any other one makes the run start again eagerly.
    std::vector<Id> pivots;
    for (const Arc& a : r.Cones)
    {
      if (r.Lines->IsPending(a.Lower) &&
        PersistenceRatio(fc.Nodes[a.Upper].Value, fc.Nodes[a.Lower].Value) <= tp * tp)
      {
        pivots.push_back(a.Lower);
      }
    }
    r.Lines->Follow(pivots);
    r.Lines->CompleteRawArcs(fc.Arcs);
  }
}

/// The cancellations at t_p (when Simplified); then the deferred lines give
/// every arc below the cap.
void SimplifyRun(CappedReconstruction& r, double tp, double cap, const Progress& progress)
{
  FlowComplex& fc = r.Complex;
  if (r.Simplified)
  {
    // The replays record what they need: Lowers for patches, Uppers for lines.
    r.Simplification = Simplify(fc.Nodes, std::move(fc.Arcs), tp, progress,
      !fc.DeferredPatches.empty(), r.Lines != nullptr);
    fc.Arcs = std::move(r.Simplification.Arcs); // the reconstruction grows on the simplified diagram
    r.Simplification.Arcs = {};
  }
  else if (r.Lines)
  {
    // On every field: arcs that compare equal are equal, so the order does
    // not depend on the schedule.
    tbb::parallel_sort(fc.Arcs.begin(), fc.Arcs.end(), [](const Arc& a, const Arc& b) {
      return std::tie(a.Lower, a.Upper, a.Multiplicity) < std::tie(b.Lower, b.Upper, b.Multiplicity);
    });
  }
  if (r.Lines)
  {
    r.Lines->SetSimplification(r.Simplified ? &r.Simplification : nullptr, tp);
    // Upflow below the cap must see every arc it could use.
    r.Lines->Follow(r.Lines->NodesBelowRatio(cap));
    r.Lines->CompleteSimplifiedArcs(fc.Arcs);
  }
}

/// The queue up to the cap; `late`: it walks what the build deferred.
void GrowRun(CappedReconstruction& r, double cap, bool late, const Progress& progress)
{
  FlowComplex& fc = r.Complex;
  const std::vector<bool> survives =
    r.Simplified ? r.Simplification.Survives : std::vector<bool>(fc.Nodes.size(), true);
  const std::vector<Id> init = InitializationEdgesFromDiagram(fc.Nodes, fc.Arcs);
  const SimplificationResult* s = r.Simplified ? &r.Simplification : nullptr;
  if (!late)
  {
    r.Run = Reconstruct(fc.Nodes, fc.Arcs, survives, init, cap, progress);
    r.Carriers = CellCarriers(r.Run, s);
    return;
  }
  DeferredReconstruction walked = ReconstructDeferred(fc,
    r.Simplified ? &r.Simplification : nullptr, *r.Triangulation, init, cap, progress, r.Lines.get());
  r.Run = std::move(walked.Run);
  r.Carriers = std::move(walked.Carriers);
  r.WalkedLate = walked.WalkedLate;
  r.ReplayedOwners = walked.ReplayedOwners;
}

/// The rest of the run from `b`, at t_p (<= b's): b's parts are copied, or
/// moved when `take`.
CappedReconstruction Continue(CappedBuild& b, double tp, bool take, const Progress& progress)
{
  CappedReconstruction r;
  TakeBuild(b, take, r);
  auto t = std::chrono::steady_clock::now();
  auto lap = [&t]() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - t).count();
    t = now;
    return seconds;
  };
  r.Simplified = tp >= 1; // below 1 nothing is cancelled
  DeferLines(r, tp);
  const bool late = !r.Complex.DeferredPatches.empty() || r.Lines;
  SimplifyRun(r, tp, b.Cap, progress.Range(0, 0.5));
  r.SimplificationSeconds = lap();
  // The simplification's lists are freed: their pages go back to the system
  // (tbbmalloc's pools, which other runs' blocks may still hold, and glibc's
  // heap cannot reuse each other's memory).
  ReleaseFreedMemory();
  GrowRun(r, b.Cap, late, progress.Range(0.5, 1.0));
  r.QueueSeconds = lap();
  return r;
}

} // namespace

void MoveNodes(FlowComplex& from, FlowComplex& to)
{
  to.Nodes = std::move(from.Nodes);
  to.Points = std::move(from.Points);
  to.Representative = std::move(from.Representative);
  from.Nodes.clear();
  from.Points.clear();
  from.Representative.clear();
}

void ReturnNodes(CappedReconstruction& r, CappedBuild& build)
{
  MoveNodes(r.Complex, build.Complex);
}

HeldRun Hold(CappedReconstruction&& r)
{
  HeldRun h;
  h.Run = Pack(r.Run, r.Carriers);
  r.Complex = FlowComplex();
  r.Cones = std::vector<Arc>();
  r.RawPatchArcs = std::vector<Arc>();
  r.Simplification = SimplificationResult();
  r.Run = ReconstructionResult();
  r.Carriers = std::vector<Id>();
  r.Triangulation.reset();
  r.Lines.reset();
  h.Rest = std::move(r);
  return h;
}

CappedReconstruction Restore(HeldRun&& h, CappedBuild& build)
{
  CappedReconstruction r = std::move(h.Rest);
  r.Complex = std::move(build.Complex);
  // The build's own arcs and lines, not the run's (it simplified a copy).
  r.Complex.Arcs = std::vector<Arc>();
  r.Complex.PendingFlowLines = std::vector<PendingFlowLine>();
  r.Triangulation = build.Triangulation;
  Unpack(h.Run, r.Run, r.Carriers);
  h.Run = PackedRun();
  return r;
}

double FlowLineDeferralRatio(double cap, double persistenceThreshold)
{
  return 1.25 * cap * std::max(1.0, persistenceThreshold);
}

void CompleteCones(CappedReconstruction& r, const std::vector<Id>& nodes)
{
  if (!r.Lines)
  {
    return;
  }
  double highest = -HUGE_VAL;
  for (const Id n : nodes)
  {
    if (r.Complex.Nodes[n].Index == 3)
    {
      highest = std::max(highest, r.Complex.Nodes[n].Value);
    }
  }
  if (highest > -HUGE_VAL)
  {
    r.Lines->FollowBoundsUpTo(highest);
  }
  r.Lines->CompleteRawArcs(r.Cones);
}

CappedBuild BuildBelow(const std::vector<Point3>& points, BuildOptions options,
  double persistenceThreshold, double cap, bool allowDeferral, const Progress& progress,
  bool keepRawPatchArcs)
{
  if (!(cap > 1) || std::isnan(persistenceThreshold))
  {
    throw InputError("reconstruction: the cap must be above 1 and t_p a number");
  }
  const bool defer = allowDeferral && cap < HUGE_VAL && persistenceThreshold < cap;
  return Build(points, options, persistenceThreshold, cap, defer, progress, keepRawPatchArcs);
}

CappedReconstruction ReconstructBuilt(
  CappedBuild& build, double persistenceThreshold, bool take, const Progress& progress)
{
  if (!(persistenceThreshold <= build.PersistenceThreshold))
  {
    throw InputError("reconstruction: t_p above the one the build deferred for");
  }
  return Continue(build, persistenceThreshold, take, progress);
}

CappedReconstruction ReconstructBelow(const std::vector<Point3>& points, BuildOptions options,
  double persistenceThreshold, double cap, bool allowDeferral, const Progress& progress,
  bool keepRawPatchArcs)
{
  CappedBuild b = BuildBelow(points, options, persistenceThreshold, cap, allowDeferral,
    progress.Range(0, 0.7), keepRawPatchArcs);
  std::string because;
  try
  {
    return Continue(b, persistenceThreshold, true, progress.Range(0.7, 1));
  }
  catch (const Degenerate& e)
  {
    if (!b.Deferred)
    {
      throw;
    }
    because = e.what();
  }
  // A deferred walk met a tie the build never saw, or the deferred flow lines
  // could not be shown harmless: the eager build retries (with another
  // perturbation, as it would have).
  b = BuildBelow(points, options, persistenceThreshold, cap, false, progress.Range(0, 0.7),
    keepRawPatchArcs);
  CappedReconstruction r = Continue(b, persistenceThreshold, true, progress.Range(0.7, 1));
  r.EagerBecause = because;
  return r;
}

} // namespace flowrecon
