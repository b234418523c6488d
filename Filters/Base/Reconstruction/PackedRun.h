// A reconstruction run and its cell carriers held in fewer bytes: only the
// inserted nodes' steps (about 17 bytes each) and a 32-bit carrier a node,
// against 40 bytes a node as computed. For a t_p candidate kept while another
// one runs (Filters/CloudReconstruction.cxx): making it again cost more time
// than holding it whole cost memory, and this costs neither.
#ifndef flowrecon_PackedRun_h
#define flowrecon_PackedRun_h

#include "Reconstruction.h"

#include <cstdint>
#include <vector>

namespace flowrecon
{

struct PackedRun
{
  Id NodeCount = 0;
  Id InitializationCount = 0;
  /// One entry per step, in step order.
  std::vector<std::int32_t> Order;
  std::vector<double> Priority;
  std::vector<std::int32_t> Sponsor;
  std::vector<std::uint8_t> Kind;
  /// Empty when every step's Threshold is the running maximum of the
  /// priorities from 1 (what Reconstruct computes); else one per step.
  std::vector<double> Threshold;
  std::vector<std::int32_t> Carriers; ///< one per node, -1: none
};

/// Packs `run` and its `carriers` (CellCarriers). Throws InputError when they
/// do not match (sizes, a step's node out of range or not inserted at that
/// step, a carrier that names no node, ids beyond 32 bits).
PackedRun Pack(const ReconstructionResult& run, const std::vector<Id>& carriers);

/// The run and carriers Pack was given, field for field.
void Unpack(const PackedRun& packed, ReconstructionResult& run, std::vector<Id>& carriers);

} // namespace flowrecon

#endif
