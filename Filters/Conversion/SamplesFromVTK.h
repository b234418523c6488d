// The samples of a VTK input (the points of a data set, or three columns of a
// table): what every stage that starts from a cloud reads first.
#ifndef SamplesFromVTK_h
#define SamplesFromVTK_h

#include "FlowComplex.h" // Point3

#include <string>
#include <vector>

class vtkDataObject;

namespace flowrecon
{

/// Sample coordinates of a vtkDataSet (its points) or a vtkTable (columns named
/// x/y/z or Points:0..2, else the first three numeric columns). Returns false and
/// sets `error` (one line) if there is nothing usable.
bool ExtractSamples(vtkDataObject* input, std::vector<Point3>& points, std::string& error);

} // namespace flowrecon

#endif
