// The vertices of an STL file (binary or ASCII) for vtkPointCloudReader, each
// once. Parsed here: VTK 9.2's vtkSTLReader reads ASCII coordinates as floats,
// "1.2.3" as (1.2, 0.3) and accepts a binary file holding fewer triangles than
// it announces; CGAL 5.5's read_STL also reads "1.2.3" as (1.2, 0.3), and a NaN
// in a binary file loses another vertex in its map (TestLibraryReaderDefects
// checks that they still do, TestPointCloudReader that this does not).
#ifndef StlPoints_h
#define StlPoints_h

#include <string>
#include <string_view>
#include <vector>

namespace flowrecon
{
namespace reader
{

/// Appends the distinct vertices of the triangles to `xyz`, in the order of
/// their first appearance (an STL file repeats each vertex in every triangle
/// around it). Binary when the size is 84 + 50 bytes per announced triangle
/// (binary files may start with "solid" too), ASCII when the file starts with
/// "solid"; anything else fails with one line.
void ReadStl(const std::string& file, std::string_view text, std::vector<double>& xyz);

} // namespace reader
} // namespace flowrecon

#endif
