// The Delaunay triangulation of the points a flow complex was built from,
// computed again (the floor cost), with the critical simplices its nodes name,
// checked on it (StoredCriticalSimplices.h): what walking some of its patches later needs (the drawing of chosen
// nodes, deferred patches). Carrying them through a pipeline would cost more.
#ifndef flowrecon_Retriangulation_h
#define flowrecon_Retriangulation_h

#include "CriticalSimplices.h"
#include "FlowComplexBuilder.h"
#include "InputPreparation.h"
#include "RecordedWalks.h"
#include "SuccessorForest.h"
#include "Triangulation.h"

#include <memory>
#include <string>
#include <vector>

namespace flowrecon
{

class Retriangulation
{
public:
  /// `fc` must be the flow complex BuildFlowComplex computed from `points` with
  /// options.Seed (its Nodes and Report.Attempts are used). Throws InputError
  /// when a node is not a critical simplex of the points, or when the triangulation
  /// would not fit in memory (`advice` says what to do); Aborted on request.
  /// Reports progress from 0 to 0.35 of `progress` (the builder's shares).
  Retriangulation(const std::vector<Point3>& points, const BuildOptions& options,
    const FlowComplex& fc, const Progress& progress, const std::string& advice);
  /// The triangulation of a stored complex's samples (the first
  /// fc.NumberOfInputPoints of fc.Points) with its stored seed: what a later
  /// stage recomputes instead of carrying geometry (docs/design.md, "Cost follows the
  /// output"). Throws as the constructor above.
  static std::unique_ptr<Retriangulation> OfStoredComplex(
    const FlowComplex& fc, const Progress& progress, const std::string& advice);
  /// The builder's own triangulation of the final attempt (`coords`, `tri` and
  /// `cs`, with the walk tables), kept rather than computed again; with the
  /// forest its flow lines walked on it (`flow`, over `maximumOfCell`) when
  /// there is one (else Flow() makes it).
  Retriangulation(PreparedInput in, const BuildOptions& options,
    std::unique_ptr<const std::vector<Point3>> coords, std::unique_ptr<const Triangulation> tri,
    CriticalSimplices cs, std::unique_ptr<SuccessorForest> flow = nullptr,
    std::unique_ptr<const std::vector<std::int32_t>> maximumOfCell = nullptr,
    RecordedWalks walks = RecordedWalks());
  ~Retriangulation();
  /// The triangulation refers to Coords: not copied, not moved.
  Retriangulation(const Retriangulation&) = delete;
  Retriangulation& operator=(const Retriangulation&) = delete;

  const Triangulation& Tri() const { return *this->Tri_; }
  const CriticalSimplices& Critical() const { return this->Cs; }
  const PreparedInput& Prepared() const { return this->In; }
  const BuildOptions& Options() const { return this->Opts; }
  /// Node id of the first index-2 and index-3 node.
  Id Base2() const { return this->Base2_; }
  Id Base3() const { return this->Base3_; }
  /// Whether the node's simplex is the given triangulation vertices (input ids).
  bool SameSimplex(const FlowComplex& fc, Id node, const Id* vertices, int count) const;
  /// A constructed point in the input's units.
  Point3 BackScaled(Point3 p) const;

  /// The flow from each Voronoi vertex to its maximum (NEXT and ROOT memoised,
  /// no polylines; Root and RootBelow are thread-safe), one per triangulation:
  /// the build, each t_p's deferred lines and the compact output's cells
  /// follow lines on it, and a chain one of them walked is not walked again
  /// (on a 10^5-point bunny the second t_p followed every deferred line anew).
  /// Made on first use: call it first from one thread.
  SuccessorForest& Flow() const;
  /// Frees the flow (made again on next use): for a caller that knows no one
  /// holds it (the deferred flow lines refer to it), before a phase that
  /// needs the memory (10^6 torus points: 19 M cells, 9 bytes each).
  void ReleaseFlow() const;

  /// The triangles the build's walks crossed (BuildOptions::RecordWalks;
  /// empty otherwise), and their release.
  const RecordedWalks& Walks() const { return this->Walks_; }
  void ReleaseWalks() const;

  static const char* Mismatch();

private:
  PreparedInput In;
  BuildOptions Opts;
  std::unique_ptr<const std::vector<Point3>> Coords; ///< the triangulation refers to them
  std::unique_ptr<const Triangulation> Tri_;
  CriticalSimplices Cs;
  Id Base2_ = 0, Base3_ = 0;
  mutable std::unique_ptr<const std::vector<std::int32_t>> MaximumOfCell;
  mutable std::unique_ptr<SuccessorForest> Forest; ///< refers to Tri_ and MaximumOfCell
  mutable RecordedWalks Walks_;

  void SetBases();
};

} // namespace flowrecon

#endif
