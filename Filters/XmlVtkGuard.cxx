// Checks of a VTK XML file (see XmlVtkGuard.h): a scan of the text before any
// appended data for counts, types and extents (with line numbers), then a
// parse with VTK's own vtkXMLDataParser for the block headers of every array
// and the last cell offsets, which size the connectivity.
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

// What the parser needs to find the block header of an array, from the
// attributes it parsed (quotes, entities or a '>' in an attribute value can
// hide an array from the text scan of CheckXmlCounts).
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
    return "no data where its header should be";
  }
  const auto read = [&](std::size_t n) {
    std::string bytes = ReadAt(xml, at, n);
    return appended ? bytes : bytes.substr(0, bytes.find('<'));
  };
  return CheckBlockHeader(read, xml.Size - at, !appended || xml.Base64Appended, xml.Compressed,
    xml.WordSize, xml.BigEndian, xml.Ratio, needed);
}

// Every data array of the parsed file (DataArray, or Array in field data).
void CheckParsedArrays(const ParsedXml& xml, vtkXMLDataElement* root)
{
  std::vector<vtkXMLDataElement*> stack{ root }; // no recursion: nesting may be deep
  while (!stack.empty())
  {
    vtkXMLDataElement* element = stack.back();
    stack.pop_back();
    for (int i = 0; i < element->GetNumberOfNestedElements(); ++i)
    {
      stack.push_back(element->GetNestedElement(i));
    }
    const std::string name = element->GetName() ? element->GetName() : "";
    const std::string problem =
      name == "DataArray" || name == "Array" ? CheckParsedHeader(xml, element, 0) : "";
    if (!problem.empty())
    {
      const char* arrayName = element->GetAttribute("Name");
      Fail(xml.File, 0,
        "data array " + Quote(arrayName ? arrayName : "") + ": " + problem +
          " (corrupt or truncated file?)");
    }
  }
}

// VTK sizes the connectivity of a cell block by the last of its offsets (the
// faces of polyhedra by the largest face offset), data the header checks do
// not see: read them with VTK's own parser, which knows every encoding and
// compressor, once their block headers were checked, including that they
// hold the values read. Only DataArray elements are cell arrays to VTK.
void CheckCellOffsets(
  const ParsedXml& xml, vtkXMLDataParser* parser, vtkXMLDataElement* data, long long limit)
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
          largest > static_cast<double>(limit))
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

// Parses the file as VTK's XML readers do, then checks the block headers of
// all its arrays and the cell offsets (`text`: the file up to a little after
// <AppendedData, as CheckXmlCounts read it).
void CheckParsedXml(const std::string& file, std::string_view text, long long limit)
{
  vtksys::ifstream stream(file.c_str(), std::ios::in | std::ios::binary);
  vtkNew<vtkXMLDataParser> parser;
  parser->SetStream(&stream);
  parser->SetIgnoreCharacterData(1); // inline data is read from the file when asked for
  // Its messages are the reader's to report.
  CapturedMessages capture;
  const auto check = [&]() {
    vtkXMLDataElement* root = parser->Parse() ? parser->GetRootElement() : nullptr;
    const char* type = root ? root->GetAttribute("type") : nullptr;
    vtkXMLDataElement* data = type ? root->FindNestedElementWithName(type) : nullptr;
    const char* compressor = root ? root->GetAttribute("compressor") : nullptr;
    vtkSmartPointer<vtkDataCompressor> decompressor =
      Decompressor(compressor ? compressor : "");
    if (!data || (compressor && *compressor && !decompressor))
    {
      return; // VTK's reader reports it
    }
    ParsedXml xml;
    xml.File = file;
    xml.Text = text;
    xml.Size = static_cast<long long>(std::filesystem::file_size(file));
    xml.Appended = parser->GetAppendedDataPosition();
    vtkXMLDataElement* eAppended = root->FindNestedElementWithName("AppendedData");
    const char* encoding = eAppended ? eAppended->GetAttribute("encoding") : nullptr;
    xml.Base64Appended = !encoding || std::strcmp(encoding, "raw") != 0;
    xml.Compressed = decompressor != nullptr;
    const char* headerType = root->GetAttribute("header_type");
    xml.WordSize = headerType && std::strcmp(headerType, "UInt64") == 0 ? 8 : 4;
    const char* byteOrder = root->GetAttribute("byte_order");
    xml.BigEndian = byteOrder && std::strcmp(byteOrder, "BigEndian") == 0;
    xml.Ratio = RatioOf(compressor ? compressor : "");
    CheckParsedArrays(xml, root);
    parser->SetCompressor(decompressor);
    CheckCellOffsets(xml, parser, data, limit);
  };
  check();
}

