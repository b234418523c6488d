// The points of the files vtkPointCloudReader hands to VTK's own readers:
// legacy .vtk (vtkGenericDataObjectReader) and the XML formats
// (vtkXMLGenericDataObjectReader), each run in a child process (IsolatedRead.h)
// with its messages captured.
#ifndef VtkFilePoints_h
#define VtkFilePoints_h

#include <string>
#include <vector>

class vtkPointData;

namespace flowrecon
{
namespace reader
{

/// Appends the points of the data set in `file`, or of every leaf of its
/// composite data set, to `xyz`; the point data arrays all leaves have go to
/// `pointData`. Throws ReadError on any problem.
void ReadLegacyVtk(const std::string& file, std::vector<double>& xyz, vtkPointData* pointData);
void ReadXmlVtk(const std::string& file, std::vector<double>& xyz, vtkPointData* pointData);

} // namespace reader
} // namespace flowrecon

#endif
