// Checks of a VTK XML file (see XmlVtkGuard.h) on the elements VTK's own
// vtkXMLDataParser parses from it, in document order and with the line of
// each: counts, types and extents, the bytes the arrays declare, the block
// headers of binary arrays, then the last cell offsets (read with that
// parser), which size the connectivity.
#include "XmlVtkGuard.h"

#include "PointCloudParsing.h"
#include "VtkMessageCapture.h"
#include "XmlBlockHeaders.h"

#include "vtkAbstractArray.h"
#include "vtkDataCompressor.h"
#include "vtkLZ4DataCompressor.h"
#include "vtkLZMADataCompressor.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"
#include "vtkZLibDataCompressor.h"
#include "vtksys/FStream.hxx"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <system_error>
#include <vector>

namespace flowrecon
{
namespace reader
{
namespace
{

// The largest of `count` values of a data array from value `start`; false if
// VTK cannot read them (its reader reports that later).
bool ReadLargest(vtkXMLDataParser* parser, vtkXMLDataElement* array, vtkTypeUInt64 start,
  std::size_t count, double& largest)
{
  int type = 0;
  vtkTypeInt64 offset = 0;
  const char* format = array->GetAttribute("format");
  if (!format || !array->GetWordTypeAttribute("type", type))
  {
    return false;
  }
  std::vector<unsigned char> buffer(count * vtkAbstractArray::GetDataTypeSize(type));
  const std::size_t read = std::strcmp(format, "appended") == 0
    ? (array->GetScalarAttribute("offset", offset)
          ? parser->ReadAppendedData(offset, buffer.data(), start, count, type)
          : 0)
    : parser->ReadInlineData(
        array, std::strcmp(format, "ascii") == 0, buffer.data(), start, count, type);
  largest = 0;
  switch (type)
  {
    vtkTemplateMacro(for (std::size_t i = 0; i < read; ++i) {
      largest = std::max(largest, static_cast<double>(reinterpret_cast<VTK_TT*>(buffer.data())[i]));
    });
    default:
      return false;
  }
  return read == count;
}

// What the checks of a parsed file need from its root and size.
struct ParsedXml
{
  std::string File;
  std::string_view Text; // the file up to a little after <AppendedData
  long long Size = 0;
  vtkTypeInt64 Appended = 0; // where the appended data starts, 0 if none
  bool Base64Appended = true;
  bool Compressed = false;
  std::size_t WordSize = 4;
  bool BigEndian = false;
  long long Ratio = 1;
  long long Limit = 0; // the most bytes of values the file can expand to
};

// `n` bytes of the file from `at` (fewer at its end).
std::string ReadAt(const ParsedXml& xml, long long at, std::size_t n)
{
  if (at >= 0 && static_cast<std::size_t>(at) + n <= xml.Text.size())
  {
    return std::string(xml.Text.substr(static_cast<std::size_t>(at), n));
  }
  std::ifstream in(xml.File, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(at));
  std::string bytes(n, '\0');
  in.read(&bytes[0], static_cast<std::streamsize>(n));
  bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return bytes;
}

// Where the inline data of an element starts, as
// vtkXMLDataParser::SeekInlineDataPosition finds it: after the first '>' from
// its start tag, past white space; -1 if the file ends first.
long long InlineDataStart(const ParsedXml& xml, vtkXMLDataElement* element)
{
  constexpr std::size_t chunk = 1 << 16;
  bool tagClosed = false;
  for (long long at = element->GetXMLByteIndex(); at >= 0 && at < xml.Size;
       at += static_cast<long long>(chunk))
  {
    const std::string bytes = ReadAt(xml, at, chunk);
    std::size_t i = 0;
    if (!tagClosed)
    {
      i = bytes.find('>');
      if (i == std::string::npos)
      {
        continue;
      }
      tagClosed = true;
      ++i;
    }
    i = bytes.find_first_not_of(" \t\r\n", i);
    if (i != std::string::npos)
    {
      return at + static_cast<long long>(i);
    }
  }
  return -1;
}

// The problem with the block header of a binary or appended data array
// (CheckBlockHeader), or "".
std::string CheckParsedHeader(
  const ParsedXml& xml, vtkXMLDataElement* array, unsigned long long needed)
{
  const char* format = array->GetAttribute("format");
  const bool appended = format && std::strcmp(format, "appended") == 0;
  long long at = -1;
  vtkTypeInt64 offset = 0;
  if (appended)
  {
    at = xml.Appended > 0 && array->GetScalarAttribute("offset", offset) && offset >= 0 &&
        offset < xml.Size - xml.Appended
      ? xml.Appended + offset
      : -1;
  }
  else if (format && std::strcmp(format, "binary") == 0)
  {
    at = InlineDataStart(xml, array);
  }
  else
  {
    return std::string(); // ASCII: no header
  }
  if (at < 0)
  {
    const char* offsetText = array->GetAttribute("offset");
    return appended ? "no data at offset " + Quote(offsetText ? offsetText : "")
                    : "no data where its header should be";
  }
  const auto read = [&](std::size_t n) {
    std::string bytes = ReadAt(xml, at, n);
    return appended ? bytes : bytes.substr(0, bytes.find('<'));
  };
  // Inline data lies in the text read (all of the file before any appended
  // data) and ends at the next tag.
  const std::size_t inlineEnd = appended
    ? 0
    : std::min(xml.Text.find('<', static_cast<std::size_t>(at)), xml.Text.size());
  const long long available = appended
    ? xml.Size - at
    : std::max(0LL, static_cast<long long>(inlineEnd) - at);
  return CheckBlockHeader(read, available, !appended || xml.Base64Appended, xml.Compressed,
    xml.WordSize, xml.BigEndian, xml.Ratio, needed);
}

// vtkXMLDataParser stops at the first tag whose name starts with
// "AppendedData": the data that follows is binary, no element.
bool IsAppendedData(const std::string& name)
{
  return name.compare(0, 12, "AppendedData") == 0;
}

// The line of an element's start tag.
std::size_t LineOf(const ParsedXml& xml, vtkXMLDataElement* element)
{
  const vtkTypeInt64 at = std::max<vtkTypeInt64>(element->GetXMLByteIndex(), 0);
  const std::size_t end = std::min(static_cast<std::size_t>(at), xml.Text.size());
  return 1 + static_cast<std::size_t>(std::count(xml.Text.begin(), xml.Text.begin() + end, '\n'));
}

void CheckFile(const std::string& file, int depth);

// The checks of the elements of one file, in document order: the counts,
// types and extents of their attributes against the file size, the bytes the
// data arrays declare, the block headers of binary arrays, and files named
// by a .vtm or .pvt* (`depth` deep).
class ElementChecks
{
public:
  ElementChecks(const ParsedXml& xml, int depth)
    : Xml(xml)
    , Depth(depth)
  {
  }

