// What Flow Complex Simplification adds to a flow complex (cancelled nodes, owners,
// the PersistencePairs block, what a replay needs) and reading it back.
#ifndef SimplificationConversion_h
#define SimplificationConversion_h

#include "FlowComplex.h"
#include "Simplification.h" // core data structure

#include <string>

class vtkMultiBlockDataSet;

namespace flowrecon
{

/// What vtkFlowComplexSimplification adds to a flow complex: the point array
/// `Cancelled` of CriticalPoints, the field arrays `OwnerOffsets`, `Owners`
/// (SimplificationResult's compressed rows) and `PersistenceThreshold` of
/// CriticalPoints and of the output, the cell array `Owner` of StableManifolds
/// (the node itself for survivors, the first owner of a cancelled node, -1 for
/// none) and the block `PersistencePairs`.
void AddSimplification(const FlowComplex& fc, const SimplificationResult& s, double threshold,
  vtkMultiBlockDataSet* output);

/// Reads back what AddSimplification stored. Returns false (with `error` empty)
/// when `input` is not simplified: then every node survives and owns nothing.
/// Returns false with `error` set when the stored arrays are inconsistent. The
/// pairs and what a replay on deferred patches needs (HasLowers) are read when
/// the simplification stored them.
bool SimplificationFromMultiBlock(vtkMultiBlockDataSet* input, Id nodeCount,
  SimplificationResult& s, std::string& error);

} // namespace flowrecon

#endif
