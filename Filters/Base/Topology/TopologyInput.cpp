#include "TopologyInput.h"

#include "DeferredPatches.h"
#include "ExteriorRegions.h"
#include "HasseTopology.h"
#include "HugePages.h"
#include "MemoryGuard.h"

#include <algorithm>
#include <array>
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
  // One pass for the samples' nodes: a pass over millions of nodes of 56
  // bytes each costs more than the growing array.
  std::vector<std::int32_t> nodeOfSample;
  for (std::size_t v = 0; v < fc.Nodes.size(); ++v)
  {
    const Node& node = fc.Nodes[v];
    if (node.Index == 0 && node.Simplex[0] >= 0)
    {
      const std::size_t s = static_cast<std::size_t>(node.Simplex[0]);
      if (s >= nodeOfSample.size())
      {
        nodeOfSample.resize(std::max(s + 1, 2 * nodeOfSample.size()), -1);
      }
      nodeOfSample[s] = static_cast<std::int32_t>(v);
    }
  }
  const Id samples = static_cast<Id>(nodeOfSample.size());
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

/// For k = 0..deepest: the least presence of a node whose value exceeds
/// r* / 2^k (+inf: none). A node present at t < first[k] sees only values up
/// to r* / 2^k present by t, its own and those before it (ties included).
std::vector<double> FirstAbove(const FlowComplex& fc, const std::vector<double>& presence,
  double reached, int deepest)
{
  std::vector<double> first(static_cast<std::size_t>(deepest) + 1, HUGE_VAL);
  // The levels once (ldexp per node was half of this pass), and per node only
  // the least level it exceeds: first[] is then a running minimum.
  std::vector<double> levels(first.size());
  for (int k = 0; k <= deepest; ++k)
  {
    levels[k] = std::ldexp(reached, -k);
  }
  for (std::size_t v = 0; v < fc.Nodes.size(); ++v)
  {
    const double value = fc.Nodes[v].Value;
    if (presence[v] < HUGE_VAL && value > levels[deepest])
    {
      int k = deepest;
      while (k > 0 && value > levels[k - 1])
      {
        --k;
      }
      first[k] = std::min(first[k], presence[v]);
    }
  }
  for (int k = 1; k <= deepest; ++k)
  {
    first[k] = std::min(first[k], first[k - 1]);
  }
  return first;
}

