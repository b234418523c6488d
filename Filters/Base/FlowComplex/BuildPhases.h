// The phases of one flow-complex build (internal to FlowComplexBuilder.cpp and
// the Build*.cpp files, one per phase): Run reads as the paper's list, Delaunay
// -> critical points -> stable manifolds of index 2 -> unstable manifolds ->
// Hasse diagram -> stable manifolds of index 3. The state the phases hand on is
// held here, so that each phase is a member function in its own file.
#ifndef flowrecon_BuildPhases_h
#define flowrecon_BuildPhases_h

#include "CriticalSimplices.h"
#include "FlowComplex.h"
#include "FlowComplexBuilder.h"
#include "InputPreparation.h"
#include "Progress.h"
#include "RecordedWalks.h"
#include "SuccessorForest.h"
#include "Triangulation.h"

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace flowrecon
{
struct Patch;

namespace internal
{

using Clock = std::chrono::steady_clock;
inline double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

/// Circumcentre (within the simplex's affine hull) and squared radius of a
/// simplex of 2..4 points; double constructions, relative to its first vertex.
std::array<double, 4> CentreAndSquaredRadius(const KPoint* p, std::size_t n);

/// The largest float at most x >= 0 (FLT_MAX above it): a lower bound stays one.
float RoundedDown(double x);

/// The one-line refusal of a cloud whose critical values underflow.
extern const char* const TooClose;
extern const char* const TooLarge;

/// Index-2 patches are walked in chunks of this many, in parallel.
constexpr std::size_t PatchChunk = 8192;

class Builder
{
public:
  Builder(const PreparedInput& in, const std::vector<Point3>& input, const BuildOptions& options,
    const Progress& progress, FlowComplex& fc)
    : In(in)
    , Input(input)
    , Options(options)
    , Report(progress)
    , FC(fc)
  {
  }

  /// One attempt on `coords` (the unique points, perhaps perturbed, scaled by
  /// 2^-ScaleExponent). Throws Degenerate if general position fails; `first`
  /// records the counts. Constructed values and points are scaled back.
  void Run(const std::vector<Point3>& coords, bool first);

  int ScaleExponent = 0;
  /// A perturbed attempt: critical values and points come from the input's
  /// coordinates (In.Unique), each of which the perturbation moved by at most
  /// Displacement (scaled units).
  bool Perturbed = false;
  double Displacement = 0;
  /// Critical points of a perturbed attempt left at the perturbed points (no
  /// limit on the input: ExactCriticalPointOf); counted by MakeNode.
  mutable std::atomic<Id> PerturbedValues{ 0 };
  /// When set, Run leaves its triangulation and critical simplices here.
  bool Keep = false;
  std::unique_ptr<const Triangulation> KeptTriangulation;
  CriticalSimplices KeptCritical;
  /// With Keep, and no polylines: the flow lines' forest and its maxima per
  /// cell, whose memoised chains later stages continue (Retriangulation::Flow).
  std::unique_ptr<const std::vector<std::int32_t>> KeptMaximumOfCell;
  std::unique_ptr<SuccessorForest> KeptForest;
  /// With Keep and options.RecordWalks: the triangles the patches' walks crossed.
  RecordedWalks KeptWalks;

private:
  // The phases, in the order Run calls them.
  void Triangulate();            ///< BuildCriticalPoints.cpp
  void FindCriticalPoints();     ///< BuildCriticalPoints.cpp: node ids, 0-1 arcs
  void DeferFarPatches();        ///< BuildCriticalPoints.cpp
  void WalkStablePatches();      ///< BuildStablePatches.cpp: index 2, 1-2 arcs
  void TraceUnstableManifolds(); ///< BuildUnstableManifolds.cpp: ends of 2-3 arcs
  void AssembleHasseDiagram();   ///< BuildHasseDiagram.cpp: nodes, 2-3 arcs
  void BuildStableCones();       ///< BuildStableCones.cpp: index 3

  // The steps of WalkStablePatches.
  struct PatchBatch;
  void WalkPatches(std::size_t begin, PatchBatch& batch) const; ///< one chunk, in parallel
  void MergePatches(PatchBatch& batch);            ///< its 1-2 arcs (and geometry), in order
  void RecordWalk(std::size_t i, PatchBatch& batch); ///< KeptWalks of patch i
  void ReserveArcsFor(const PatchBatch& batch);    ///< room for its arcs, or a refusal
  void AppendPatchGeometry(std::size_t i, const Patch& patch); ///< the triangles of patch i

  // The steps of TraceUnstableManifolds.
  struct FlowLineWalk;
  std::vector<std::int32_t> MaximumOfCells() const; ///< per Delaunay cell: its maximum, or -1
  void RecordFlowLines(FlowLineWalk& walk);         ///< with polylines, in facet order
  void TraceFlowLines(std::size_t i, FlowLineWalk& walk); ///< the two of index-2 point i

  void ScaleBack();
  void LowerPendingBounds();
  /// The node of a critical simplex (ids into coords): from coords, or in a
  /// perturbed attempt from the input's coordinates; `count` adds the fallbacks
  /// to PerturbedValues (once per node).
  Node MakeNode(int index, const Id* simplex, const std::vector<Point3>& coords, bool count = true) const;
  const std::vector<Point3>& Coords() const { return *this->CoordsOfAttempt; }
  std::string Cloud() const { return std::to_string(this->Coords().size()) + " points"; }

  const PreparedInput& In;
  const std::vector<Point3>& Input;
  const BuildOptions& Options;
  const Progress& Report;
  FlowComplex& FC;

  // What one phase hands to the next, for the current attempt.
  const std::vector<Point3>* CoordsOfAttempt = nullptr;
  bool First = false;
  std::unique_ptr<const Triangulation> Tri;
  CriticalSimplices Cs;
  Id M = 0, NEdges = 0, NFacets = 0;  ///< vertices, Gabriel edges, index-2 facets
  Id Base1 = 0, Base2 = 0, Base3 = 0; ///< first node id of each index
  std::vector<char> Deferred;         ///< per facet: patch not walked
  bool RecordingWalks = false;        ///< the walks record their triangles (KeptWalks)
  std::vector<Id> TriangleBegin;      ///< per facet: first triangle (geometry only)
  std::vector<std::array<std::int32_t, 2>> Ends; ///< per facet: the maxima reached
  std::vector<char> PatchFaces;       ///< per facet: which end its normals face
  /// The forest of the flow lines (without polylines) and the maxima it
  /// refers to: kept with the triangulation (Keep), else freed after the phase.
  std::unique_ptr<const std::vector<std::int32_t>> LineMaxima;
  std::unique_ptr<SuccessorForest> LineForest;
};

} // namespace internal
} // namespace flowrecon

#endif
