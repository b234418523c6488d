#include "TopologyInput.h"

#include "DeferredPatches.h"
#include "ExteriorRegions.h"
#include "HasseTopology.h"
#include "HugePages.h"
#include "MemoryGuard.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace flowrecon
{

namespace
{

/// The 0-1 arcs of every edge, cancelled ones too (the simplified diagram has
/// none for those): its two samples.
void AppendEdgeEnds(const FlowComplex& fc, std::vector<Arc>& raw)
{
  Id samples = 0;
  for (const Node& v : fc.Nodes)
  {
    samples = std::max<Id>(samples, v.Index == 0 ? v.Simplex[0] + 1 : 0);
  }
  std::vector<std::int32_t> nodeOfSample(static_cast<std::size_t>(samples), -1);
  for (std::size_t v = 0; v < fc.Nodes.size(); ++v)
  {
    if (fc.Nodes[v].Index == 0)
    {
      nodeOfSample[fc.Nodes[v].Simplex[0]] = static_cast<std::int32_t>(v);
    }
  }
  for (std::size_t v = 0; v < fc.Nodes.size(); ++v)
  {
    if (fc.Nodes[v].Index == 1)
    {
      for (int k = 0; k < 2; ++k)
      {
        const std::int32_t s = fc.Nodes[v].Simplex[k];
        if (s < 0 || s >= samples || nodeOfSample[s] < 0)
        {
          throw InputError("topology: edge " + std::to_string(v) + " has no sample node");
        }
        raw.emplace_back(nodeOfSample[s], static_cast<Id>(v), 1);
      }
    }
  }
}

/// The lines not followed: ended at their regions of {d > r*} (TopologyInput.h);
/// `regions` is reused when its level is high enough. Throws Degenerate when
/// the proof's premises fail to be shown.
void EndInRegions(CappedReconstruction& r, TopologyInput& t, std::size_t cones,
  std::unique_ptr<ExteriorRegions>& regions)
{
  const FlowComplex& fc = r.Complex;
  double reached = 0; // r*
  for (std::size_t v = 0; v < fc.Nodes.size(); ++v)
  {
    if (t.Presence[v] < HUGE_VAL)
    {
      reached = std::max(reached, fc.Nodes[v].Value);
    }
  }
  // Values are rounded from exact quantities: a relative margin keeps above.
  // The triangulation's units are the values' times 2^-ScaleExponent. A
  // perturbed run draws on the perturbed points while its values are the
  // input's: a node's perturbed value is at most its value plus the reach of
  // the perturbation (FlowComplexBuilder.cpp, LowerPendingBounds), so the
  // drawn reconstructions stay within r* plus that reach.
  const Retriangulation& re = *r.Triangulation;
  const int e = re.Prepared().ScaleExponent;
  const double reach = 1.8 * std::ldexp(fc.Report.PerturbationMagnitude, -e);
  const double level = (std::ldexp(reached, -e) + reach) * (1 + 1e-9) + 1e-300;
  if (!regions || regions->Of() != re.Tri().Serial() || !(regions->Level() >= level * level))
  {
    regions.reset();
    regions = std::make_unique<ExteriorRegions>(re.Tri(), level * level);
  }
  const std::vector<DeferredFlowLines::Ends> ends =
    r.Lines->EndsAbove(std::nextafter(regions->Level(), HUGE_VAL));
  // Each region's first maximum (infinity for the unbounded one): the others
  // join it. A bounded region holds the maximum of the distance over it.
  std::vector<Id> first(static_cast<std::size_t>(regions->Count()), -1);
  auto absent = [&](Id m) {
    if (t.Presence[m] < HUGE_VAL)
    {
      throw Degenerate("topology: a maximum above every reconstruction is in one");
    }
    return m;
  };
  if (regions->InfiniteRegion() >= 0)
  {
    first[regions->InfiniteRegion()] = absent(fc.InfinityNode);
  }
  const CriticalSimplices& cs = re.Critical();
  for (std::size_t i = 0; i < cs.Cells.size(); ++i)
  {
    const std::int32_t region = regions->RegionOf(cs.Cells[i].Cell);
    if (region < 0)
    {
      continue;
    }
    const Id m = absent(re.Base3() + static_cast<Id>(i));
    if (first[region] < 0)
    {
      first[region] = m;
    }
    else
    {
      t.Joined.emplace_back(m, first[region]);
    }
  }
  if (std::find(first.begin(), first.end(), -1) != first.end())
  {
    throw Degenerate("topology: a region of the complement without a maximum");
  }
  std::vector<Arc> rows;
  bool reachesPresent = false; // a walk that ended at a maximum some reconstruction holds
  for (const DeferredFlowLines::Ends& e : ends)
  {
    Id to[2];
    for (int s = 0; s < 2; ++s)
    {
      const Id end = e.End[s];
      if (end == -1 || (end <= -2 && regions->RegionOf(-2 - end) < 0))
      {
        throw Degenerate("topology: a pending line without its end");
      }
      to[s] = end >= 0 ? end : first[regions->RegionOf(-2 - end)];
      reachesPresent = reachesPresent || (end >= 0 && t.Presence[end] < HUGE_VAL);
      t.LinesToRegions += end >= 0 ? 0 : 1;
    }
    if (to[0] == to[1])
    {
      rows.emplace_back(e.Node, to[0], 2);
    }
    else
    {
      rows.emplace_back(e.Node, to[0], 1);
      rows.emplace_back(e.Node, to[1], 1);
    }
  }
  ReplaceRows(t.Arcs, cones, rows);
  if (reachesPresent)
  {
    // Its node is drawn with that maximum's cone. The nodes this adds have
    // values below the maximum's, so r* and the regions stand.
    t.Presence = PresenceTimes(fc.Nodes, t.Arcs, r.Carriers, r.Run);
  }
  t.Regions = regions->Count();
  t.CellsAbove = regions->CellsAbove();
}

} // namespace

TopologyInput TopologyOfCappedRun(CappedReconstruction& r, std::unique_ptr<ExteriorRegions>* shared)
{
  const FlowComplex& fc = r.Complex;
  if (r.Lines)
  {
    r.Lines->CompleteRawArcs(r.Cones); // what the run followed
  }
  // Memory: the raw arcs (the 1-2 ones kept, two per edge, the cones), the
  // regions (9 bytes a cell while built: a flag, the union-find, the labels)
  // and the topology's arrays after them (HasseBarcode: ~40 bytes a node).
  const double cells = r.Triangulation ? static_cast<double>(r.Triangulation->Tri().NumberOfCells()) : 0;
  RequireMemory(static_cast<double>(sizeof(Arc)) *
        static_cast<double>(r.RawPatchArcs.size() + 2 * fc.CountByIndex()[1] + r.Cones.size()) +
      9.0 * cells + 40.0 * static_cast<double>(fc.Nodes.size()),
    "the Betti numbers of a " + std::to_string(fc.CountByIndex()[0]) + "-point cloud's reconstructions",
    "turn the topology off with given thresholds, or use fewer points");
  TopologyInput t;
  std::vector<Arc>& raw = t.Arcs;
  raw.swap(r.RawPatchArcs);
  // One allocation for all (growing by doubling copied ~10^7 arcs twice).
  ReserveHuge(raw, raw.size() + 2 * static_cast<std::size_t>(fc.CountByIndex()[1]) + r.Cones.size() +
    (r.Lines ? 2 * r.Lines->Nodes().size() : 0));
  AppendEdgeEnds(fc, raw);
  std::size_t cones = raw.size(); // the 2-3 arcs are the tail, by lower node
  raw.insert(raw.end(), r.Cones.begin(), r.Cones.end());
  if (!fc.DeferredPatches.empty())
  {
    // The deferred patches drawn below the cap: theirs, or a maximum's over them.
    const std::vector<double> presence = PresenceTimes(fc.Nodes, raw, r.Carriers, r.Run);
    std::vector<Id> drawn;
    for (const Id y : fc.DeferredPatches)
    {
      if (presence[y] < HUGE_VAL)
      {
        drawn.push_back(y);
      }
    }
    DeferredPatches walker(fc, nullptr, *r.Triangulation);
    const std::vector<Arc> more = walker.Walk(drawn, Progress());
    raw.insert(raw.begin() + static_cast<std::ptrdiff_t>(cones), more.begin(), more.end());
    cones += more.size();
  }
  // Without the pending lines' sides: those that end at a maximum some
  // reconstruction holds are walked to it, and added then (EndInRegions).
  t.Presence = PresenceTimes(fc.Nodes, raw, r.Carriers, r.Run);
  if (!r.Lines)
  {
    return t;
  }
  const Id followed = r.Lines->LinesFollowed();
  std::unique_ptr<ExteriorRegions> own;
  try
  {
    EndInRegions(r, t, cones, shared ? *shared : own);
  }
  catch (const Degenerate&)
  {
    // Not shown: every line is followed (a tie there is the caller's Degenerate).
    t.Joined.clear();
    t.LinesToRegions = t.Regions = t.CellsAbove = 0;
    r.Lines->Follow(r.Lines->Nodes());
    ReplaceRows(raw, cones, r.Lines->FollowedRawArcs());
    t.Presence = PresenceTimes(fc.Nodes, raw, r.Carriers, r.Run);
  }
  t.LinesFollowed = r.Lines->LinesFollowed() - followed;
  return t;
}

} // namespace flowrecon