/// Ends the lines of the nodes flagged in `only` at the regions of `regions`:
/// a line's side is its maximum when the walk met it, else the first maximum
/// of the region where it stopped. With `joined`, every maximum of a region is
/// joined to its first and none may be present (the top level, r*). Appends
/// the rows; returns whether a walk ended at a maximum some reconstruction
/// holds. `memo`: the ends at this level, kept across the runs of one build.
bool EndAt(CappedReconstruction& r, TopologyInput& t, const ExteriorRegions& regions,
  const std::vector<char>& only, bool joined, std::vector<Arc>& rows,
  DeferredFlowLines::EndMemo* memo = nullptr)
{
  const FlowComplex& fc = r.Complex;
  const Retriangulation& re = *r.Triangulation;
  const std::vector<DeferredFlowLines::Ends> ends =
    r.Lines->EndsAbove(std::nextafter(regions.Level(), HUGE_VAL), &only, memo);
  // Each region's first maximum (infinity for the unbounded one): the others
  // join it. A bounded region holds the maximum of the distance over it.
  std::vector<Id> first(static_cast<std::size_t>(regions.Count()), -1);
  auto absent = [&](Id m) {
    if (joined && t.Presence[m] < HUGE_VAL)
    {
      throw Degenerate("topology: a maximum above every reconstruction is in one");
    }
    return m;
  };
  if (regions.InfiniteRegion() >= 0)
  {
    first[regions.InfiniteRegion()] = absent(fc.InfinityNode);
  }
  const CriticalSimplices& cs = re.Critical();
  for (std::size_t i = 0; i < cs.Cells.size(); ++i)
  {
    const std::int32_t region = regions.RegionOf(cs.Cells[i].Cell);
    if (region < 0)
    {
      continue;
    }
    const Id m = absent(re.Base3() + static_cast<Id>(i));
    if (first[region] < 0)
    {
      first[region] = m;
    }
    else if (joined)
    {
      t.Joined.emplace_back(m, first[region]);
    }
  }
  if (std::find(first.begin(), first.end(), -1) != first.end())
  {
    throw Degenerate("topology: a region of the complement without a maximum");
  }
  bool reachesPresent = false;
  for (const DeferredFlowLines::Ends& e : ends)
  {
    Id to[2];
    for (int s = 0; s < 2; ++s)
    {
      const Id end = e.End[s];
      if (end == -1 || (end <= -2 && regions.RegionOf(-2 - end) < 0))
      {
        throw Degenerate("topology: a pending line without its end");
      }
      to[s] = end >= 0 ? end : first[regions.RegionOf(-2 - end)];
      reachesPresent = reachesPresent || (end >= 0 && t.Presence[end] < HUGE_VAL);
      t.LinesToRegions += end >= 0 ? 0 : 1;
      t.LinesToLowerLevels += end >= 0 || joined ? 0 : 1;
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
  return reachesPresent;
}

/// The lines not followed, ended at regions of {d > level} (TopologyInput.h):
/// those of nodes no reconstruction holds at r*, the top level (`regions`,
/// reused when its level is high enough); those of a node present at t at
/// the least of a few lower levels (r* / 2^k) above every value present by t.
/// Throws Degenerate when the proof's premises fail to be shown.
void EndInRegions(CappedReconstruction& r, TopologyInput& t, std::size_t cones, SharedRegions& shared)
{
  std::unique_ptr<ExteriorRegions>& regions = shared.Regions;
  const FlowComplex& fc = r.Complex;
  const std::size_t n = fc.Nodes.size();
  double reached = 0; // r*
  for (std::size_t v = 0; v < n; ++v)
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
  auto levelSq = [&](double value) {
    const double level = (std::ldexp(value, -e) + reach) * (1 + 1e-9) + 1e-300;
    return level * level;
  };
  // Levels: a node present at t needs U above the values present by t (the
  // union-find of HasseBarcode then already joins every maximum of a region
  // of it: no join is needed, unlike at r*, where the lines of nodes never
  // present are merged first). A lower level stops the walk sooner: the lines
  // of a surface sample's patches end near the surface instead of at the
  // medial axis, once the run has inserted the inner maxima at t_p 0.
  constexpr int Deepest = 8;
  constexpr std::int8_t Shared = -1; // the level of another candidate's r*
  // Levels below r*: the first costs a flood of the cells, each deeper one
  // what enters U below the one before (ExteriorRegions::Descend).
  constexpr int Passes = 3;
  const std::vector<Id>& nodes = r.Lines->Nodes();
  std::vector<char> pending(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    pending[i] = r.Lines->IsPending(nodes[i]);
  }
  const std::vector<double> first = FirstAbove(fc, t.Presence, reached, Deepest);
  std::vector<std::int8_t> level(nodes.size(), 0); // k: r* / 2^k; 0: r*
  std::vector<std::size_t> count(Deepest + 1, 0);
  std::size_t present = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    if (pending[i] && t.Presence[nodes[i]] < HUGE_VAL)
    {
      int k = 0;
      while (k < Deepest && t.Presence[nodes[i]] < first[k + 1])
      {
        ++k;
      }
      level[i] = static_cast<std::int8_t>(k);
      ++count[k];
      ++present;
    }
  }
  // A lower r* of another candidate, whose regions and line ends are made
  // already, is a level like the others for the nodes present before any
  // value above it (Shared): those within two halvings of their own level
  // take it, and only the others count for the levels below.
  const bool share = regions && regions->Of() == re.Tri().Serial() && shared.Reached > 0 &&
    shared.Reached < reached;
  const double sharedReached = shared.Reached; // the top may replace the regions below
  const double firstShared = share ? FirstAbove(fc, t.Presence, sharedReached, 0)[0] : -HUGE_VAL;
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    if (share && pending[i] && t.Presence[nodes[i]] < firstShared &&
      shared.Reached <= 4 * std::ldexp(reached, -level[i]))
    {
      --count[level[i]];
      --present;
      level[i] = Shared;
    }
  }
  // The levels holding an eighth of those nodes or more, the deepest
  // `Passes`; a node of another level goes up to the next one kept.
  std::vector<char> kept(Deepest + 1, 0);
  kept[0] = 1;
  for (int k = Deepest, passes = 0; k >= 1 && passes < Passes; --k)
  {
    if (count[k] > 0 && 8 * count[k] >= present)
    {
      kept[k] = 1;
      ++passes;
    }
  }
  for (std::int8_t& k : level)
  {
    while (k != Shared && !kept[k])
    {
      --k;
    }
  }
  std::vector<Arc> rows;
  bool reachesPresent = false;
  std::vector<char> only(n, 0);
  auto flag = [&](int k) {
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
      only[nodes[i]] = pending[i] && level[i] == k;
    }
  };
  if (share)
  {
    flag(Shared);
    const Id before = t.LinesToLowerLevels;
    reachesPresent = EndAt(r, t, *regions, only, false, rows, &shared.Ends) || reachesPresent;
    t.LinesToSharedLevel = t.LinesToLowerLevels - before;
  }
  // The lower levels from the highest down: one set of regions, each level's
  // from the one above (ExteriorRegions::Descend), where a flood each cost
  // the same again (they hold nearly the same cells).
  int lowerLeft = static_cast<int>(std::count(kept.begin() + 1, kept.end(), 1));
  std::unique_ptr<ExteriorRegions> lower;
  for (int k = 1; k <= Deepest; ++k)
  {
    if (!kept[k])
    {
      continue;
    }
    flag(k);
    const double sq = levelSq(std::ldexp(reached, -k));
    --lowerLeft;
    if (!lower)
    {
      lower = std::make_unique<ExteriorRegions>(re.Tri(), sq, lowerLeft > 0);
    }
    else
    {
      lower->Descend(sq);
    }
    reachesPresent = EndAt(r, t, *lower, only, false, rows) || reachesPresent;
  }
  lower.reset();
  {
    flag(0);
    const double top = levelSq(reached);
    if (!regions || regions->Of() != re.Tri().Serial() || !(regions->Level() >= top))
    {
      regions.reset();
      regions = std::make_unique<ExteriorRegions>(re.Tri(), top);
      shared.Reached = reached;
    }
    reachesPresent = EndAt(r, t, *regions, only, true, rows, &shared.Ends) || reachesPresent;
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Arc& a, const Arc& b) { return a.Lower < b.Lower; });
  ReplaceRows(t.Arcs, cones, rows);
  if (reachesPresent)
  {
    // Its node is drawn with that maximum's cone, hence present by then. The
    // nodes this adds have values below the maximum's, present no later, so
    // no value present by any t grows: the levels stand (checked).
    t.Presence = PresenceTimes(fc.Nodes, t.Arcs, r.Carriers, r.Run);
    const std::vector<double> after = FirstAbove(fc, t.Presence, reached, Deepest);
    const double afterShared = share ? FirstAbove(fc, t.Presence, sharedReached, 0)[0] : -HUGE_VAL;
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
      if ((level[i] > 0 && !(t.Presence[nodes[i]] < after[level[i]])) ||
        (level[i] == Shared && !(t.Presence[nodes[i]] < afterShared)))
      {
        throw Degenerate("topology: a level below r* no longer holds");
      }
    }
  }
  t.Regions = regions->Count();
  t.CellsAbove = regions->CellsAbove();
}

} // namespace

