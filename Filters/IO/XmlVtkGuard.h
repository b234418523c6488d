// Checks of a VTK XML file (.vtp .vtu .vts .vtr .vti .vtm .vthb .pvt*) before
// VTK 9.2's vtkXMLGenericDataObjectReader sees it. That reader aborts the
// process when an allocation fails, loops on absurd component counts,
// dereferences null arrays on unknown types and reads blocks that are not
// there; every such case found (most by fuzzing) is refused here with a
// one-line error. The files a .vtm or .pvt* names are checked too.
#ifndef XmlVtkGuard_h
#define XmlVtkGuard_h

#include <string>

namespace flowrecon
{
namespace reader
{

/// Throws ReadError when VTK's XML readers could not read `file` safely: its
/// counts, extents and block headers must fit the file size times the best
/// ratio of its compressor, its types must be known, its last cell offsets
/// must fit too.
void CheckXmlFile(const std::string& file);

} // namespace reader
} // namespace flowrecon

#endif
