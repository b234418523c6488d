// vtkPointCloudReader: the class, the choice of a format by extension and the
// output (double points, one vertex each). Each format's parser is in a file
// of its own (PointCloudTextFormats, PlyPoints, and VtkFilePoints, which runs
// VTK's readers in a child process: IsolatedRead), all in namespace
// flowrecon::reader.
#include "vtkPointCloudReader.h"

#include "PipelinePorts.h"
#include "PlyPoints.h"
#include "PointCloudParsing.h"
#include "LasPoints.h"
#include "PointCloudTextFormats.h"
#include "StlPoints.h"
#include "VtkFilePoints.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtksys/SystemTools.hxx"

#include <filesystem>
#include <new>
#include <numeric>
#include <string>
#include <system_error>
#include <vector>

vtkStandardNewMacro(vtkPointCloudReader);

namespace flowrecon
{
namespace reader
{
namespace
{

// Lowercased extension with its dot ("" if none; a name that starts with its
// only dot, ".xyz", has none), e.g. ".xyz".
std::string Extension(const std::string& path)
{
  const std::string name = vtksys::SystemTools::GetFilenameName(path);
  const std::string extension = vtksys::SystemTools::GetFilenameLastExtension(name);
  return extension.size() == name.size() ? std::string() : Lower(extension);
}

enum class Format
{
  Unknown,
  Xyz,
  Csv,
  Off,
  Obj,
  Ply,
  Stl,
  Las,
  Laz,
  LegacyVtk,
  XmlVtk
};

Format FormatOf(const std::string& extension)
{
  static const std::pair<const char*, Format> formats[] = { { ".xyz", Format::Xyz },
    { ".txt", Format::Xyz }, { ".pwn", Format::Xyz }, { ".pts", Format::Xyz },
    { ".csv", Format::Csv }, { ".off", Format::Off }, { ".ply", Format::Ply },
    { ".obj", Format::Obj }, { ".stl", Format::Stl }, { ".las", Format::Las },
    { ".laz", Format::Laz },
    { ".vtk", Format::LegacyVtk }, { ".vtp", Format::XmlVtk }, { ".vtu", Format::XmlVtk },
    { ".vts", Format::XmlVtk }, { ".vtr", Format::XmlVtk }, { ".vti", Format::XmlVtk },
    { ".vtm", Format::XmlVtk }, { ".vthb", Format::XmlVtk }, { ".pvtp", Format::XmlVtk },
    { ".pvtu", Format::XmlVtk }, { ".pvts", Format::XmlVtk }, { ".pvtr", Format::XmlVtk },
    { ".pvti", Format::XmlVtk } };
  for (const auto& f : formats)
  {
    if (extension == f.first)
    {
      return f.second;
    }
  }
  return Format::Unknown;
}

const char* const SupportedExtensions =
  ".xyz .txt .pwn .pts .csv .off .ply .obj .stl .las .vtk .vtp .vtu .vts .vtr .vti .vtm .vthb .pvtp .pvtu "
  ".pvts .pvtr .pvti";

void ReadCloud(const std::string& file, std::vector<double>& xyz, vtkPointData* pointData)
{
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status))
  {
    Fail(file, 0, "no such file");
  }
  if (std::filesystem::is_directory(status))
  {
    Fail(file, 0, "is a directory, not a file");
  }
  if (!std::filesystem::is_regular_file(status))
  {
    // Devices and pipes may never end.
    Fail(file, 0, "not a regular file");
  }
  const std::string extension = Extension(file);
  const Format format = FormatOf(extension);
  if (format == Format::Unknown)
  {
    Fail(file, 0,
      (extension.empty() ? std::string("no file extension")
                         : "unknown file extension " + Quote(extension)) +
        " (expected one of " + SupportedExtensions + ")");
  }
  if (std::filesystem::file_size(file, error) == 0 && !error)
  {
    Fail(file, 0, "file is empty");
  }
  switch (format)
  {
    case Format::Xyz:
      ReadXyz(file, ReadWholeFile(file), xyz);
      break;
    case Format::Csv:
      ReadCsv(file, ReadWholeFile(file), xyz);
      break;
    case Format::Off:
      ReadOff(file, ReadWholeFile(file), xyz);
      break;
    case Format::Obj:
      ReadObj(file, ReadWholeFile(file), xyz);
      break;
    case Format::Ply:
      ReadPly(file, ReadWholeFile(file), xyz, pointData);
      break;
    case Format::Stl:
      ReadStl(file, ReadWholeFile(file), xyz);
      break;
    case Format::Las:
      ReadLas(file, ReadWholeFile(file), xyz);
      break;
    case Format::Laz:
      Fail(file, 0,
        "compressed LAS (LAZ) is not supported: decompress it to .las first (laszip, "
        "pdal translate)");
    case Format::LegacyVtk:
      ReadLegacyVtk(file, xyz, pointData);
      break;
    default:
      ReadXmlVtk(file, xyz, pointData);
      break;
  }
  if (xyz.empty())
  {
    Fail(file, 0, "no points found");
  }
}

} // namespace
} // namespace reader
} // namespace flowrecon

//------------------------------------------------------------------------------
vtkPointCloudReader::vtkPointCloudReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkPointCloudReader::~vtkPointCloudReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkPointCloudReader::CanReadFile(const char* fileName)
{
  using namespace flowrecon::reader;
  const Format format = fileName ? FormatOf(Extension(fileName)) : Format::Unknown;
  return format != Format::Unknown && format != Format::Laz;
}

//------------------------------------------------------------------------------
int vtkPointCloudReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->ErrorMessage.clear();
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  // The whole cloud goes to piece 0; other pieces (parallel runs) stay empty.
  if (flowrecon::IsLaterPiece(outputVector))
  {
    return 1;
  }
  const std::string file = this->FileName ? this->FileName : "";
  std::vector<double> xyz;
  vtkNew<vtkPointData> pointData;
  try
  {
    if (file.empty())
    {
      throw flowrecon::reader::ReadError("no file name given");
    }
    flowrecon::reader::ReadCloud(file, xyz, pointData);
  }
  catch (const flowrecon::reader::ReadError& e)
  {
    this->ErrorMessage = e.what();
  }
  catch (const std::bad_alloc&)
  {
    this->ErrorMessage = file + ": out of memory";
  }
  catch (const std::exception& e)
  {
    // e.g. std::filesystem errors on unusual paths.
    this->ErrorMessage = file + ": " + e.what();
  }
  if (!this->ErrorMessage.empty())
  {
    vtkErrorMacro(<< this->ErrorMessage);
    return 0;
  }

  const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(n);
  std::copy(xyz.begin(), xyz.end(), coordinates->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);

  // One VTK_VERTEX per point.
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(n + 1);
  connectivity->SetNumberOfValues(n);
  std::iota(offsets->GetPointer(0), offsets->GetPointer(0) + n + 1, vtkIdType(0));
  std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + n, vtkIdType(0));
  vtkNew<vtkCellArray> vertices;
  vertices->SetData(offsets, connectivity);

  output->SetPoints(points);
  output->SetVerts(vertices);
  if (pointData->GetNumberOfArrays() > 0)
  {
    output->GetPointData()->ShallowCopy(pointData);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
