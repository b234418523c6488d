// The vertex element of a PLY file (ASCII or binary) for vtkPointCloudReader.
// Parsed here: VTK 9.2's vtkPLYReader aborts the process on a truncated file
// and reads garbage numbers as 0, and CGAL 5.5's read_PLY crashes on integer
// coordinates, hangs on a large element without properties, allocates a
// list's announced length, skips unknown property types (misreading the rest)
// and reads a missing z as 0 (TestLibraryReaderDefects checks that they still
// do, TestPointCloudReader that this does not); this reports the element and line.
#ifndef PlyPoints_h
#define PlyPoints_h

#include <string>
#include <string_view>
#include <vector>

class vtkPointData;

namespace flowrecon
{
namespace reader
{

/// Appends the vertices' x, y, z to `xyz`; the other scalar vertex properties
/// become arrays of `pointData` (nx/ny/nz as Normals, red/green/blue[/alpha] as
/// RGB/RGBA, as vtkPLYReader names them).
void ReadPly(
  const std::string& file, std::string_view text, std::vector<double>& xyz, vtkPointData* pointData);

} // namespace reader
} // namespace flowrecon

#endif
