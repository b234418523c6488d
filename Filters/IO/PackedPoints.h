// The points and point data a reader found, as bytes: how they come back from
// the child process that read them (IsolatedRead.h). Arrays keep their type,
// name, component names, values and attribute roles (not their information keys).
#ifndef PackedPoints_h
#define PackedPoints_h

#include <string>
#include <vector>

class vtkPointData;

namespace flowrecon
{
namespace reader
{

std::string PackPoints(const std::vector<double>& xyz, vtkPointData* pointData);

/// The packed points into `xyz` and their arrays into `pointData`; throws
/// ReadError naming `file` if the bytes do not hold them.
void UnpackPoints(const std::string& file, const std::string& bytes, std::vector<double>& xyz,
  vtkPointData* pointData);

} // namespace reader
} // namespace flowrecon

#endif
