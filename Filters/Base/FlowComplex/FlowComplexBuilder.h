// Computes the flow complex of a point cloud: the entry point of the core.
#ifndef flowrecon_FlowComplexBuilder_h
#define flowrecon_FlowComplexBuilder_h

#include "FlowComplex.h"
#include "Progress.h"

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace flowrecon
{

struct BuildOptions
{
  bool StableManifolds = true;   ///< triangulated index-2 patches and index-3 cones
  /// With StableManifolds: at most this many triangles and tetrahedra, or -1 for
  /// all. Nodes are drawn in filtration order while their cells fit (see
  /// NodesWithinBudget), after the Hasse diagram, from a second triangulation.
  std::int64_t MaximumGeometryCells = -1;
  bool UnstableManifolds = true; ///< polylines of index-2 unstable manifolds
  std::uint64_t Seed = 1;        ///< seed of the perturbation of degenerate input
  int MaxAttempts = 6;           ///< perturbations tried before giving up
  bool ExactOnly = false;        ///< skip the interval filter (for testing the exact path)
  /// Without StableManifolds: the patches of index-2 nodes whose value is at
  /// least this many times the largest Gabriel-edge value are not walked (no
  /// 1-2 arcs; listed in FlowComplex::DeferredPatches). Every ratio V(b)/V(a)
  /// of their 1-2 arcs is then >= it: no cancellation below it and no upflow
  /// below it uses them (DeferredPatches.h walks them when they are needed).
  double DeferPatchesAboveRatio = HUGE_VAL;
  /// Without StableManifolds and UnstableManifolds: a flow line of an index-2
  /// node x is stopped at the first Voronoi vertex certainly this many times
  /// farther from the samples than x (listed in FlowComplex::PendingFlowLines,
  /// no 2-3 arc): every ratio of its arc is above it. DeferredFlowLines.h
  /// follows them when a stage needs them.
  double DeferFlowLinesAboveRatio = HUGE_VAL;
  /// With a kept triangulation: the triangles each patch's walk crosses are
  /// recorded there (Retriangulation::Walks), 4 bytes each, for a compact
  /// output that would otherwise walk the patches again.
  bool RecordWalks = false;
};

/// The flow complex of `points`. Throws InputError for unusable input (non-finite
/// coordinates, fewer than 4 distinct points, coplanar points) and Aborted when
/// `progress` asks to stop. Degenerate input is perturbed (see Report).
FlowComplex BuildFlowComplex(
  const std::vector<Point3>& points, const BuildOptions& options, const Progress& progress);

class Retriangulation;

/// The same; with `keep`, the triangulation is handed over there instead of
/// being freed (for walks after the build: drawing, deferred patches), which
/// spares computing it again at the cost of holding it meanwhile.
FlowComplex BuildFlowComplex(const std::vector<Point3>& points, const BuildOptions& options,
  const Progress& progress, std::unique_ptr<Retriangulation>* keep);

} // namespace flowrecon

#endif
