// The compact complexes of a reconstruction's whole family t_r <= T_max, for a
// stage that shows one t_r after another (Flow Reconstruction in ParaView):
// the walks and flow lines are made once (PrepareCompact), each t_r only
// selects (SelectCompact), so a new t_r costs time linear in the
// triangulation rather than a walk of every patch.
#ifndef flowrecon_CompactFamily_h
#define flowrecon_CompactFamily_h

#include "CompactReconstruction.h"
#include "FlowComplex.h"
#include "Progress.h"
#include "Reconstruction.h"

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
  /// fit). Throws InputError, Aborted on request.
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
  /// NaN for the nodes outside. Its Betti are left zero: they are the
  /// reconstruction's, which a caller showing it computes anyway.
  CompactComplex At(double tr, std::vector<double>& nodeThreshold) const;

private:
  const FlowComplex& FC;
  const std::vector<Id>& Carriers;
  const ReconstructionResult& Run;
  double Tmax;
  CompactPieces Pieces;
  /// The cells the selection reads: the triangulation itself is freed once
  /// the pieces are prepared.
  CompactCells Cells;
};

} // namespace flowrecon

#endif
