#include "CloudReconstruction.h"

#include "CappedReconstruction.h"
#include "CellHomology.h"
#include "HasseTopology.h"
#include "TopologyInput.h"
#include "MemoryGuard.h"
#include "NodeIndices.h"
#include "ReconstructionConversion.h"
#include "TopologyConversion.h"
#include "StableManifoldGeometry.h"

#include "vtkInformationVector.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <optional>
#include <sstream>

namespace flowrecon
{

namespace
{

/// One t_p: the capped run and the bars of its reconstructions below the cap.
struct Candidate
{
  CappedReconstruction R;
  std::vector<Bar> Bars;
  std::string TopologyError;
  double Tp = 0;
  double TopologySeconds = 0; ///< following the lines, the raw arcs and the bars
  /// The levels' premise failed to be shown: every pending line was followed
  /// (right, but slow; said in the work report).
  bool FollowedEveryLine = false;
  Id LinesDeferred = 0, LinesFollowed = 0;
  Id LinesToRegions = 0; ///< ended by the topology at a region of {d > r*} (TopologyInput.h)
  Id LinesToLowerLevels = 0; ///< of those, at a level below r*
  Id Regions = 0;        ///< of {d > r*}
  std::int64_t CellsAbove = 0;
  /// A run before the last, kept packed for the compact output (empty R).
  std::optional<HeldRun> Held;
  /// The Threshold of the carrier of each maximum with cells, sorted: how
  /// many are in the reconstruction at any t_r once the run is gone (CheckFilled).
  std::vector<double> MaximumThresholds;
  Id MaximaBelow(double t) const
  {
    return static_cast<Id>(std::lower_bound(this->MaximumThresholds.begin(), this->MaximumThresholds.end(), t) -
      this->MaximumThresholds.begin());
  }
};

/// Keeps only the arcs the output reads after a run, those of index-1 nodes
/// (edge multiplicities): the others would add to the topology's peak.
void KeepEdgeArcs(FlowComplex& fc)
{
  const std::vector<std::int8_t> index = NodeIndices(fc.Nodes);
  const auto edge = [&index](const Arc& a) { return index[static_cast<std::size_t>(a.Lower)] == 1; };
  std::vector<Arc> kept;
  kept.reserve(static_cast<std::size_t>(std::count_if(fc.Arcs.begin(), fc.Arcs.end(), edge)));
  std::copy_if(fc.Arcs.begin(), fc.Arcs.end(), std::back_inserter(kept), edge);
  fc.Arcs.swap(kept);
}

/// The run at `tp` from `build` (taken when `take`, else its nodes are given
/// back); `regions`: shared by the runs of one build (TopologyOfCappedRun),
/// with the ends of the lines walked there.
/// Without `topology` the bars are not computed (a run made again: it has them).
Candidate Run(CappedBuild& build, double tp, bool take, const CloudReconstructionSettings& settings,
  SharedRegions& regions, const Progress& progress, bool topology = true)
{
  Candidate c;
  c.Tp = tp;
  c.R = ReconstructBuilt(build, tp, take, progress);
  c.LinesDeferred = c.R.Lines ? c.R.Lines->LinesDeferred() : 0;
  c.MaximumThresholds = MaximumThresholds(c.R.Complex.Nodes, c.R.Carriers, c.R.Run);
  // Nothing after the run reads the simplification (carriers and lines hold
  // what they need): it would only add to the topology's peak.
  c.R.Simplification = SimplificationResult();
  KeepEdgeArcs(c.R.Complex);
  // The queue's freed memory, handed back: the topology's allocations did not
  // reuse it (about 20 MB at 10^6 points).
  ReleaseFreedMemory();
  if (settings.Topology && topology)
  {
    const auto start = std::chrono::steady_clock::now();
    // Every reconstruction below the cap, from the diagram alone.
    const TopologyInput input = TopologyOfCappedRun(c.R, &regions);
    c.LinesToRegions = input.LinesToRegions;
    c.LinesToLowerLevels = input.LinesToLowerLevels;
    c.Regions = input.Regions;
    c.CellsAbove = input.CellsAbove;
    c.FollowedEveryLine = input.FollowedEveryLine;
    try
    {
      c.Bars = HasseBarcode(c.R.Complex.Nodes, input.Arcs, input.Presence, input.Joined);
    }
    catch (const InputError& e)
    {
      c.TopologyError = e.what(); // the reconstruction is still written
    }
    c.TopologySeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  c.LinesFollowed = c.R.Lines ? c.R.Lines->LinesFollowed() : 0;
  if (!take)
  {
    ReturnNodes(c.R, build);
  }
  return c;
}

/// t_r and t_p from the profiles (a given t_r: the candidate whose window
/// around it is the longest), and whether the answer is a surface filled in:
/// then, with t_r chosen, a window with a void is preferred (PreferSurface).
ThresholdChoice Choose(const std::vector<Candidate>& candidates,
  const CloudReconstructionSettings& settings, const std::vector<Point3>& samples,
  const std::vector<Node>& nodes)
{
  std::vector<std::vector<TopologyStep>> profiles;
  for (const Candidate& c : candidates)
  {
    profiles.push_back(c.TopologyError.empty() ? TopologyProfile(c.Bars, 1, settings.Cap)
                                               : std::vector<TopologyStep>());
  }
  ThresholdChoice choice = settings.AutomaticReconstruction
    ? ChooseThresholds(profiles, settings.Cap)
    : ChoosePersistence(profiles, settings.ReconstructionThreshold, settings.Cap);
  CheckFilled(choice, samples, candidates[choice.Candidate].MaximaBelow(choice.ReconstructionThreshold));
  if (settings.AutomaticReconstruction)
  {
    PreferSurface(choice, profiles, settings.Cap);
  }
  CheckFar(choice, nodes, static_cast<Id>(samples.size()));
  return choice;
}

std::string WorkReport(const CappedReconstruction& r, Id linesDeferred, Id linesFollowed,
  const Candidate& chosen)
{
  const Timings& t = r.Complex.Time;
  std::ostringstream work;
  work << "patches deferred: " << r.DeferredPatches << " of " << r.Complex.CountByIndex()[2]
       << ", walked late: " << r.WalkedLate << ", owners found by replays: " << r.ReplayedOwners
       << "\nflow lines deferred: " << linesDeferred << " of " << 2 * r.Complex.CountByIndex()[2]
       << ", followed late: " << linesFollowed
       << ", ended in regions of the complement for the topology: " << chosen.LinesToRegions
       << " (in " << chosen.Regions << " regions of " << chosen.CellsAbove << " Delaunay cells; "
       << chosen.LinesToLowerLevels << " of them at a lower level, their patch present)"
       << (r.EagerBecause.empty() ? "" : "\nbuilt again without deferral: " + r.EagerBecause)
       << std::fixed << std::setprecision(3) << "\nflow complex (s): Delaunay " << t.Delaunay
       << "; critical points " << t.CriticalPoints << "; stable manifolds " << t.StableManifolds
       << "; unstable manifolds " << t.UnstableManifolds << "; assembly " << t.Assembly
       << "; then simplification " << r.SimplificationSeconds << "; reconstruction queue "
       << r.QueueSeconds << ";";
  return work.str();
}

/// The seconds of the topology of each t_p (--timings).
std::string ListTopologyTimes(const std::vector<Candidate>& candidates)
{
  std::ostringstream each;
  for (const Candidate& c : candidates)
  {
    each << (each.tellp() > 0 ? ", " : "") << "t_p " << c.Tp << ": " << std::fixed
         << std::setprecision(3) << c.TopologySeconds << std::defaultfloat
         << (c.FollowedEveryLine ? " (every line followed)" : "");
  }
  return each.str();
}

/// ReconstructCloud's phases and what they hand on.
class CloudRun
{
public:
  CloudRun(const std::vector<Point3>& samples, const CloudReconstructionSettings& settings,
    const CloudReconstructionOutputs& outputs, const Progress& progress,
    const std::function<void(const char*)>& phaseDone)
    : Samples(samples)
    , Settings(settings)
    , Outputs(outputs)
    , Report(progress)
    , PhaseDone(phaseDone)
    , Automatic(settings.AutomaticPersistence || settings.AutomaticReconstruction)
    , Tps(settings.AutomaticPersistence ? settings.PersistenceCandidates
                                        : std::vector<double>{ settings.PersistenceThreshold })
    , Tr(settings.ReconstructionThreshold)
  {
    if (this->Automatic && !settings.Topology)
    {
      throw InputError("automatic thresholds need the topology");
    }
    if (this->Tps.empty())
    {
      throw InputError("automatic thresholds: no t_p candidate");
    }
    this->Options.StableManifolds = false;
    this->Options.UnstableManifolds = false;
    // The compact output's pieces are the triangles the build's walks cross.
    this->Options.RecordWalks = settings.Compact;
  }

  void BuildAndChoose(); ///< [0, 0.7]: the flow complex, a run per t_p, the choice
  void SetThresholds();  ///< t_r and t_p used; what is written and drawn
  void Draw();           ///< [0.7, 0.9]: the cells of the nodes below the drawn threshold
  void DrawCompact();    ///< [0.9, 0.95]: the compact complex at t_r (settings.Compact)
  std::vector<Id> Selected() const; ///< the chosen run's nodes with cells at t_r
  void WriteOutputs();   ///< [0.95, 1]: the grid, the profile, the topology and warnings

  CloudReconstructionReport Result;

private:
  void BuildAndRun(bool defer);
  std::vector<Candidate> RunEach(CappedBuild& build, SharedRegions& regions);
  /// The share of the progress of run k.
  Progress RunRange(std::size_t k) const
  {
    const double share = 0.3 / static_cast<double>(this->Tps.size());
    return this->Report.Range(
      0.4 + share * static_cast<double>(k), 0.4 + share * static_cast<double>(k + 1));
  }

  const std::vector<Point3>& Samples;
  const CloudReconstructionSettings& Settings;
  const CloudReconstructionOutputs& Outputs;
  const Progress& Report;
  const std::function<void(const char*)>& PhaseDone;
  const bool Automatic; ///< a threshold is chosen
  const std::vector<double> Tps;
  BuildOptions Options;
  Candidate Chosen;
  double Tr;                 ///< t_r, given or chosen
  std::string TopologyTimes; ///< for the work report
  double Output = 0;        ///< the grid holds the cells below it
  double Window = 0;        ///< under-sampling reported in [t_r, Window t_r)
  double DrawThreshold = 0; ///< the nodes below it are drawn
};

void CloudRun::BuildAndChoose()
{
  for (bool defer = true;; defer = false)
  {
    try
    {
      this->BuildAndRun(defer);
      return;
    }
    catch (const Degenerate&)
    {
      if (!defer)
      {
        throw InputError("input too degenerate (a tie in a stable manifold)");
      }
    }
  }
}

void CloudRun::BuildAndRun(bool defer)
{
  const CloudReconstructionSettings& settings = this->Settings;
  // One build serves every t_p: its lines are deferred from the largest.
  CappedBuild build = BuildBelow(this->Samples, this->Options,
    *std::max_element(this->Tps.begin(), this->Tps.end()), settings.Cap, defer,
    this->Report.Range(0, 0.4), settings.Topology);
  this->PhaseDone("flow complex");
  // The drawing makes the points again from the samples, and nothing here
  // reads the representatives: a copy of the cloud less until then.
  build.Complex.Points = std::vector<Point3>();
  build.Complex.Representative = std::vector<Id>();
  SharedRegions regions;
  std::vector<Candidate> candidates = this->RunEach(build, regions);
  this->TopologyTimes = ListTopologyTimes(candidates);
  std::size_t pick = 0;
  if (this->Automatic)
  {
    // The nodes are the build's, or the one run's that took them.
    this->Result.Choice = Choose(candidates, settings, this->Samples,
      this->Tps.size() == 1 ? candidates.front().R.Complex.Nodes : build.Complex.Nodes);
    this->Result.Automatic = true;
    pick = this->Result.Choice.Candidate;
    this->Tr = this->Result.Choice.ReconstructionThreshold;
  }
  const bool one = this->Tps.size() == 1;
  if (!one && pick + 1 == candidates.size())
  {
    MoveNodes(build.Complex, candidates[pick].R.Complex);
  }
  else if (!one && candidates[pick].Held)
  {
    // The build is spent: the held run takes its nodes.
    candidates.back().R = CappedReconstruction();
    candidates[pick].R = Restore(std::move(*candidates[pick].Held), build);
    candidates[pick].Held.reset();
  }
  else if (!one)
  {
    // The same run again (deterministic), without its topology: the first
    // one's bars are those it would compute (about 2 s of a 10^6-point
    // bunny's run).
    candidates.back().R = CappedReconstruction();
    Candidate first = std::move(candidates[pick]);
    candidates[pick] = Run(build, this->Tps[pick], true, settings, regions, this->RunRange(pick), false);
    Candidate& again = candidates[pick];
    again.Bars = std::move(first.Bars);
    again.TopologyError = first.TopologyError;
    again.TopologySeconds = first.TopologySeconds;
    again.LinesToRegions = first.LinesToRegions;
    again.LinesToLowerLevels = first.LinesToLowerLevels;
    again.Regions = first.Regions;
    again.CellsAbove = first.CellsAbove;
    again.FollowedEveryLine = first.FollowedEveryLine;
  }
  this->PhaseDone(this->Tps.size() > 1
      ? "simplification, reconstruction queue, Betti numbers (each t_p)"
      : "simplification, reconstruction queue, Betti numbers");
  this->Chosen = std::move(candidates[pick]);
  candidates.clear();
}

/// With several t_p, two runs (insertions, lines, arcs) held together were
/// most of the peak: a run before the last keeps its bars and, for the
/// compact output (which draws no stable manifold), its insertions and
/// carriers packed (HeldRun: 60 MB against 4 s of a 10^6-point bunny's run to
/// make it again); for the exact output it is run again if chosen. So the
/// build stays whole until the choice.
std::vector<Candidate> CloudRun::RunEach(CappedBuild& build, SharedRegions& regions)
{
  std::vector<Candidate> candidates;
  candidates.reserve(this->Tps.size());
  const bool one = this->Tps.size() == 1;
  for (std::size_t k = 0; k < this->Tps.size(); ++k)
  {
    const bool last = k + 1 == this->Tps.size();
    // With the compact output no run is made again after the last one: it
    // takes the build's arcs and lines instead of copying them, and gives
    // back only the nodes, which the choice and a held run read.
    const bool takeLast = last && !one && this->Settings.Compact;
    candidates.push_back(
      Run(build, this->Tps[k], one || takeLast, this->Settings, regions, this->RunRange(k)));
    if (takeLast)
    {
      ReturnNodes(candidates.back().R, build);
    }
    if (!last && this->Settings.Compact)
    {
      candidates.back().Held = Hold(std::move(candidates.back().R));
    }
    else if (!last)
    {
      candidates.back().R = CappedReconstruction();
    }
  }
  return candidates;
}

void CloudRun::SetThresholds()
{
  const CloudReconstructionSettings& settings = this->Settings;
  this->Result.PersistenceThreshold = this->Chosen.Tp;
  this->Result.ReconstructionThreshold = this->Tr;
  this->Output = settings.AutomaticReconstruction ? std::max(settings.OutputThreshold, this->Tr)
                                                  : settings.OutputThreshold;
  this->Window = std::max(1.0, std::min(settings.UnderSamplingWindow, settings.Cap / this->Tr));
  this->DrawThreshold = std::min(settings.Cap,
    settings.AutomaticReconstruction ? std::max(this->Output, this->Tr * this->Window)
                                     : settings.DrawThreshold);
}

void CloudRun::Draw()
{
  CappedReconstruction& r = this->Chosen.R;
  Id linesDeferred = 0, linesFollowed = 0;
  for (bool again = false;; again = true)
  {
    try
    {
      // The compact output stands in for the stable manifolds: none is drawn
      // (only the samples and Gabriel edges are, which the output leaves out).
      const std::vector<Id> draw = this->Settings.Compact
        ? std::vector<Id>()
        : NodesToDraw(r.Complex.Nodes, r.Carriers, r.Run, this->DrawThreshold);
      CompleteCones(r, draw);
      // What only the queue needed goes before the drawing, the largest phase.
      linesDeferred = r.Lines ? r.Lines->LinesDeferred() : this->Chosen.LinesDeferred;
      linesFollowed = r.Lines ? r.Lines->LinesFollowed() : this->Chosen.LinesFollowed;
      r.Lines.reset();
      r.Simplification = SimplificationResult();
      // Their lists sat in tbbmalloc's pools, which the drawing's vectors
      // (glibc's heap) cannot reuse: hand them back first.
      ReleaseFreedMemory();
      DrawStableManifolds(this->Samples, this->Options, draw, r.Complex, this->Report.Range(0.7, 0.9),
        this->Settings.Advice, &r.Cones, r.Triangulation.get());
      if (this->Settings.Compact)
      {
        this->PhaseDone("drawing");
        this->DrawCompact(); // on the triangulation, before it goes
      }
      break;
    }
    catch (const Degenerate&)
    {
      // A deferred patch drawn late met a tie: the chosen t_p, eagerly.
      if (again)
      {
        throw InputError("input too degenerate (a tie in a stable manifold)");
      }
      CappedBuild eager = BuildBelow(this->Samples, this->Options, this->Chosen.Tp, this->Settings.Cap,
        false, this->Report.Range(0, 0.4), this->Settings.Topology);
      SharedRegions regions;
      this->Chosen =
        Run(eager, this->Chosen.Tp, true, this->Settings, regions, this->Report.Range(0.4, 0.7));
    }
  }
  // The shallow-solid and side-by-side checks read cells on the samples: the
  // exact output has none, so the compact ones of the same reconstruction
  // stand in.
  ThresholdChoice& choice = this->Result.Choice;
  const bool rows = this->Automatic && choice.NeedsRows();
  const bool depth = this->Automatic && choice.NeedsDepth();
  // The compact output is at hand: CheckJoins gates itself on its cells.
  const bool joins = this->Automatic && (this->Settings.Compact || choice.NeedsJoins());
  CompactComplex probe;
  bool measurable = depth || rows || joins;
  if (measurable && !this->Settings.Compact)
  {
    try
    {
      probe = CompactReconstruction(*r.Triangulation, r.Complex.Nodes, this->Selected());
    }
    catch (const std::exception&)
    {
      // A walk met a tie, or memory ran short: only a warning needed these
      // cells, so the exact output goes on, unmeasured (Depth -1).
      measurable = false;
    }
  }
  this->Result.Work = WorkReport(r, linesDeferred, linesFollowed, this->Chosen) +
    (this->TopologyTimes.empty() ? "" : "\nBetti numbers from the Hasse diagram (s): " + this->TopologyTimes);
  r.Triangulation.reset();
  // The triangulation is the largest block until here (~0.7 KB per point, in
  // tbbmalloc's pools): the VTK arrays below need that memory back.
  ReleaseFreedMemory();
  const CompactComplex& cells = this->Settings.Compact ? this->Result.Compact : probe;
  if (measurable && depth)
  {
    // After the triangulation is gone: on a large solid the samples' stars
    // are ~100 MB (10^6 cube points).
    CheckShallow(choice, cells.Tetrahedra);
  }
  if (measurable && rows)
  {
    CheckRows(choice, r.Complex.Nodes, static_cast<Id>(this->Samples.size()), cells);
  }
  if (measurable && joins)
  {
    const auto start = std::chrono::steady_clock::now();
    if (CheckJoins(choice, this->Samples, cells))
    {
      std::ostringstream took;
      took << std::fixed << std::setprecision(3)
           << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      this->Result.Work += "\nparts held by long edges, checked (s): " + took.str();
    }
  }
  if (!this->Settings.Compact)
  {
    this->PhaseDone("drawing");
  }
}

std::vector<Id> CloudRun::Selected() const
{
  const CappedReconstruction& r = this->Chosen.R;
  std::vector<Id> selected;
  for (std::size_t i = 0; i < r.Complex.Nodes.size(); ++i)
  {
    const Id carrier = r.Carriers[i];
    if (carrier >= 0 && r.Run.Contains(carrier, this->Tr))
    {
      selected.push_back(static_cast<Id>(i));
    }
  }
  return selected;
}

void CloudRun::DrawCompact()
{
  const CappedReconstruction& r = this->Chosen.R;
  const std::vector<Id> selected = this->Selected();
  this->Result.NodeThreshold.assign(r.Complex.Nodes.size(), std::nan(""));
  for (const Id i : selected)
  {
    this->Result.NodeThreshold[i] = r.Run.Nodes[r.Carriers[i]].Threshold;
  }
  // The walks are the flow's last use (Draw dropped the deferred lines): its
  // memory goes before the search for voids, the compact output's peak.
  this->Result.Compact = CompactReconstruction(
    *r.Triangulation, r.Complex.Nodes, selected, this->Report.Range(0.9, 0.95), true);
  this->PhaseDone("compact output");
}

void CloudRun::WriteOutputs()
{
  const CloudReconstructionSettings& settings = this->Settings;
  CappedReconstruction& r = this->Chosen.R;
  FlowComplex& fc = r.Complex;
  CloudReconstructionReport& report = this->Result;
  report.TopologyError = settings.Topology ? this->Chosen.TopologyError : "not asked for";
  this->Report(0.95, "output");
  if (settings.Compact)
  {
    // The compact cells replace the exact ones in every caller, which keeps
    // only this grid's field data: its samples, Gabriel edges and their ten
    // arrays (1 s and some 100 bytes a sample at 10^6 points) went unread.
    if (this->Outputs.Grid)
    {
      this->Outputs.Grid->Initialize();
    }
  }
  else
  {
    const CellsByNode triangles = PositionsByRow(fc.TriangleNode, fc.Nodes.size());
    const CellsByNode tetrahedra = PositionsByRow(fc.TetrahedronNode, fc.Nodes.size());
    // The grid reads the groups, not what they came from, nor the drawing's
    // node points and cone boundaries.
    fc.TriangleNode = std::vector<Id>();
    fc.TetrahedronNode = std::vector<Id>();
    fc.NodePoint = std::vector<Id>();
    r.Cones = std::vector<Arc>();
    // No sponsor arrows: nothing here reads them (millions at 10^6 points).
    ReconstructionToVTK(fc, r.Carriers, r.Run, this->Output, triangles, tetrahedra, this->Outputs.Grid,
      nullptr, nullptr, settings.Advice);
  }
  // The geometry is in the grid now: the profile and the rest read nodes and
  // steps only, and need its memory.
  fc.Points = std::vector<Point3>();
  fc.Triangles = std::vector<std::array<Id, 3>>();
  fc.Tetrahedra = std::vector<std::array<Id, 4>>();
  fc.Arcs = std::vector<Arc>();
  r.Carriers = std::vector<Id>();
  ReconstructionToVTK(fc, r.Carriers, r.Run, this->Output, {}, {}, nullptr, this->Outputs.Profile,
    nullptr, settings.Advice);
  if (report.TopologyError.empty())
  {
    TopologyToVTK(this->Chosen.Bars, this->Output, settings.Cap, this->Outputs.Grid, this->Outputs.Topology);
    // A short stable window: its end is where the topology changes next.
    double warn = this->Window;
    if (report.Automatic && report.Choice.Short() && report.Choice.Window.To > this->Tr)
    {
      warn = std::max(warn, report.Choice.Window.To / this->Tr * (1 + 1e-9));
    }
    UnderSamplingToVTK(TopologyChangesAbove(this->Chosen.Bars, this->Tr, warn), {}, fc,
      this->Outputs.UnderSampling);
  }
  ThresholdsToVTK(report.PersistenceThreshold, this->Tr, settings.AutomaticPersistence,
    settings.AutomaticReconstruction, report.Automatic ? &report.Choice.Window : nullptr,
    this->Outputs.Grid);
  report.Nodes = std::move(fc.Nodes);
  this->PhaseDone("VTK output");
}

} // namespace

CloudReconstructionReport ReconstructCloud(const std::vector<Point3>& samples,
  const CloudReconstructionSettings& settings, const CloudReconstructionOutputs& outputs,
  const Progress& progress, const std::function<void(const char*)>& phaseDone)
{
  CloudRun run(samples, settings, outputs, progress, phaseDone);
  run.BuildAndChoose();
  run.SetThresholds();
  run.Draw();
  run.WriteOutputs();
  return std::move(run.Result);
}

CloudReconstructionOutputs ReconstructionPorts(vtkInformationVector* outputVector)
{
  return { vtkUnstructuredGrid::GetData(outputVector, 0), vtkTable::GetData(outputVector, 1),
    vtkTable::GetData(outputVector, 3), vtkPolyData::GetData(outputVector, 4) };
}

} // namespace flowrecon
