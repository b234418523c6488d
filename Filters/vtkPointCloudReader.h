/**
 * @class   vtkPointCloudReader
 * @brief   Read the points of a point cloud from a text, mesh or VTK file.
 *
 * The format is chosen by the file extension (case-insensitive):
 * - `.xyz`, `.txt`, `.pts`, `.pwn` (CGAL's points with normals): one point per
 *   line, `x y z` separated by blanks or commas; further columns are ignored.
 *   Blank lines and lines starting with `#` or `//` are skipped. The first line
 *   may hold only the point count (as `.pts` files and CGAL's XYZ format allow;
 *   a count other than the number of points that follow is an error),
 *   which is skipped.
 * - `.csv`: comma (or semicolon, or tab) separated, with an optional header row.
 *   Columns named `x`, `y`, `z` (or `Points:0..2`, `coordinates:0..2`, any
 *   case) are used when the header names all three; otherwise the first three
 *   numeric columns of the first data row.
 * - `.off`: the vertices of an (ST)(C)(N)OFF file; faces are ignored.
 * - `.obj`: the `v x y z` lines; everything else is ignored.
 * - `.stl` (binary or ASCII): the distinct vertices of the triangles, in the
 *   order of their first appearance.
 * - `.las` (ASPRS LAS 1.0-1.4, point formats 0-10): each record's integer
 *   coordinates times the header's scale plus its offset. Compressed `.laz`
 *   files are refused with one line.
 * - `.ply` (ASCII or binary): the vertex element; its scalar properties other
 *   than x, y, z become point data arrays (nx/ny/nz as `Normals`,
 *   red/green/blue[/alpha] as `RGB`/`RGBA`).
 * - `.vtk` (legacy VTK) and the VTK XML formats `.vtp .vtu .vts .vtr .vti .vtm
 *   .vthb .pvtp .pvtu .pvts .pvtr .pvti`: the points of the data set, or of
 *   every leaf of a composite data set, appended in order. Point data arrays are
 *   passed through (for a composite, the arrays all leaves have). The counts,
 *   block headers and last cell offsets in these files (and in the files a
 *   `.vtm` or `.pvt*` names) are checked against the file size, times the best
 *   ratio of its compressor, before VTK's readers see them, since those readers
 *   abort or hang on some corrupt files; an allocation VTK's reader still cannot
 *   make fails the read (`FILE: out of memory`) instead of aborting.
 *
 * The output is a vtkPolyData with double-precision points and one VTK_VERTEX
 * cell per point. Text, OFF, OBJ and PLY files are parsed here (independently of
 * the locale, with the line of any error); vtkPLYReader and vtkOBJReader are not
 * used because they abort on truncated files or read malformed numbers as 0.
 *
 * Bad input (missing file, unknown extension, a line that does not parse, fewer
 * than three coordinates, NaN or infinite coordinates, no points, truncated
 * files, files another VTK reader rejects) makes RequestData fail with one line,
 * `FILE:LINE: message` or `FILE: message`, available from GetErrorMessage() and
 * raised with vtkErrorMacro. The messages of the VTK readers used internally
 * are kept out of VTK's output window (the first one becomes part of the line);
 * VTK's logger still copies them to stderr unless the application turns that
 * off with vtkLogger::SetStderrVerbosity, as the flowrecon tool does.
 */
#ifndef vtkPointCloudReader_h
#define vtkPointCloudReader_h

#include "FlowReconFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for ErrorMessage

class FLOWRECONFILTERS_EXPORT vtkPointCloudReader : public vtkPolyDataAlgorithm
{
public:
  static vtkPointCloudReader* New();
  vtkTypeMacro(vtkPointCloudReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to read.
   */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /**
   * The one-line description of why the last read failed (`FILE:LINE: message`
   * or `FILE: message`); an empty string after a successful read.
   */
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

  /**
   * Whether the extension of `fileName` is one this reader handles (the file
   * itself is not opened).
   */
  static bool CanReadFile(VTK_FILEPATH const char* fileName);

protected:
  vtkPointCloudReader();
  ~vtkPointCloudReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  std::string ErrorMessage;

private:
  vtkPointCloudReader(const vtkPointCloudReader&) = delete;
  void operator=(const vtkPointCloudReader&) = delete;
};

#endif