  void Check(vtkXMLDataElement* element)
  {
    const std::string name = element->GetName() ? element->GetName() : "";
    const std::size_t line = LineOf(this->Xml, element);
    static const char* const sections[] = { "PointData", "CellData", "Points", "Verts", "Lines",
      "Strips", "Polys", "Cells", "Coordinates", "FieldData" };
    if (std::find(std::begin(sections), std::end(sections), name) != std::end(sections))
    {
      this->Section = name;
    }
    if (name == "Piece")
    {
      this->TuplesOf.clear();
    }
    long long components = 1, tuples = -1;
    std::string format, type, arrayName;
    for (int i = 0; i < element->GetNumberOfAttributes(); ++i)
    {
      const std::string attribute = element->GetAttributeName(i);
      const std::string value = element->GetAttributeValue(i);
      format = attribute == "format" ? value : format;
      type = attribute == "type" ? value : type;
      arrayName = attribute == "Name" ? value : arrayName;
      this->CheckAttribute(name, line, attribute, value, components, tuples);
    }
    if (name == "VTKFile" && !type.empty())
    {
      this->CheckPrimary(element, type, line);
    }
    const bool isArray = name == "DataArray" || name == "Array";
    if (!isArray)
    {
      return;
    }
    const std::string what = "data array " + Quote(arrayName);
    if (type.empty())
    {
      // No type at all: vtkXMLReader dereferences a null array (field data).
      Fail(this->Xml.File, line, what + " has no type (corrupt or truncated file?)");
    }
    // The connectivity of cells is sized by offsets (CheckCellOffsets).
    const auto sized = this->TuplesOf.find(this->Section);
    if (arrayName != "connectivity" && arrayName != "faces" &&
      (tuples >= 0 || sized != this->TuplesOf.end()))
    {
      this->Declared += static_cast<double>(components) * (tuples >= 0 ? tuples : sized->second) *
        BitsPerValue(type, format) / 8;
      if (this->Declared > static_cast<double>(this->Xml.Limit))
      {
        Fail(this->Xml.File, line,
          what + " makes the data larger than the file can hold (corrupt or truncated file?)");
      }
    }
    const std::string problem = CheckParsedHeader(this->Xml, element, 0);
    if (!problem.empty())
    {
      Fail(this->Xml.File, line, what + ": " + problem + " (corrupt or truncated file?)");
    }
  }

private:
  void CheckAttribute(const std::string& name, std::size_t line, const std::string& attribute,
    const std::string& value, long long& components, long long& tuples)
  {
    long long count = 0;
    const auto implausible = [&]() {
      Fail(this->Xml.File, line,
        "implausible " + attribute + "=" + Quote(value) + " (corrupt or truncated file?)");
    };
    if (attribute.compare(0, 8, "NumberOf") == 0 && attribute != "NumberOfPieces")
    {
      if (!ParseCount(value, count) || count > this->Xml.Limit ||
        (attribute == "NumberOfComponents" && count > 10000))
      {
        implausible();
      }
      if (attribute == "NumberOfComponents")
      {
        components = count;
      }
      else if (attribute == "NumberOfTuples")
      {
        tuples = count;
      }
      else if (name == "Piece")
      {
        // NumberOfPoints, NumberOfCells, NumberOfVerts...
        const std::string kind = attribute.substr(8);
        this->TuplesOf[kind] = count;
        this->TuplesOf[kind == "Points" ? "PointData" : "CellData"] += count;
      }
    }
    else if (attribute == "type" && name == "VTKFile")
    {
      // The types of the extensions we read. Others reach readers that do not
      // exist in VTK 9.2 (vtkNonOverlappingAMR: the data object leaks) or hold
      // no points.
      static const char* const types[] = { "PolyData", "UnstructuredGrid", "StructuredGrid",
        "RectilinearGrid", "ImageData", "PPolyData", "PUnstructuredGrid", "PStructuredGrid",
        "PRectilinearGrid", "PImageData", "vtkMultiBlockDataSet", "vtkOverlappingAMR",
        "vtkHierarchicalBoxDataSet" };
      if (std::find(std::begin(types), std::end(types), value) == std::end(types))
      {
        Fail(this->Xml.File, line,
          "unsupported VTK XML file type " + Quote(value) +
            " (expected a dataset with points or a multiblock of them)");
      }
    }
    else if ((attribute == "type" && (name == "DataArray" || name == "Array")) ||
      attribute == "header_type")
    {
      // An unknown type makes vtkXMLReader dereference a null array.
      static const char* const types[] = { "Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32",
        "Int64", "UInt64", "Float32", "Float64", "String", "Bit" };
      if (std::find(std::begin(types), std::end(types), value) == std::end(types) ||
        (attribute == "header_type" && value != "UInt32" && value != "UInt64"))
      {
        implausible();
      }
    }
    else if (attribute == "index" || attribute == "level" || attribute == "group")
    {
      // Composite readers make room for that many children.
      if (!ParseCount(value, count) || count > static_cast<long long>(this->Xml.Text.size()))
      {
        implausible();
      }
    }
    else if (attribute == "Extent" || attribute == "WholeExtent")
    {
      this->CheckExtent(name, value, implausible);
    }
    else if ((attribute == "file" || attribute == "Source") && this->Depth < 8)
    {
      // A block or piece in another file.
      const auto sub = std::filesystem::path(this->Xml.File).parent_path() / value;
      std::error_code error;
      if (std::filesystem::is_regular_file(sub, error))
      {
        CheckFile(sub.string(), this->Depth + 1);
      }
    }
  }