long long MaximumRatio(std::string_view header)
{
  const auto has = [&header](const char* name) {
    return header.find(std::string("compressor=\"") + name + '"') != std::string_view::npos;
  };
  return header.find("compressor=") == std::string_view::npos ? 1
    : has("vtkLZ4DataCompressor")                             ? RatioOf("vtkLZ4DataCompressor")
    : has("vtkZLibDataCompressor")                            ? RatioOf("vtkZLibDataCompressor")
                                                              : RatioOf("other");
}

// vtkXMLReader aborts the process when an allocation fails and loops on absurd
// component counts, so the counts in the XML header (and in the files a .vtm or
// .pvt* refers to) are checked against the file size first: the arrays cannot
// declare more bytes than the file holds times the compressor's best ratio (an
// ASCII value takes at least one character).
void CheckXmlCounts(const std::string& file, int depth)
{
  const std::string text = ReadWholeFile(file, "<AppendedData");
  const std::string_view header = std::string_view(text).substr(0, text.find("<AppendedData"));
  const long long size = static_cast<long long>(std::filesystem::file_size(file));
  const long long ratio = MaximumRatio(header);
  const long long limit = size * ratio;
  constexpr long long maximumPoints = 1LL << 30;
  const std::size_t wordSize =
    header.find("header_type=\"UInt64\"") != std::string_view::npos ? 8 : 4;
  const bool bigEndian = header.find("byte_order=\"BigEndian\"") != std::string_view::npos;
  // Appended data starts after the '_' that follows <AppendedData ...>.
  const std::size_t appended = text.find('_', std::min(text.find('>', header.size()), text.size()));
  const bool rawAppended =
    text.substr(header.size(), 60).find("encoding=\"raw\"") != std::string::npos;
  // Tuples of the arrays of each section of the current piece ("Points",
  // "CellData", "Verts"...), and the bytes all arrays declare.
  std::map<std::string, long long, std::less<>> tuplesOf;
  std::string_view section;
  double declared = 0;
  std::size_t tag = 0;
  // The element VTKFile's type names must come first inside it: without it
  // VTK 9.2's composite readers dereference a null primary element.
  std::string_view primary;
  std::size_t primaryLine = 0;
  while ((tag = header.find('<', tag)) != std::string_view::npos)
  {
    const std::size_t close = header.find('>', tag);
    if (close == std::string_view::npos)
    {
      break; // an unterminated tag: the XML parser reports it
    }
    const std::string_view element = header.substr(tag + 1, close - tag - 1);
    const std::size_t line = 1 + std::count(header.begin(), header.begin() + tag, '\n');
    tag = close;
    const std::string_view name = element.substr(0, element.find_first_of(" \t\r\n/"));
    if (!primary.empty() && !name.empty() && name[0] != '!' && name[0] != '?')
    {
      if (name != primary)
      {
        Fail(file, line,
          "expected the element <" + std::string(primary) + "> inside VTKFile, found " +
            Quote(name) + " (corrupt or truncated file?)");
      }
      primary = {};
    }
    static const char* const sections[] = { "PointData", "CellData", "Points", "Verts", "Lines",
      "Strips", "Polys", "Cells", "Coordinates", "FieldData" };
    section = std::find(std::begin(sections), std::end(sections), name) != std::end(sections)
      ? name
      : section;
    if (name == "Piece")
    {
      tuplesOf.clear();
    }
    long long components = 1, tuples = -1;
    std::string_view format, offset, type, arrayName;
    // Attributes: name="value".
    for (std::size_t eq = 0; (eq = element.find("=\"", eq)) != std::string_view::npos; eq += 2)
    {
      std::size_t start = eq;
      while (start > 0 &&
        (std::isalpha(static_cast<unsigned char>(element[start - 1])) || element[start - 1] == '_'))
      {
        --start;
      }
      const std::string_view attribute = element.substr(start, eq - start);
      const std::size_t valueEnd = element.find('"', eq + 2);
      const std::string_view value = element.substr(eq + 2, valueEnd - eq - 2);
      long long count = 0;
      const auto implausible = [&]() {
        Fail(file, line,
          "implausible " + std::string(attribute) + "=" + Quote(value) +
            " (corrupt or truncated file?)");
      };
      format = attribute == "format" ? value : format;
      offset = attribute == "offset" ? value : offset;
      type = attribute == "type" ? value : type;
      arrayName = attribute == "Name" ? value : arrayName;
      if (attribute.substr(0, 8) == "NumberOf" && attribute != "NumberOfPieces")
      {
        if (!ParseCount(value, count) || count > limit ||
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
          const std::string_view kind = attribute.substr(8);
          tuplesOf[std::string(kind)] = count;
          tuplesOf[kind == "Points" ? "PointData" : "CellData"] += count;
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
          Fail(file, line,
            "unsupported VTK XML file type " + Quote(value) +
              " (expected a dataset with points or a multiblock of them)");
        }
        primary = value;
        primaryLine = line;
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
        if (!ParseCount(value, count) || count > static_cast<long long>(header.size()))
        {
          implausible();
        }
      }
      else if (attribute == "Extent" || attribute == "WholeExtent")
      {
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
          if (!ok || hi < lo || hi - lo >= maximumPoints ||
            (product *= hi - lo + 1) > maximumPoints)
          {
            implausible();
          }
          cells *= std::max(hi - lo, 1LL);
        }
        if (name == "Piece")
        {
          tuplesOf["PointData"] = product;
          tuplesOf["CellData"] = cells;
        }
      }
      else if ((attribute == "file" || attribute == "Source") && depth < 8)
      {
        // A block or piece in another file.
        const auto sub = std::filesystem::path(file).parent_path() / std::string(value);
        std::error_code error;
        if (std::filesystem::is_regular_file(sub, error))
        {
          CheckXmlCounts(sub.string(), depth + 1);
        }
      }
    }
    const bool isArray = name == "DataArray" || name == "Array";
    if (isArray && type.empty())
    {
      // No type at all: vtkXMLReader dereferences a null array too (field data).
      Fail(file, line,
        "data array " + Quote(arrayName) + " has no type (corrupt or truncated file?)");
    }
    // The connectivity of cells is sized by offsets (CheckCellOffsets).
    const auto sized = tuplesOf.find(section);
    if (isArray && arrayName != "connectivity" && arrayName != "faces" &&
      (tuples >= 0 || sized != tuplesOf.end()))
    {
      declared += static_cast<double>(components) * (tuples >= 0 ? tuples : sized->second) *
        BitsPerValue(type, format) / 8;
      if (declared > static_cast<double>(limit))
      {
        Fail(file, line,
          "data array " + Quote(arrayName) +
            " makes the data larger than the file can hold (corrupt or truncated file?)");
      }
    }
    if (isArray && (format == "binary" || format == "appended"))
    {
      std::string problem = "no data at offset " + Quote(offset);
      long long position = 0;
      if (format == "binary")
      {
        const std::size_t start =
          std::min(header.find_first_not_of(" \t\r\n", close + 1), header.size());
        const std::size_t end = std::min(header.find('<', start), header.size());
        const auto read = [&](std::size_t n) { return std::string(header.substr(start, n)); };
        problem = CheckBlockHeader(
          read, static_cast<long long>(end - start), true, ratio > 1, wordSize, bigEndian, ratio);
      }
      else if (appended != std::string::npos && ParseCount(offset, position) &&
        position < size - static_cast<long long>(appended + 1))
      {
        const long long at = static_cast<long long>(appended + 1) + position;
        const auto read = [&](std::size_t n) {
          std::ifstream in(file, std::ios::binary);
          in.seekg(static_cast<std::streamoff>(at));
          std::string bytes(n, '\0');
          in.read(&bytes[0], static_cast<std::streamsize>(n));
          bytes.resize(static_cast<std::size_t>(in.gcount()));
          return bytes;
        };
        problem =
          CheckBlockHeader(read, size - at, !rawAppended, ratio > 1, wordSize, bigEndian, ratio);
      }
      if (!problem.empty())
      {
        Fail(file, line,
          "data array " + Quote(arrayName) + ": " + problem + " (corrupt or truncated file?)");
      }
    }
  }
  if (!primary.empty())
  {
    Fail(file, primaryLine,
      "VTKFile of type " + Quote(primary) + " holds no <" + std::string(primary) +
        "> element (corrupt or truncated file?)");
  }
  CheckParsedXml(file, text, limit);
}

} // namespace

void CheckXmlFile(const std::string& file)
{
  CheckXmlCounts(file, 0);
}

} // namespace reader
} // namespace flowrecon
