// The files the commands write, and their failures as one line naming the path
// (a full disk as such). A run interrupted while writing leaves no file.
#ifndef flowrecon_cli_OutputFiles_h
#define flowrecon_cli_OutputFiles_h

#include "Persistence.h" // core: PersistencePair

#include <string>
#include <vector>

class vtkDataObject;
class vtkTable;
class vtkXMLWriter;

namespace flowrecon::cli
{

/// The extension of `path` in lower case (".vtm"), "" for none.
std::string ExtensionOf(const std::string& path);

/// Refuses an output `path` whose directory does not exist (a Failure), before
/// the long computation.
void RequireDirectory(const std::string& path);

/// Writes `data` with `writer` as VTK XML (appended raw binary, LZ4).
void WriteXML(vtkXMLWriter* writer, vtkDataObject* data, const std::string& path);

/// Writes the `columns` of `table` as CSV under the line `header`: integer
/// arrays as integers, the others with 17 significant digits.
void WriteCsv(vtkTable* table, const std::vector<const char*>& columns, const std::string& header,
  const std::string& path);

/// The persistence diagram as CSV: "dimension,birth,death", 'inf' for the
/// death of an essential class.
void WriteDiagramCsv(const std::vector<PersistencePair>& pairs, const std::string& path);

} // namespace flowrecon::cli

#endif