  template <class Implausible>
  void CheckExtent(const std::string& name, const std::string& value, const Implausible& implausible)
  {
    constexpr long long maximumPoints = 1LL << 30;
    std::vector<std::string_view> bounds;
    SplitLoose(value, bounds, 6);
    long long product = 1, cells = 1;
    for (std::size_t k = 0; k + 1 < bounds.size(); k += 2)
    {
      long long lo = 0, hi = 0;
      const bool ok =
        std::from_chars(bounds[k].data(), bounds[k].data() + bounds[k].size(), lo).ec ==
          std::errc() &&
        std::from_chars(bounds[k + 1].data(), bounds[k + 1].data() + bounds[k + 1].size(), hi)
            .ec == std::errc();
      if (!ok || hi < lo || hi - lo >= maximumPoints || (product *= hi - lo + 1) > maximumPoints)
      {
        implausible();
      }
      cells *= std::max(hi - lo, 1LL);
    }
    if (name == "Piece")
    {
      this->TuplesOf["PointData"] = product;
      this->TuplesOf["CellData"] = cells;
    }
  }

  // The element VTKFile's type names must come first inside it: without it
  // VTK 9.2's composite readers dereference a null primary element.
  void CheckPrimary(vtkXMLDataElement* root, const std::string& primary, std::size_t line)
  {
    vtkXMLDataElement* first = root->GetNumberOfNestedElements() > 0 ? root->GetNestedElement(0) : nullptr;
    const std::string name = first && first->GetName() ? first->GetName() : "";
    if (!first || IsAppendedData(name))
    {
      Fail(this->Xml.File, line,
        "VTKFile of type " + Quote(primary) + " holds no <" + primary +
          "> element (corrupt or truncated file?)");
    }
    if (name != primary)
    {
      Fail(this->Xml.File, LineOf(this->Xml, first),
        "expected the element <" + primary + "> inside VTKFile, found " + Quote(name) +
          " (corrupt or truncated file?)");
    }
  }

