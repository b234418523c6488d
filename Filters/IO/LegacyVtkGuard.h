// Checks of a legacy VTK file (.vtk) before VTK 9.2's vtkGenericDataObjectReader
// sees it. That reader trusts the counts in the file (a huge one makes it fail
// an allocation and abort, a negative one crashes it), hangs on long runs of
// blanks and dereferences null arrays after some malformed FIELD blocks; every
// such case found (most by fuzzing) is refused here with a one-line error.
#ifndef LegacyVtkGuard_h
#define LegacyVtkGuard_h

#include <string>
#include <string_view>

namespace flowrecon
{
namespace reader
{

/// Throws ReadError when VTK's legacy reader could not read `text` (the whole
/// file `file`) safely: a bad first line, an implausible count, a malformed
/// FIELD block before the point or cell data, a corrupt pre-5.0 cell list.
void CheckLegacyFile(const std::string& file, std::string_view text);

} // namespace reader
} // namespace flowrecon

#endif