TopologyInput TopologyOfCappedRun(CappedReconstruction& r, SharedRegions* shared)
{
  const FlowComplex& fc = r.Complex;
  if (r.Lines)
  {
    r.Lines->CompleteRawArcs(r.Cones); // what the run followed
  }
  // Memory: the raw arcs (the 1-2 ones kept, two per edge, the cones), the
  // regions (10 bytes a cell while built or kept for a lower level: the flags,
  // the union-find, the labels, the failed facets)
  // and the topology's arrays after them (HasseBarcode: ~48 bytes a node, its
  // sort holding two copies of the present ones).
  const double cells = r.Triangulation ? static_cast<double>(r.Triangulation->Tri().NumberOfCells()) : 0;
  const std::array<Id, 4> count = fc.CountByIndex(); // a pass over every node: once
  RequireMemory(static_cast<double>(sizeof(Arc)) *
        static_cast<double>(r.RawPatchArcs.size() + 2 * count[1] + r.Cones.size()) +
      10.0 * cells + 48.0 * static_cast<double>(fc.Nodes.size()),
    "the Betti numbers of a " + std::to_string(count[0]) + "-point cloud's reconstructions",
    "turn the topology off with given thresholds, or use fewer points");
  TopologyInput t;
  std::vector<Arc>& raw = t.Arcs;
  raw.swap(r.RawPatchArcs);
  // One allocation for all (growing by doubling copied ~10^7 arcs twice).
  ReserveHuge(raw, raw.size() + 2 * static_cast<std::size_t>(count[1]) + r.Cones.size() +
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
  SharedRegions own;
  try
  {
    EndInRegions(r, t, cones, shared ? *shared : own);
  }
  catch (const Degenerate&)
  {
    // Not shown: every line is followed (a tie there is the caller's Degenerate).
    t.Joined.clear();
    t.LinesToRegions = t.LinesToLowerLevels = t.LinesToSharedLevel = t.Regions = t.CellsAbove = 0;
    t.FollowedEveryLine = true;
    r.Lines->Follow(r.Lines->Nodes());
    ReplaceRows(raw, cones, r.Lines->FollowedRawArcs());
    t.Presence = PresenceTimes(fc.Nodes, raw, r.Carriers, r.Run);
  }
  t.LinesFollowed = r.Lines->LinesFollowed() - followed;
  return t;
}

} // namespace flowrecon
