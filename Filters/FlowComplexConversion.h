// Conversions between VTK data and the core's plain structures: samples in,
// the flow complex out as the named blocks of DESIGN.md §1. No geometry here.
#ifndef FlowComplexConversion_h
#define FlowComplexConversion_h

#include "FlowComplex.h" // core data structure

#include <string>
#include <vector>

class vtkDataObject;
class vtkMultiBlockDataSet;
class vtkFieldData;

namespace flowrecon
{

/// Sample coordinates of a vtkDataSet (its points) or a vtkTable (columns named
/// x/y/z or Points:0..2, else the first three numeric columns). Returns false and
/// sets `error` (one line) if there is nothing usable.
bool ExtractSamples(vtkDataObject* input, std::vector<Point3>& points, std::string& error);

/// Fills `output` with the blocks CriticalPoints, HasseDiagram, StableManifolds and
/// UnstableManifolds (the last two empty when not computed) and the report arrays.
void ToMultiBlock(const FlowComplex& fc, vtkMultiBlockDataSet* output);

/// The report arrays (NodeCountByIndex, EulerCharacteristic, ..., Timings).
void AddReport(const FlowComplex& fc, vtkFieldData* fd);

} // namespace flowrecon

#endif
