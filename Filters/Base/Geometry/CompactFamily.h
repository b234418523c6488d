// The compact complexes of a reconstruction's whole family t_r <= T_max, for a
// stage that shows one t_r after another (Flow Reconstruction in ParaView):
// the walks and flow lines are made once, and so is the threshold above which
// each piece enters (a node, a triangle, a solid cell, an edge or a sample
// held by another cell, a cell of a void to fill: VoidSweep). A new t_r then
// compares thresholds, in time linear in the pieces it keeps, and gives the
// complex SelectCompact gives for the same nodes.
#ifndef flowrecon_CompactFamily_h
#define flowrecon_CompactFamily_h

#include "CompactReconstruction.h"
#include "FlowComplex.h"
#include "Progress.h"
#include "Reconstruction.h"
#include "VoidSweep.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace flowrecon
{

class Retriangulation;

class CompactFamily
{
public:
  /// The family of the run `run` of `fc` (with `carriers`, CellCarriers) below
  /// `tmax`. `re` is the triangulation of fc's samples when the caller has it
  /// (else it is computed again; `advice` says what to do when it does not
  /// fit); it is freed once the pieces are made. Throws InputError, Aborted
  /// on request.
  CompactFamily(const FlowComplex& fc, const std::vector<Id>& carriers,
    const ReconstructionResult& run, double tmax, std::unique_ptr<Retriangulation> re,
    const Progress& progress, const std::string& advice);
  ~CompactFamily();
  CompactFamily(const CompactFamily&) = delete;
  CompactFamily& operator=(const CompactFamily&) = delete;

  /// The T_max the family was prepared for.
  double MaximumThreshold() const { return this->Tmax; }

  /// The compact complex of the reconstruction at `tr` <= MaximumThreshold();
  /// `nodeThreshold` (per node) receives the Threshold of each node's carrier,
  /// NaN for the nodes outside. Its Voids and Betti are left zero: the Betti
  /// numbers are the reconstruction's, which a caller showing it has anyway.
  CompactComplex At(double tr, std::vector<double>& nodeThreshold) const;
  /// The same into `out`, whose memory is reused: a caller that shows one t_r
  /// after another keeps it (new memory is faulted in page by page).
  void At(double tr, std::vector<double>& nodeThreshold, CompactComplex& out) const;

private:
  const FlowComplex& FC;
  double Tmax;
  CompactPieces Pieces; // without Neighbours: the void cells keep theirs
  /// Per node, the threshold above which it is in (HUGE_VAL: never below T_max).
  std::vector<double> NodeEntry;
  /// The nodes in at T_max, sorted.
  std::vector<Id> Candidates;
  /// The candidate edges and samples (by node id), with the threshold above
  /// which a triangle or solid cell holds the edge, or any written cell or
  /// selected edge uses the sample.
  struct Lone
  {
    Id Node;
    std::array<std::int32_t, 2> Simplex; ///< input ids (one for a sample)
    double Entry, HeldAbove;
  };
  std::vector<Lone> Edges, Samples;
  /// The claims of one triangle: Pieces.Claims[GroupStart[g], GroupStart[g+1]),
  /// written above GroupEntry[g].
  std::vector<std::size_t> GroupStart;
  std::vector<double> GroupEntry;
  /// Per group, the threshold above which a cell on either side of its
  /// triangle is solid (the triangle is then left out).
  std::vector<double> GroupCover;
  std::vector<std::int32_t> SolidCells; ///< the cells that flow to a candidate maximum
  std::vector<VoidCell> Voids;
  /// The input ids (sorted) of each of SolidCells and of each cell of Voids:
  /// the only cells a t_r writes.
  std::vector<std::array<std::int32_t, 4>> SolidVertices, VoidVertices;
  /// At's list of the written triangles' groups, kept like `out` (At is not
  /// to be called from two threads at once).
  mutable std::vector<std::size_t> Written;
  mutable std::vector<char> Drop;
};

} // namespace flowrecon

#endif