  const ParsedXml& Xml;
  const int Depth;
  // Tuples of the arrays of each section of the current piece ("Points",
  // "CellData", "Verts"...), and the bytes all arrays declare.
  std::map<std::string, long long, std::less<>> TuplesOf;
  std::string Section;
  double Declared = 0;
};

// VTK sizes the connectivity of a cell block by the last of its offsets (the
// faces of polyhedra by the largest face offset), data the header checks do
// not see: read them with VTK's own parser, which knows every encoding and
// compressor, once their block headers were checked, including that they
// hold the values read. Only DataArray elements are cell arrays to VTK.
void CheckCellOffsets(const ParsedXml& xml, vtkXMLDataParser* parser, vtkXMLDataElement* data)
{
  for (int p = 0, piece = 0; p < data->GetNumberOfNestedElements(); ++p)
  {
    vtkXMLDataElement* ePiece = data->GetNestedElement(p);
    if (std::strcmp(ePiece->GetName(), "Piece") != 0)
    {
      continue;
    }
    for (int b = 0; b < ePiece->GetNumberOfNestedElements(); ++b)
    {
      vtkXMLDataElement* block = ePiece->GetNestedElement(b);
      long long cells = 0; // NumberOfVerts, ..., NumberOfCells
      if (!ePiece->GetScalarAttribute(
            (std::string("NumberOf") + block->GetName()).c_str(), cells) ||
        cells <= 0)
      {
        continue;
      }
      const std::string where =
        "piece " + std::to_string(piece) + ", " + block->GetName() + ": array ";
      for (int a = 0; a < block->GetNumberOfNestedElements(); ++a)
      {
        vtkXMLDataElement* array = block->GetNestedElement(a);
        const char* arrayName = array->GetAttribute("Name");
        int type = 0;
        if (std::strcmp(array->GetName(), "DataArray") != 0 || !arrayName ||
          (std::strcmp(arrayName, "offsets") != 0 && std::strcmp(arrayName, "faceoffsets") != 0) ||
          !array->GetWordTypeAttribute("type", type))
        {
          continue;
        }
        const bool faces = std::strcmp(arrayName, "faceoffsets") == 0;
        // Both reads below end at value `cells` - 1.
        const std::string problem = CheckParsedHeader(xml, array,
          static_cast<unsigned long long>(cells) *
            static_cast<unsigned long long>(vtkAbstractArray::GetDataTypeSize(type)));
        if (!problem.empty())
        {
          Fail(xml.File, 0,
            where + Quote(arrayName) + ": " + problem + " (corrupt or truncated file?)");
        }
        double largest = 0;
        // Offsets increase (VTK refuses them otherwise): the last is the largest.
        if (ReadLargest(parser, array, faces ? 0 : cells - 1, faces ? cells : 1, largest) &&
          largest > static_cast<double>(xml.Limit))
        {
          char count[32];
          std::snprintf(count, sizeof(count), "%.15g", largest);
          Fail(xml.File, 0,
            where + Quote(arrayName) + " announces " + count +
              " connectivity values, more than the file can hold (corrupt or truncated file?)");
        }
      }
    }
    ++piece;
  }
}

// The compressor named by the root element, null if none or unknown.
vtkSmartPointer<vtkDataCompressor> Decompressor(const std::string& name)
{
  if (name == "vtkLZ4DataCompressor")
  {
    return vtkSmartPointer<vtkLZ4DataCompressor>::New();
  }
  if (name == "vtkZLibDataCompressor")
  {
    return vtkSmartPointer<vtkZLibDataCompressor>::New();
  }
  if (name == "vtkLZMADataCompressor")
  {
    return vtkSmartPointer<vtkLZMADataCompressor>::New();
  }
  return nullptr;
}

// Parses `file` as VTK's XML readers do (with vtkXMLDataParser), then checks
// every element in document order and the last cell offsets. A file that does
// not parse is refused here, with the parser's message: VTK's reader would fail
// on the same parse, but only after making the data object its own scan of the
// type names (vtkNonOverlappingAMR then leaks).
void CheckFile(const std::string& file, int depth)
{
  const std::string text = ReadWholeFile(file, "<AppendedData");
  vtksys::ifstream stream(file.c_str(), std::ios::in | std::ios::binary);
  vtkNew<vtkXMLDataParser> parser;
  parser->SetStream(&stream);
  parser->SetIgnoreCharacterData(1); // inline data is read from the file when asked for
  // Its messages are the reader's to report.
  CapturedMessages capture;
  vtkXMLDataElement* root = parser->Parse() ? parser->GetRootElement() : nullptr;
  if (!root)
  {
    const std::string why = OneLine(capture.First());
    Fail(file, 0, "cannot read VTK XML file" + (why.empty() ? std::string() : " (" + why + ")"));
  }
  ParsedXml xml;
  xml.File = file;
  xml.Text = text;
  xml.Size = static_cast<long long>(std::filesystem::file_size(file));
  xml.Appended = parser->GetAppendedDataPosition();
  vtkXMLDataElement* eAppended = root->FindNestedElementWithName("AppendedData");
  const char* encoding = eAppended ? eAppended->GetAttribute("encoding") : nullptr;
  xml.Base64Appended = !encoding || std::strcmp(encoding, "raw") != 0;
  const char* compressor = root->GetAttribute("compressor");
  xml.Ratio = RatioOf(compressor ? compressor : "");
  xml.Compressed = xml.Ratio > 1;
  xml.Limit = xml.Size * xml.Ratio;
  const char* headerType = root->GetAttribute("header_type");
  xml.WordSize = headerType && std::strcmp(headerType, "UInt64") == 0 ? 8 : 4;
  const char* byteOrder = root->GetAttribute("byte_order");
  xml.BigEndian = byteOrder && std::strcmp(byteOrder, "BigEndian") == 0;

  ElementChecks checks(xml, depth);
  std::vector<vtkXMLDataElement*> stack{ root }; // no recursion: nesting may be deep
  while (!stack.empty())
  {
    vtkXMLDataElement* element = stack.back();
    stack.pop_back();
    if (element->GetName() && IsAppendedData(element->GetName()))
    {
      continue;
    }
    checks.Check(element);
    for (int i = element->GetNumberOfNestedElements() - 1; i >= 0; --i)
    {
      stack.push_back(element->GetNestedElement(i));
    }
  }

  const char* type = root->GetAttribute("type");
  vtkXMLDataElement* data = type ? root->FindNestedElementWithName(type) : nullptr;
  vtkSmartPointer<vtkDataCompressor> decompressor = Decompressor(compressor ? compressor : "");
  if (data && (!xml.Compressed || decompressor))
  {
    parser->SetCompressor(decompressor);
    CheckCellOffsets(xml, parser, data);
  }
}

} // namespace

void CheckXmlFile(const std::string& file)
{
  CheckFile(file, 0);
}

} // namespace reader
} // namespace flowrecon
