// The text formats of vtkPointCloudReader: .xyz/.txt/.pts, .csv, the vertices
// of .off and the `v` lines of .obj. Parsed here so that every bad line is
// reported with its number: VTK 9.2's readers read a malformed number as 0 and
// accept truncated files, vtkDelimitedTextReader's rows are not the file's
// lines, and CGAL 5.5's read_XYZ/read_OFF/read_OBJ read "3x" as 3 and
// "1.2.3 4" as (1.2, 0.3, 4), take a first line they cannot parse for a count,
// and accept truncated OFF files (TestLibraryReaderDefects checks that they
// still do, TestPointCloudReader that this does not). See
// PointCloudParsing.h for the shared pieces.
#ifndef PointCloudTextFormats_h
#define PointCloudTextFormats_h

#include <string>
#include <string_view>
#include <vector>

namespace flowrecon
{
namespace reader
{

/// One point per line, `x y z` separated by blanks or commas, further columns
/// ignored; a first line holding only the point count (.pts files, and CGAL's
/// XYZ format) is skipped.
void ReadXyz(const std::string& file, std::string_view text, std::vector<double>& xyz);

/// Delimited columns (`;`, tab, `,` or blanks) with an optional header naming x, y, z.
void ReadCsv(const std::string& file, std::string_view text, std::vector<double>& xyz);

/// The vertices of an (ST)(C)(N)OFF file; the face count is checked, not read.
void ReadOff(const std::string& file, std::string_view text, std::vector<double>& xyz);

/// The `v x y z` lines of an OBJ file.
void ReadObj(const std::string& file, std::string_view text, std::vector<double>& xyz);

} // namespace reader
} // namespace flowrecon

#endif
