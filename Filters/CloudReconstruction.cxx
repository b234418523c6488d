#include "CloudReconstruction.h"

#include "CappedReconstruction.h"
#include "CellHomology.h"
#include "HasseTopology.h"
#include "MemoryGuard.h"
#include "ReconstructionConversion.h"
#include "TopologyConversion.h"
#include "StableManifoldGeometry.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace flowrecon
{

CloudReconstructionReport ReconstructCloud(const std::vector<Point3>& samples,
  const CloudReconstructionSettings& settings, const CloudReconstructionOutputs& outputs,
  const Progress& progress, const std::function<void(const char*)>& phaseDone)
{
  const double tr = settings.ReconstructionThreshold;
  const double tdraw = settings.DrawThreshold;
  BuildOptions build;
  build.StableManifolds = false;
  build.UnstableManifolds = false;
  CappedReconstruction r;
  std::vector<Bar> bars;
  std::string topologyError;
  Id linesDeferred = 0, linesFollowed = 0;
  for (bool defer = true;; defer = false)
  {
    try
    {
      r = ReconstructBelow(
        samples, build, settings.PersistenceThreshold, settings.Cap, defer, progress.Range(0, 0.7),
        settings.Topology);
      phaseDone("flow complex, simplification, reconstruction queue");
      if (settings.Topology)
      {
        // Every reconstruction below the cap, from the diagram alone: it needs
        // the 2-3 arcs of every index-2 node (the complement's structure).
        const std::vector<Arc> raw = RawArcsForTopology(r);
        try
        {
          const auto P = PresenceTimes(r.Complex.Nodes, raw, r.Carriers, r.Run);
          bars = HasseBarcode(r.Complex.Nodes, raw, P);
        }
        catch (const InputError& e)
        {
          topologyError = e.what(); // the reconstruction is still written
        }
        phaseDone("Betti numbers");
      }
      const std::vector<Id> draw = NodesToDraw(r.Complex.Nodes, r.Carriers, r.Run, tdraw);
      CompleteCones(r, draw);
      // What only the queue needed goes before the drawing, the largest phase.
      linesDeferred = r.Lines ? r.Lines->LinesDeferred() : 0;
      linesFollowed = r.Lines ? r.Lines->LinesFollowed() : 0;
      r.Lines.reset();
      r.Simplification = SimplificationResult();
      // Their lists sat in tbbmalloc's pools, which the drawing's vectors
      // (glibc's heap) cannot reuse: hand them back first.
      ReleaseFreedMemory();
      DrawStableManifolds(samples, build, draw, r.Complex, progress.Range(0.7, 0.9),
        settings.Advice, &r.Cones, r.Triangulation.get());
      break;
    }
    catch (const Degenerate&)
    {
      if (!defer)
      {
        throw InputError("input too degenerate (a tie in a stable manifold)");
      }
    }
  }
  CloudReconstructionReport report;
  {
    const Timings& t = r.Complex.Time;
    std::ostringstream work;
    work << "patches deferred: " << r.DeferredPatches << " of " << r.Complex.CountByIndex()[2]
         << ", walked late: " << r.WalkedLate << ", owners found by replays: " << r.ReplayedOwners
         << "\nflow lines deferred: " << linesDeferred << " of "
         << 2 * r.Complex.CountByIndex()[2]
         << ", followed late: " << linesFollowed
         << (r.EagerBecause.empty() ? "" : "\nbuilt again without deferral: " + r.EagerBecause)
         << std::fixed << std::setprecision(3) << "\nflow complex (s): Delaunay " << t.Delaunay
         << "; critical points " << t.CriticalPoints << "; stable manifolds " << t.StableManifolds
         << "; unstable manifolds " << t.UnstableManifolds << "; assembly " << t.Assembly
         << "; then simplification " << r.SimplificationSeconds << "; reconstruction queue "
         << r.QueueSeconds << ";";
    report.Work = work.str();
  }
  r.Triangulation.reset();
  // The triangulation is the largest block until here (~0.7 KB per point, in
  // tbbmalloc's pools): the VTK arrays below need that memory back.
  ReleaseFreedMemory();
  FlowComplex& fc = r.Complex;
  phaseDone("drawing");
  const CellsByNode triangles = PositionsByRow(fc.TriangleNode, fc.Nodes.size());
  const CellsByNode tetrahedra = PositionsByRow(fc.TetrahedronNode, fc.Nodes.size());
  report.TopologyError = settings.Topology ? topologyError : "not asked for";
  progress(0.95, "output");
  // No sponsor arrows: nothing here reads them (millions at 10^6 points).
  ReconstructionToVTK(fc, r.Carriers, r.Run, settings.OutputThreshold, triangles, tetrahedra,
    outputs.Grid, outputs.Profile, nullptr, settings.Advice);
  if (report.TopologyError.empty())
  {
    TopologyToVTK(bars, settings.OutputThreshold, settings.Cap, outputs.Grid, outputs.Topology);
    const double window = std::max(1.0, std::min(settings.UnderSamplingWindow, settings.Cap / tr));
    UnderSamplingToVTK(TopologyChangesAbove(bars, tr, window), {}, fc, outputs.UnderSampling);
  }
  report.Nodes = std::move(fc.Nodes);
  phaseDone("VTK output");
  return report;
}

} // namespace flowrecon
