// The points of an ASPRS LAS file (versions 1.0-1.4, point formats 0-10), the
// format of airborne and terrestrial laser scans, for vtkPointCloudReader.
// Parsed here: neither VTK 9.2 as Debian builds it nor CGAL 5.5 reads LAS
// without libLAS or LASlib, which Debian 12 does not package; a record's
// coordinates are its first 12 bytes in every point format, so only the header
// needs the specification. Compressed LAZ files are refused with one line.
#ifndef LasPoints_h
#define LasPoints_h

#include <string>
#include <string_view>
#include <vector>

namespace flowrecon
{
namespace reader
{

/// Appends the points' coordinates, each the record's integer times the
/// header's scale plus its offset, to `xyz`.
void ReadLas(const std::string& file, std::string_view bytes, std::vector<double>& xyz);

} // namespace reader
} // namespace flowrecon

#endif
