// The flow complex as the named blocks of docs/data-contract.md (CriticalPoints,
// HasseDiagram, StableManifolds, UnstableManifolds, GabrielEdges) and its report
// arrays. No geometry is computed here: only what the core built is copied.
#ifndef FlowComplexToVTK_h
#define FlowComplexToVTK_h

#include "FlowComplex.h"
#include "Progress.h"

class vtkFieldData;
class vtkMultiBlockDataSet;

namespace flowrecon
{

/// Fills `output` with the blocks CriticalPoints, HasseDiagram, StableManifolds and
/// UnstableManifolds (the last two empty when not computed) and the report arrays.
/// Reports progress per block and every 2^16 cells (the copy of millions of
/// cells takes seconds), and throws Aborted when asked to stop.
void ToMultiBlock(
  const FlowComplex& fc, vtkMultiBlockDataSet* output, const Progress& progress = Progress());

/// Refuses (InputError, one line) to convert a flow complex whose VTK copy
/// would not fit in memory: about 60 bytes per arc, 150 per node and 200 per
/// drawn cell, on top of the core's copy.
void RequireMemoryForVTK(const FlowComplex& fc);

/// The report arrays (NodeCountByIndex, EulerCharacteristic, ..., Timings).
void AddReport(const FlowComplex& fc, vtkFieldData* fd);

/// `output` as `input` with the HasseDiagram block made from fc.Arcs: every
/// other block (and the field data) is a shallow copy, so a stage that changes
/// only the arcs costs what the arcs cost, not what the drawn geometry costs.
void ReplaceHasseDiagram(
  vtkMultiBlockDataSet* input, const FlowComplex& fc, vtkMultiBlockDataSet* output);

/// Makes Index the active scalars of CriticalPoints (points), StableManifolds and
/// GabrielEdges (cells), likewise of their Surviving parts, and PersistencePairs have none: what a VTK mapper, or ParaView once a
/// block is extracted, colours by. (On the whole multiblock ParaView 5.11 picks
/// no default: it merges the blocks' active scalars, which are empty unless
/// every block agrees; without this PersistencePairs' Ratio was the only one.)
void SetDefaultScalars(vtkMultiBlockDataSet* output);

} // namespace flowrecon

#endif
