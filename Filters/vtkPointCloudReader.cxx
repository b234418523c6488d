#include "vtkPointCloudReader.h"

#include "MemoryGuard.h" // core: bounds allocations the file cannot
#include "Progress.h"    // core: InputError

#include "vtkCellArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLZ4DataCompressor.h"
#include "vtkLZMADataCompressor.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"
#include "vtkXMLGenericDataObjectReader.h"
#include "vtkZLibDataCompressor.h"
#include "vtksys/FStream.hxx"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

vtkStandardNewMacro(vtkPointCloudReader);

namespace
{

// A failure to report; what() is the complete one-line message.
class ReadError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void Fail(const std::string& file, std::size_t line, const std::string& message)
{
  std::string where = file;
  if (line > 0)
  {
    where += ":" + std::to_string(line);
  }
  throw ReadError(where + ": " + message);
}

std::string ToLower(std::string_view s)
{
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// Lowercased extension with its dot ("" if none), e.g. ".xyz".
std::string Extension(const std::string& path)
{
  const std::string name = std::filesystem::path(path).filename().string();
  const std::size_t dot = name.rfind('.');
  return dot == std::string::npos || dot == 0 ? std::string() : ToLower(name.substr(dot));
}

enum class Format
{
  Unknown,
  Xyz,
  Pts,
  Csv,
  Off,
  Obj,
  Ply,
  LegacyVtk,
  XmlVtk
};

Format FormatOf(const std::string& extension)
{
  static const std::pair<const char*, Format> formats[] = { { ".xyz", Format::Xyz },
    { ".txt", Format::Xyz }, { ".pts", Format::Pts }, { ".csv", Format::Csv },
    { ".off", Format::Off }, { ".ply", Format::Ply }, { ".obj", Format::Obj },
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

// ---------------------------------------------------------------------------
// Text formats.

bool IsBlank(char c)
{
  return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r';
}

std::string_view Trim(std::string_view s)
{
  while (!s.empty() && IsBlank(s.front()))
  {
    s.remove_prefix(1);
  }
  while (!s.empty() && IsBlank(s.back()))
  {
    s.remove_suffix(1);
  }
  return s;
}

// A token for an error message: quoted, control bytes escaped, long ones cut.
std::string Quote(std::string_view token)
{
  constexpr std::size_t maxLength = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < maxLength; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c < 0x20 || c == 0x7f)
    {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\x%02x", c);
      out += escaped;
    }
    else
    {
      out += static_cast<char>(c);
    }
  }
  return out + (token.size() > maxLength ? "...'" : "'");
}

bool HasControlBytes(std::string_view text)
{
  return std::any_of(text.begin(), text.end(), [](char ch) {
    const unsigned char c = static_cast<unsigned char>(ch);
    return (c < 0x20 && !IsBlank(ch)) || c == 0x7f;
  });
}

enum class Number
{
  Ok,
  Invalid,
  Overflow
};

// Locale-independent (std::from_chars). Accepts a leading '+', which from_chars
// does not; NaN and infinities parse (the caller rejects them with a clear
// message); magnitudes below the smallest double become zero.
Number ParseNumber(std::string_view token, double& value)
{
  if (token.size() > 1 && token[0] == '+' && token[1] != '+' && token[1] != '-')
  {
    token.remove_prefix(1);
  }
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (token.empty() || ptr != end || ec == std::errc::invalid_argument)
  {
    return Number::Invalid;
  }
  if (ec == std::errc::result_out_of_range)
  {
    const std::size_t e = token.find_first_of("eE");
    if (e != std::string_view::npos && e + 1 < token.size() && token[e + 1] == '-')
    {
      value = token[0] == '-' ? -0.0 : 0.0;
      return Number::Ok;
    }
    return Number::Overflow;
  }
  return Number::Ok;
}

// Parses one coordinate; `what` names it for the message ("y coordinate").
double Coordinate(
  const std::string& file, std::size_t line, std::string_view token, const std::string& what)
{
  double value = 0;
  switch (ParseNumber(token, value))
  {
    case Number::Invalid:
      if (token.empty())
      {
        Fail(file, line, "empty field where the " + what + " was expected");
      }
      Fail(file, line, "cannot parse " + Quote(token) + " as a number (" + what + ")");
    case Number::Overflow:
      Fail(file, line, "number " + Quote(token) + " is out of range (" + what + ")");
    case Number::Ok:
      break;
  }
  if (!std::isfinite(value))
  {
    Fail(file, line, "non-finite " + what + " " + Quote(token));
  }
  return value;
}

const char* const AxisName[3] = { "x", "y", "z" };

// Iterates over the lines of a buffer ("\n", "\r\n" or "\r" endings), numbered
// from 1; a UTF-8 byte order mark is dropped.
class Lines
{
public:
  Lines(const std::string& file, std::string_view text)
    : File(file)
    , Text(text)
  {
    if (this->Text.substr(0, 3) == "\xEF\xBB\xBF")
    {
      this->Pos = 3;
    }
  }

  bool Next(std::string_view& line)
  {
    if (this->Pos >= this->Text.size())
    {
      return false;
    }
    std::size_t end = this->Text.find_first_of("\r\n", this->Pos);
    if (end == std::string_view::npos)
    {
      end = this->Text.size();
    }
    line = this->Text.substr(this->Pos, end - this->Pos);
    this->Pos = end + 1;
    if (end < this->Text.size() && this->Text[end] == '\r' && this->Pos < this->Text.size() &&
      this->Text[this->Pos] == '\n')
    {
      ++this->Pos;
    }
    ++this->Number;
    return true;
  }

  // The next line that is neither blank nor a comment (# or //). Control
  // bytes mean a binary file: stop there rather than report odd numbers.
  bool NextData(std::string_view& line)
  {
    while (this->Next(line))
    {
      if (HasControlBytes(line))
      {
        Fail(this->File, this->Number, "binary data in a text file");
      }
      const std::string_view t = Trim(line);
      if (!t.empty() && t[0] != '#' && t.substr(0, 2) != "//")
      {
        return true;
      }
    }
    return false;
  }

  // Byte offset of the next line.
  std::size_t Offset() const { return this->Pos; }

  std::size_t Number = 0;

private:
  const std::string& File;
  std::string_view Text;
  std::size_t Pos = 0;
};

// The first `maxFields` fields of a line separated by runs of blanks and commas.
void SplitLoose(std::string_view line, std::vector<std::string_view>& fields, std::size_t maxFields)
{
  fields.clear();
  std::size_t i = 0;
  while (fields.size() < maxFields)
  {
    while (i < line.size() && (IsBlank(line[i]) || line[i] == ','))
    {
      ++i;
    }
    if (i >= line.size())
    {
      return;
    }
    const std::size_t start = i;
    while (i < line.size() && !IsBlank(line[i]) && line[i] != ',')
    {
      ++i;
    }
    fields.push_back(line.substr(start, i - start));
  }
}

// CSV fields: split on `delimiter` outside double quotes, trimmed, unquoted.
void SplitCsv(std::string_view line, char delimiter, std::vector<std::string_view>& fields)
{
  if (delimiter == ' ')
  {
    SplitLoose(line, fields, std::string_view::npos);
    return;
  }
  fields.clear();
  std::size_t start = 0;
  bool quoted = false;
  for (std::size_t i = 0; i <= line.size(); ++i)
  {
    if (i < line.size() && line[i] == '"')
    {
      quoted = !quoted;
    }
    else if (i == line.size() || (!quoted && line[i] == delimiter))
    {
      std::string_view field = Trim(line.substr(start, i - start));
      if (field.size() >= 2 && field.front() == '"' && field.back() == '"')
      {
        field = Trim(field.substr(1, field.size() - 2));
      }
      fields.push_back(field);
      start = i + 1;
    }
  }
}

// Which coordinate a CSV header names: x/y/z, or ParaView's Points:0..2
// (also coordinates:/coords:/point:), any case; -1 otherwise.
int AxisOfHeader(std::string_view name)
{
  const std::string n = ToLower(name);
  for (int axis = 0; axis < 3; ++axis)
  {
    if (n == AxisName[axis])
    {
      return axis;
    }
  }
  const std::size_t colon = n.find(':');
  if (colon != std::string::npos && n.size() == colon + 2 && n[colon + 1] >= '0' &&
    n[colon + 1] <= '2')
  {
    const std::string prefix = n.substr(0, colon);
    if (prefix == "points" || prefix == "point" || prefix == "coordinates" || prefix == "coords")
    {
      return n[colon + 1] - '0';
    }
  }
  return -1;
}

void ReadXyz(
  const std::string& file, std::string_view text, bool countLine, std::vector<double>& xyz)
{
  Lines lines(file, text);
  std::string_view line;
  std::vector<std::string_view> fields;
  bool first = true;
  while (lines.NextData(line))
  {
    SplitLoose(line, fields, 3);
    if (first && countLine && fields.size() == 1 &&
      fields[0].find_first_not_of("0123456789") == std::string_view::npos)
    {
      first = false; // the point count of a .pts file
      continue;
    }
    first = false;
    double p[3];
    for (std::size_t k = 0; k < fields.size(); ++k)
    {
      p[k] = Coordinate(file, lines.Number, fields[k], std::string(AxisName[k]) + " coordinate");
    }
    if (fields.size() < 3)
    {
      Fail(file, lines.Number,
        "expected 3 coordinates (x y z), found " + std::to_string(fields.size()));
    }
    xyz.insert(xyz.end(), p, p + 3);
  }
}

void ReadCsv(const std::string& file, std::string_view text, std::vector<double>& xyz)
{
  Lines lines(file, text);
  std::string_view line;
  std::vector<std::string_view> fields;
  char delimiter = 0;
  bool first = true;
  std::array<std::size_t, 3> column{};
  std::array<std::string, 3> what; // "y coordinate (column 'Y')"
  bool haveColumns = false;
  while (lines.NextData(line))
  {
    if (!delimiter)
    {
      // ';' and tabs never occur in numbers, commas may (decimal commas).
      delimiter = line.find(';') != std::string_view::npos ? ';'
        : line.find('\t') != std::string_view::npos        ? '\t'
        : line.find(',') != std::string_view::npos         ? ','
                                                           : ' ';
    }
    SplitCsv(line, delimiter, fields);
    if (std::all_of(fields.begin(), fields.end(), [](std::string_view f) { return f.empty(); }))
    {
      continue;
    }
    double value;
    const auto isNumber = [&value](std::string_view f) {
      return ParseNumber(f, value) != Number::Invalid;
    };
    if (first)
    {
      first = false;
      if (std::none_of(fields.begin(), fields.end(), isNumber))
      {
        // A header row: use the columns it names x, y, z when it names all three.
        std::array<int, 3> named{ { -1, -1, -1 } };
        for (std::size_t i = 0; i < fields.size(); ++i)
        {
          const int axis = AxisOfHeader(fields[i]);
          if (axis >= 0 && named[axis] < 0)
          {
            named[axis] = static_cast<int>(i);
          }
        }
        if (std::all_of(named.begin(), named.end(), [](int c) { return c >= 0; }))
        {
          for (int k = 0; k < 3; ++k)
          {
            column[k] = static_cast<std::size_t>(named[k]);
            what[k] =
              std::string(AxisName[k]) + " coordinate (column " + Quote(fields[column[k]]) + ")";
          }
          haveColumns = true;
        }
        continue;
      }
    }
    if (!haveColumns)
    {
      // No usable header: the first three numeric columns of the first data row.
      std::size_t found = 0;
      for (std::size_t i = 0; i < fields.size() && found < 3; ++i)
      {
        if (isNumber(fields[i]))
        {
          column[found] = i;
          what[found] =
            std::string(AxisName[found]) + " coordinate (column " + std::to_string(i + 1) + ")";
          ++found;
        }
      }
      if (found < 3)
      {
        Fail(file, lines.Number,
          "expected at least 3 numeric columns (x y z), found " + std::to_string(found));
      }
      haveColumns = true;
    }
    double p[3];
    for (int k = 0; k < 3; ++k)
    {
      if (column[k] >= fields.size())
      {
        Fail(file, lines.Number,
          "missing " + what[k] + ": the line has only " + std::to_string(fields.size()) +
            " fields");
      }
      p[k] = Coordinate(file, lines.Number, fields[column[k]], what[k]);
    }
    xyz.insert(xyz.end(), p, p + 3);
  }
}

bool ParseCount(std::string_view token, long long& count)
{
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, count);
  return !token.empty() && ec == std::errc() && ptr == end && count >= 0;
}

void ReadOff(const std::string& file, std::string_view text, std::vector<double>& xyz)
{
  Lines lines(file, text);
  std::string_view line;
  std::vector<std::string_view> fields;
  if (!lines.NextData(line))
  {
    Fail(file, 0, "no OFF header (the file holds no data)");
  }
  SplitLoose(line, fields, std::string_view::npos);
  // [ST][C][N]OFF; 4OFF and nOFF are higher-dimensional. A line of separators
  // only has no field at all.
  std::string_view keyword = fields.empty() ? std::string_view() : fields[0];
  if (keyword.substr(0, 2) == "ST")
  {
    keyword.remove_prefix(2);
  }
  for (const char prefix : { 'C', 'N' })
  {
    if (!keyword.empty() && keyword[0] == prefix)
    {
      keyword.remove_prefix(1);
    }
  }
  if (keyword != "OFF")
  {
    const std::string_view found = fields.empty() ? line : fields[0];
    Fail(file, lines.Number,
      found.find("OFF") != std::string_view::npos
        ? "unsupported OFF variant " + Quote(found) + " (only 3D OFF files are read)"
        : "expected the OFF header keyword, found " + Quote(found));
  }
  if (std::find(fields.begin(), fields.end(), "BINARY") != fields.end())
  {
    Fail(file, lines.Number, "binary OFF files are not supported");
  }
  // The counts may follow the keyword on the same line.
  fields.erase(fields.begin());
  if (fields.empty())
  {
    if (!lines.NextData(line))
    {
      Fail(file, lines.Number, "file ends before the vertex and face counts");
    }
    SplitLoose(line, fields, std::string_view::npos);
  }
  long long vertices = 0, faces = 0;
  if (fields.size() < 2 || !ParseCount(fields[0], vertices) || !ParseCount(fields[1], faces))
  {
    Fail(
      file, lines.Number, "expected the counts 'vertices faces edges', found " + Quote(Trim(line)));
  }
  if (vertices == 0)
  {
    Fail(file, lines.Number, "the OFF file has no vertices");
  }
  // Never trust a count for an allocation: each vertex line takes >= 6 bytes.
  xyz.reserve(3 * static_cast<std::size_t>(std::min<long long>(vertices, text.size() / 6 + 1)));
  for (long long i = 0; i < vertices; ++i)
  {
    if (!lines.NextData(line))
    {
      Fail(file, lines.Number,
        "file ends after " + std::to_string(i) + " of " + std::to_string(vertices) + " vertices");
    }
    SplitLoose(line, fields, 3);
    double p[3];
    for (std::size_t k = 0; k < fields.size(); ++k)
    {
      p[k] = Coordinate(file, lines.Number, fields[k], std::string(AxisName[k]) + " coordinate");
    }
    if (fields.size() < 3)
    {
      Fail(file, lines.Number,
        "expected 3 coordinates (x y z), found " + std::to_string(fields.size()));
    }
    xyz.insert(xyz.end(), p, p + 3);
  }
  // Faces are not used, but a file that ends early is truncated or laid out in a
  // way this reader would misread (several vertices per line): refuse it.
  long long faceLines = 0;
  while (faceLines < faces && lines.NextData(line))
  {
    ++faceLines;
  }
  if (faceLines < faces)
  {
    Fail(file, lines.Number,
      "file ends after " + std::to_string(faceLines) + " of " + std::to_string(faces) +
        " faces (truncated, or not one vertex per line)");
  }
}

void ReadObj(const std::string& file, std::string_view text, std::vector<double>& xyz)
{
  // Only "v x y z [w | r g b]" lines matter; faces, normals, groups... are skipped.
  Lines lines(file, text);
  std::string_view line;
  std::vector<std::string_view> fields;
  while (lines.NextData(line))
  {
    SplitLoose(line, fields, 4);
    if (fields.empty() || fields[0] != "v") // a line of separators only has no field
    {
      continue;
    }
    double p[3];
    for (std::size_t k = 1; k < fields.size(); ++k)
    {
      p[k - 1] =
        Coordinate(file, lines.Number, fields[k], std::string(AxisName[k - 1]) + " coordinate");
    }
    if (fields.size() < 4)
    {
      Fail(file, lines.Number,
        "expected 3 coordinates after 'v', found " + std::to_string(fields.size() - 1));
    }
    xyz.insert(xyz.end(), p, p + 3);
  }
}

// ---------------------------------------------------------------------------
// PLY: the vertex element is read here (vtkPLYReader aborts the process on a
// truncated file and reads garbage numbers as 0). Scalar vertex properties other
// than x, y, z become point data arrays.

struct PlyProperty
{
  std::string Name;
  int Type = 0;      // VTK type of the value, or of a list's items
  int CountType = 0; // VTK type of a list's length; 0 for a scalar
};

struct PlyElement
{
  std::string Name;
  long long Count = 0;
  std::vector<PlyProperty> Properties;
};

int PlyType(std::string_view name)
{
  static const std::pair<const char*, int> types[] = { { "char", VTK_SIGNED_CHAR },
    { "int8", VTK_SIGNED_CHAR }, { "uchar", VTK_UNSIGNED_CHAR }, { "uint8", VTK_UNSIGNED_CHAR },
    { "short", VTK_SHORT }, { "int16", VTK_SHORT }, { "ushort", VTK_UNSIGNED_SHORT },
    { "uint16", VTK_UNSIGNED_SHORT }, { "int", VTK_INT }, { "int32", VTK_INT },
    { "uint", VTK_UNSIGNED_INT }, { "uint32", VTK_UNSIGNED_INT }, { "float", VTK_FLOAT },
    { "float32", VTK_FLOAT }, { "double", VTK_DOUBLE }, { "float64", VTK_DOUBLE } };
  for (const auto& t : types)
  {
    if (name == t.first)
    {
      return t.second;
    }
  }
  return 0;
}

template <typename T>
double Load(const unsigned char* bytes)
{
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return static_cast<double>(value);
}

// Reads one binary value at `pos` and advances; false if the data ends first.
bool ReadBinary(std::string_view data, std::size_t& pos, int type, bool swap, double& value)
{
  const std::size_t size = static_cast<std::size_t>(vtkAbstractArray::GetDataTypeSize(type));
  if (data.size() - pos < size)
  {
    return false;
  }
  unsigned char bytes[8];
  std::memcpy(bytes, data.data() + pos, size);
  pos += size;
  if (swap)
  {
    std::reverse(bytes, bytes + size);
  }
  switch (type)
  {
    case VTK_SIGNED_CHAR:
      value = Load<signed char>(bytes);
      break;
    case VTK_UNSIGNED_CHAR:
      value = Load<unsigned char>(bytes);
      break;
    case VTK_SHORT:
      value = Load<short>(bytes);
      break;
    case VTK_UNSIGNED_SHORT:
      value = Load<unsigned short>(bytes);
      break;
    case VTK_INT:
      value = Load<int>(bytes);
      break;
    case VTK_UNSIGNED_INT:
      value = Load<unsigned int>(bytes);
      break;
    case VTK_FLOAT:
      value = Load<float>(bytes);
      break;
    default:
      value = Load<double>(bytes);
      break;
  }
  return true;
}

// Walks the values of PLY element instances, ASCII (one instance per line) or
// binary; failures name the element and property.
class PlyCursor
{
public:
  PlyCursor(const std::string& file, Lines& lines, std::string_view text, const std::string& format)
    : File(file)
    , Text(lines)
    , Data(text)
    , Pos(lines.Offset())
    , Ascii(format == "ascii")
  {
    const std::uint16_t one = 1;
    const bool littleEndianHost = *reinterpret_cast<const unsigned char*>(&one) == 1;
    this->Swap = !this->Ascii && (format == "binary_little_endian") != littleEndianHost;
  }

  // The line of the current instance (ASCII), 0 for binary files.
  std::size_t Line() const { return this->Ascii ? this->Text.Number : 0; }

  void Begin(const PlyElement& element, long long n)
  {
    std::string_view line;
    if (this->Ascii)
    {
      if (!this->Text.NextData(line))
      {
        Fail(this->File, this->Text.Number,
          "file ends after " + std::to_string(n) + " of " + std::to_string(element.Count) + " " +
            element.Name + " elements");
      }
      SplitLoose(line, this->Tokens, std::string_view::npos);
      this->Token = 0;
    }
  }

  double Next(int type, const PlyProperty& property, const PlyElement& element)
  {
    double value = 0;
    if (!this->Ascii)
    {
      if (!ReadBinary(this->Data, this->Pos, type, this->Swap, value))
      {
        this->Truncated(property, element);
      }
      return value;
    }
    if (this->Token >= this->Tokens.size())
    {
      Fail(this->File, this->Text.Number,
        "missing value of " + element.Name + " property '" + property.Name + "'");
    }
    const std::string_view token = this->Tokens[this->Token++];
    if (ParseNumber(token, value) != Number::Ok)
    {
      Fail(this->File, this->Text.Number,
        "cannot parse " + Quote(token) + " as a number (" + element.Name + " property '" +
          property.Name + "')");
    }
    return value;
  }

  void SkipList(const PlyProperty& property, const PlyElement& element)
  {
    const double length = this->Next(property.CountType, property, element);
    const std::size_t size =
      static_cast<std::size_t>(vtkAbstractArray::GetDataTypeSize(property.Type));
    const std::size_t left =
      this->Ascii ? this->Tokens.size() - this->Token : (this->Data.size() - this->Pos) / size;
    if (!(length >= 0 && length <= static_cast<double>(left)))
    {
      if (this->Ascii)
      {
        Fail(this->File, this->Text.Number,
          "invalid length of " + element.Name + " list '" + property.Name + "'");
      }
      this->Truncated(property, element);
    }
    (this->Ascii ? this->Token : this->Pos) +=
      static_cast<std::size_t>(length) * (this->Ascii ? 1 : size);
  }

private:
  [[noreturn]] void Truncated(const PlyProperty& property, const PlyElement& element)
  {
    Fail(this->File, 0,
      "file ends inside " + element.Name + " property '" + property.Name + "' (truncated?)");
  }

  const std::string& File;
  Lines& Text;
  std::string_view Data;
  std::size_t Pos;
  bool Ascii;
  bool Swap = false;
  std::vector<std::string_view> Tokens;
  std::size_t Token = 0;
};

// Replaces the single-component arrays `names` by one array `grouped` (as
// vtkPLYReader does for normals and colors).
void GroupArrays(vtkPointData* pointData, const std::vector<const char*>& names,
  const char* grouped, bool asNormals)
{
  std::vector<vtkDataArray*> parts;
  for (const char* name : names)
  {
    vtkDataArray* part = pointData->GetArray(name);
    if (!part || (!parts.empty() && part->GetDataType() != parts[0]->GetDataType()))
    {
      return;
    }
    parts.push_back(part);
  }
  vtkSmartPointer<vtkDataArray> array;
  array.TakeReference(vtkDataArray::CreateDataArray(parts[0]->GetDataType()));
  array->SetName(grouped);
  array->SetNumberOfComponents(static_cast<int>(parts.size()));
  array->SetNumberOfTuples(parts[0]->GetNumberOfTuples());
  for (int c = 0; c < static_cast<int>(parts.size()); ++c)
  {
    array->CopyComponent(c, parts[c], 0);
  }
  for (const char* name : names)
  {
    pointData->RemoveArray(name);
  }
  if (asNormals)
  {
    pointData->SetNormals(array);
  }
  else
  {
    pointData->AddArray(array);
  }
}

void ReadPly(
  const std::string& file, std::string_view text, std::vector<double>& xyz, vtkPointData* pointData)
{
  Lines lines(file, text);
  std::string_view line;
  std::vector<std::string_view> fields;
  if (!lines.Next(line) || Trim(line) != "ply")
  {
    Fail(file, 0, "not a PLY file (it does not start with 'ply')");
  }
  std::string format;
  std::vector<PlyElement> elements;
  for (;;)
  {
    if (!lines.Next(line))
    {
      Fail(file, 0, "the PLY header has no end_header (truncated?)");
    }
    SplitLoose(line, fields, std::string_view::npos);
    if (fields.empty() || fields[0] == "comment" || fields[0] == "obj_info")
    {
      continue;
    }
    if (HasControlBytes(line))
    {
      Fail(file, lines.Number, "binary data in the PLY header");
    }
    if (fields[0] == "end_header")
    {
      break;
    }
    if (fields[0] == "format" && fields.size() >= 2 &&
      (fields[1] == "ascii" || fields[1] == "binary_little_endian" ||
        fields[1] == "binary_big_endian"))
    {
      format = fields[1];
    }
    else if (fields[0] == "element" && fields.size() == 3)
    {
      elements.emplace_back();
      elements.back().Name = fields[1];
      if (!ParseCount(fields[2], elements.back().Count))
      {
        Fail(file, lines.Number, "invalid element count " + Quote(fields[2]));
      }
    }
    else if (fields[0] == "property" && !elements.empty() &&
      (fields.size() == 3 || (fields.size() == 5 && fields[1] == "list")))
    {
      PlyProperty property;
      property.Name = fields.back();
      property.Type = PlyType(fields[fields.size() - 2]);
      property.CountType = fields.size() == 5 ? PlyType(fields[2]) : 0;
      if (!property.Type || (fields.size() == 5 && !property.CountType))
      {
        Fail(file, lines.Number, "unknown PLY property type in " + Quote(Trim(line)));
      }
      elements.back().Properties.push_back(property);
    }
    else
    {
      Fail(file, lines.Number, "invalid PLY header line " + Quote(Trim(line)));
    }
  }
  if (format.empty())
  {
    Fail(file, 0, "the PLY header has no format line");
  }
  const auto vertexElement = std::find_if(
    elements.begin(), elements.end(), [](const PlyElement& e) { return e.Name == "vertex"; });
  if (vertexElement == elements.end())
  {
    Fail(file, 0, "the PLY file has no vertex element");
  }
  const PlyElement& vertex = *vertexElement;
  std::array<int, 3> axis{ { -1, -1, -1 } };
  std::size_t minimumBytes = 0; // bytes one vertex takes at least
  for (std::size_t i = 0; i < vertex.Properties.size(); ++i)
  {
    const PlyProperty& property = vertex.Properties[i];
    for (int k = 0; k < 3; ++k)
    {
      if (property.Name == AxisName[k] && !property.CountType)
      {
        axis[k] = static_cast<int>(i);
      }
    }
    minimumBytes += format == "ascii" ? 2
                                      : static_cast<std::size_t>(vtkAbstractArray::GetDataTypeSize(
                                          property.CountType ? property.CountType : property.Type));
  }
  for (int k = 0; k < 3; ++k)
  {
    if (axis[k] < 0)
    {
      Fail(file, 0, std::string("the PLY vertex element has no '") + AxisName[k] + "' property");
    }
  }
  // Never allocate for a count the file cannot hold.
  const std::size_t dataBytes = text.size() - lines.Offset();
  if (vertex.Count > 0 && static_cast<unsigned long long>(vertex.Count) > dataBytes / minimumBytes)
  {
    Fail(file, 0,
      "the PLY header announces " + std::to_string(vertex.Count) + " vertices but only " +
        std::to_string(dataBytes) + " bytes of data follow (truncated?)");
  }

  // One point data array per scalar property other than x, y, z.
  std::vector<vtkSmartPointer<vtkDataArray>> arrays(vertex.Properties.size());
  for (std::size_t i = 0; i < vertex.Properties.size(); ++i)
  {
    const PlyProperty& property = vertex.Properties[i];
    if (!property.CountType && std::find(axis.begin(), axis.end(), int(i)) == axis.end())
    {
      arrays[i].TakeReference(vtkDataArray::CreateDataArray(property.Type));
      arrays[i]->SetName(property.Name.c_str());
      arrays[i]->SetNumberOfTuples(vertex.Count);
    }
  }
  xyz.reserve(3 * static_cast<std::size_t>(vertex.Count));
  std::vector<double> values(vertex.Properties.size());
  PlyCursor cursor(file, lines, text, format);
  for (const PlyElement& element : elements)
  {
    const bool isVertex = &element == &vertex;
    for (long long n = 0; n < element.Count && !element.Properties.empty(); ++n)
    {
      cursor.Begin(element, n);
      for (std::size_t i = 0; i < element.Properties.size(); ++i)
      {
        const PlyProperty& property = element.Properties[i];
        if (property.CountType)
        {
          cursor.SkipList(property, element);
        }
        else
        {
          values[i] = cursor.Next(property.Type, property, element);
        }
      }
      if (!isVertex)
      {
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        if (!std::isfinite(values[axis[k]]))
        {
          Fail(file, cursor.Line(),
            "non-finite " + std::string(AxisName[k]) + " coordinate (vertex " + std::to_string(n) +
              ")");
        }
        xyz.push_back(values[axis[k]]);
      }
      for (std::size_t i = 0; i < arrays.size(); ++i)
      {
        if (arrays[i])
        {
          arrays[i]->SetComponent(static_cast<vtkIdType>(n), 0, values[i]);
        }
      }
    }
    if (isVertex)
    {
      break; // the elements after the vertices are not needed
    }
  }
  for (const auto& array : arrays)
  {
    if (array)
    {
      pointData->AddArray(array);
    }
  }
  GroupArrays(pointData, { "nx", "ny", "nz" }, "Normals", true);
  GroupArrays(pointData, { "red", "green", "blue", "alpha" }, "RGBA", false);
  GroupArrays(pointData, { "red", "green", "blue" }, "RGB", false);
}

// The bytes of a file; with `stopAfter`, reading may stop once that text was read.
std::string ReadWholeFile(const std::string& file, std::string_view stopAfter = {})
{
  std::ifstream in(file, std::ios::binary);
  if (!in)
  {
    Fail(file, 0, std::string("cannot open file (") + std::strerror(errno) + ")");
  }
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof(buffer)) || in.gcount() > 0)
  {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    // Stop a little after the marker: callers look at the bytes that follow it.
    const std::size_t found = stopAfter.empty() ? std::string::npos : text.find(stopAfter);
    if (found != std::string::npos && text.size() > found + 1024)
    {
      break;
    }
  }
  if (in.bad())
  {
    Fail(file, 0, "read error");
  }
  return text;
}

// ---------------------------------------------------------------------------
// Files read by VTK readers.

// The whitespace-separated tokens of a legacy file, as vtkDataReader's `>>`
// reads them, with its way of skipping a line or binary bytes.
class LegacyTokens
{
public:
  LegacyTokens(std::string_view text, std::size_t pos)
    : Text(text)
    , Pos(pos)
  {
  }

  bool Next(std::string_view& token)
  {
    const auto space = [](char c) { return c == ' ' || (c >= '\t' && c <= '\r'); };
    while (this->Pos < this->Text.size() && space(this->Text[this->Pos]))
    {
      ++this->Pos;
    }
    const std::size_t start = this->Pos;
    while (this->Pos < this->Text.size() && !space(this->Text[this->Pos]))
    {
      ++this->Pos;
    }
    token = this->Text.substr(start, this->Pos - start);
    return !token.empty();
  }

  // To the start of the next line; false at the end of the text.
  bool SkipLine()
  {
    const std::size_t end = this->Text.find('\n', this->Pos);
    this->Pos = end == std::string_view::npos ? this->Text.size() : end + 1;
    return end != std::string_view::npos;
  }

  bool Skip(unsigned long long bytes)
  {
    if (bytes > this->Left())
    {
      return false;
    }
    this->Pos += static_cast<std::size_t>(bytes);
    return true;
  }

  // Skips the METADATA block vtkDataReader::ReadArray reads after an array's
  // values, if one follows, as it reads it: lines of spaces are popped, then
  // "metadata" must start right there; its lines end at the first one that is
  // empty for strlen (a NUL first counts: VTK reads lines into a C string).
  // VTK's component-name and information readers may read past such a line;
  // stopping here instead only checks more of the file, never less.
  void SkipMetadata()
  {
    for (;;)
    {
      const std::size_t p = this->Text.find_first_not_of(' ', this->Pos);
      if (p == std::string_view::npos)
      {
        return;
      }
      if (this->Text[p] != '\n')
      {
        break;
      }
      this->Pos = p + 1;
    }
    if (ToLower(this->Text.substr(this->Pos, 8)) != "metadata")
    {
      return;
    }
    while (this->SkipLine())
    {
      if (this->Pos >= this->Text.size() || this->Text[this->Pos] == '\n' ||
        this->Text[this->Pos] == '\0')
      {
        this->SkipLine();
        break;
      }
    }
  }

  unsigned long long Left() const { return this->Text.size() - this->Pos; }

  std::string_view Text;
  std::size_t Pos;
};

// How vtkDataReader::ReadArray stores a value of a legacy type in a binary
// file: its size in bytes, or one of these.

enum LegacyValue : int
{
  LegacyUnknown = -1, // a type it does not read
  LegacyBit = -2,
  LegacyString = -3, // length-prefixed
  LegacyText = -4    // a type and a value, as in ASCII files
};

int LegacyValueSize(std::string_view type)
{
  // ReadArray's tests in its order: most by prefix, char and signed_char exactly.
  static const std::pair<const char*, int> types[] = { { "bit", LegacyBit }, { "unsigned_char", 1 },
    { "short", 2 }, { "unsigned_short", 2 }, { "vtkidtype", 4 }, { "int", 4 },
    { "unsigned_int", 4 }, { "long", 8 }, { "unsigned_long", 8 }, { "vtktypeint64", 8 },
    { "vtktypeuint64", 8 }, { "float", 4 }, { "double", 8 }, { "string", LegacyString },
    { "utf8_string", LegacyString }, { "variant", LegacyText } };
  const std::string t = ToLower(type);
  if (t == "char" || t == "signed_char")
  {
    return 1;
  }
  for (const auto& entry : types)
  {
    if (t.compare(0, std::strlen(entry.first), entry.first) == 0)
    {
      return entry.second;
    }
  }
  return LegacyUnknown;
}

// Skips the `count` length-prefixed strings of a binary string array (the
// two top bits of the first byte give the size of the length); false if the
// file ends first.
bool SkipBinaryStrings(LegacyTokens& tokens, unsigned long long count)
{
  for (unsigned long long i = 0; i < count; ++i)
  {
    if (tokens.Left() == 0)
    {
      return false;
    }
    const unsigned char first = static_cast<unsigned char>(tokens.Text[tokens.Pos]);
    const std::size_t header = std::size_t(1) << (3 - (first >> 6)); // 1, 2, 4 or 8 bytes
    if (tokens.Left() < header)
    {
      return false;
    }
    unsigned long long length = 0;
    for (std::size_t k = 0; k < header; ++k)
    {
      length = (length << 8) | static_cast<unsigned char>(tokens.Text[tokens.Pos + k]);
    }
    if (header < 8)
    {
      length &= (1ULL << (8 * header - 2)) - 1;
    }
    if (!tokens.Skip(header) || !tokens.Skip(length))
    {
      return false;
    }
  }
  return true;
}

// Skips the `count` values of an array of a known type; false if the file
// ends first.
bool SkipLegacyValues(LegacyTokens& tokens, int size, unsigned long long count, bool binary)
{
  std::string_view token;
  if (count == 0)
  {
    return true;
  }
  if (size == LegacyString)
  {
    // A newline, then a line (ASCII) or a length-prefixed string (binary) each.
    tokens.SkipLine();
    if (binary)
    {
      return SkipBinaryStrings(tokens, count);
    }
    for (unsigned long long i = 0; i < count; ++i)
    {
      if (!tokens.SkipLine() && i + 1 < count)
      {
        return false;
      }
    }
    return true;
  }
  if (binary && size != LegacyText)
  {
    tokens.SkipLine();
    return tokens.Skip(
      size == LegacyBit ? (count + 7) / 8 : count * static_cast<unsigned long long>(size));
  }
  if (size == LegacyText)
  {
    for (unsigned long long i = 0; i < 2 * count; ++i)
    {
      if (!tokens.Next(token))
      {
        return false;
      }
    }
    return true;
  }
  // `>>` stops at the first word that is not a number, and VTK reads on from
  // there: stop before it too.
  double value = 0;
  for (unsigned long long i = 0; i < count; ++i)
  {
    if (!tokens.Next(token) || ParseNumber(token, value) != Number::Ok)
    {
      tokens.Pos = static_cast<std::size_t>(token.data() - tokens.Text.data());
      return false;
    }
  }
  return true;
}

// Walks a FIELD block (the tokens after its keyword) as
// vtkDataReader::ReadFieldData reads it. Before POINT_DATA and CELL_DATA,
// VTK 9.2's readers use what it returns unchecked (a null pointer when the
// header lacks the name or the count, or an array has an unknown type), so
// refuse whatever it would not read; each count must fit the file.
void CheckFieldBlock(const std::string& file, LegacyTokens& tokens, bool binary)
{
  // Problems are reported on the line of the keyword or of the array.
  const auto lineOf = [&tokens](std::string_view token) {
    return 1 + static_cast<std::size_t>(std::count(tokens.Text.data(), token.data(), '\n'));
  };
  const std::size_t line = lineOf(tokens.Text.substr(tokens.Pos));
  std::string_view name, token;
  long long arrays = 0;
  if (!tokens.Next(name) || name.size() > 255 || !tokens.Next(token) ||
    !ParseCount(token, arrays))
  {
    Fail(file, line, "FIELD block without a name and an array count ('FIELD name arrays')");
  }
  const std::string block = "FIELD block " + Quote(name);
  if (arrays > static_cast<long long>(tokens.Left()))
  {
    Fail(file, line,
      block + " announces " + std::to_string(arrays) + " arrays, more than the file can hold");
  }
  for (long long a = 0; a < arrays; ++a)
  {
    std::string_view array;
    if (!tokens.Next(array) || array.size() > 255)
    {
      Fail(file, line,
        block + ": the file ends before array " + std::to_string(a + 1) + " of " +
          std::to_string(arrays));
    }
    if (array == "NULL_ARRAY")
    {
      continue;
    }
    const std::size_t at = lineOf(array);
    const std::string what = block + ", array " + Quote(array);
    std::string_view fields[3];
    long long components = 0, tuples = 0;
    if (!tokens.Next(fields[0]) || !tokens.Next(fields[1]) || !tokens.Next(fields[2]) ||
      !ParseCount(fields[0], components) || !ParseCount(fields[1], tuples) || components == 0)
    {
      Fail(file, at, what + ": expected 'name components tuples type'");
    }
    const int size = LegacyValueSize(fields[2]);
    if (size == LegacyUnknown)
    {
      Fail(file, at, what + ": unknown type " + Quote(fields[2]));
    }
    // Every value takes at least a byte, or a bit.
    const unsigned long long room = tokens.Left() * (size == LegacyBit ? 8ULL : 1ULL);
    const auto values = static_cast<unsigned long long>(components);
    if (values > room || static_cast<unsigned long long>(tuples) > room / values)
    {
      Fail(file, at,
        what + ": " + std::to_string(components) + " x " + std::to_string(tuples) +
          " values, more than the file can hold");
    }
    if (!SkipLegacyValues(tokens, size, values * static_cast<unsigned long long>(tuples), binary))
    {
      Fail(file, at, what + ": the file ends inside its values (truncated?)");
    }
    tokens.SkipMetadata();
  }
}

// Skips the values of an array whose count `name` announced and whose type
// follows ("POINTS n type", "X_COORDINATES n type", "OFFSETS type"...);
// false if the file ends first or the type is unknown (VTK stops there).
bool SkipLegacyArray(
  LegacyTokens& tokens, unsigned long long count, unsigned long long perCount, bool binary)
{
  std::string_view type;
  const int size = tokens.Next(type) ? LegacyValueSize(type) : LegacyUnknown;
  if (size == LegacyUnknown || count > tokens.Left() || perCount * count > 8 * tokens.Left() ||
    !SkipLegacyValues(tokens, size, perCount * count, binary))
  {
    return false;
  }
  tokens.SkipMetadata();
  return true;
}

// Before version 5, a cell list is `size` ints, each cell its point count and
// its points; vtkCellArray::ImportLegacyFormat trusts the counts (reads past
// the list). Checks them where the values can be read (VTK stops at the first
// ASCII word that is not a number).
void CheckLegacyCells(LegacyTokens tokens, unsigned long long size, bool binary,
  const std::string& keyword, const std::string& file)
{
  const char* at = tokens.Text.data() + tokens.Pos;
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(tokens.Text.data(), at, '\n'));
  if (binary)
  {
    tokens.SkipLine();
  }
  long long left = 0; // points of the current cell still to come
  std::string_view token;
  for (unsigned long long i = 0; i < size; ++i)
  {
    long long value = 0;
    if (binary)
    {
      if (tokens.Left() < 4)
      {
        return;
      }
      std::uint32_t bits = 0; // big-endian
      for (int k = 0; k < 4; ++k)
      {
        bits = (bits << 8) | static_cast<unsigned char>(tokens.Text[tokens.Pos++]);
      }
      value = static_cast<std::int32_t>(bits);
    }
    else if (!tokens.Next(token) ||
      std::from_chars(token.data(), token.data() + token.size(), value).ec != std::errc())
    {
      return;
    }
    if (left > 0)
    {
      --left;
    }
    else if (value < 0 || static_cast<unsigned long long>(value) > size - i - 1)
    {
      Fail(file, line,
        Quote(keyword) + ": a cell of " + std::to_string(value) +
          " points runs past the end of the cell list (corrupt file?)");
    }
    else
    {
      left = value;
    }
  }
}

// Skips the data of a geometry keyword that announces counts, as VTK's legacy
// readers read it, so that binary values are not taken for keywords; false
// where it stops short (bad count, unknown type, end of the file).
bool SkipLegacyGeometry(LegacyTokens& tokens, const std::string& keyword, int majorVersion,
  bool binary, const std::string& file)
{
  std::string_view token;
  long long n = 0, size = 0;
  const bool coordinates =
    keyword.compare(0, 6, "points") == 0 || keyword.find("_coordinates") != std::string::npos;
  if (!tokens.Next(token))
  {
    return false;
  }
  // VTK reads the count with >>, which stops at the first letter: "12utf8_string"
  // is the count 12 and the type utf8_string (found by fuzzing).
  std::string_view glued;
  if (coordinates && !ParseCount(token, n))
  {
    const std::size_t digits = token.find_first_not_of("0123456789");
    if (digits > 0 && digits != std::string_view::npos)
    {
      glued = token.substr(digits);
    }
  }
  if (!glued.empty())
  {
    // falls through to the type check below with the glued type
  }
  else if (!ParseCount(token, n))
  {
    return false;
  }
  if (coordinates)
  {
    // VTK reads coordinates as a vtkDataArray: a string or variant array is
    // read, then dropped without being freed (a leak found by fuzzing).
    LegacyTokens peek = tokens;
    std::string_view type = glued;
    if (!type.empty() || peek.Next(type))
    {
      std::string lower(type);
      std::transform(lower.begin(), lower.end(), lower.begin(),
        [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      if (lower.compare(0, 6, "string") == 0 || lower.compare(0, 11, "utf8_string") == 0 ||
        lower.compare(0, 7, "variant") == 0)
      {
        const char* at = tokens.Text.data() + tokens.Pos;
        Fail(file, 1 + static_cast<std::size_t>(std::count(tokens.Text.data(), at, '\n')),
          "coordinates of type '" + std::string(type) + "': coordinates are numbers");
      }
    }
    if (!glued.empty())
    {
      return false; // a count VTK reads differently from here: stop the walk
    }
    return SkipLegacyArray(
      tokens, static_cast<unsigned long long>(n), keyword.compare(0, 6, "points") == 0 ? 3 : 1, binary);
  }
  if (keyword.compare(0, 10, "cell_types") == 0)
  {
    return SkipLegacyValues(tokens, 4, static_cast<unsigned long long>(n), binary);
  }
  // Cells: "KEYWORD n size", then (version 5 and later) OFFSETS and
  // CONNECTIVITY arrays of n and size values, or (before) size ints.
  if (!tokens.Next(token) || !ParseCount(token, size))
  {
    return false;
  }
  if (majorVersion < 5)
  {
    CheckLegacyCells(tokens, static_cast<unsigned long long>(size), binary, keyword, file);
    return SkipLegacyValues(tokens, 4, static_cast<unsigned long long>(size), binary);
  }
  return n < 1 ||
    (tokens.Next(token) && SkipLegacyArray(tokens, static_cast<unsigned long long>(n), 1, binary) &&
      tokens.Next(token) &&
      SkipLegacyArray(tokens, static_cast<unsigned long long>(size), 1, binary));
}

// Checks the FIELD blocks VTK reads before any POINT_DATA or CELL_DATA (those
// of the data set or data object; VTK checks the others), walking the
// geometry as VTK reads it. Keywords are matched as vtkDataReader does:
// case-insensitive prefixes.
void CheckLegacyFieldBlocks(const std::string& file, std::string_view text)
{
  // As vtkDataReader::ReadHeader: the version is "%d.%d" (0 otherwise), the
  // file type the first word of the third line.
  int major = 0, minor = 0;
  const std::string first(text.substr(0, std::min<std::size_t>(text.find('\n'), 255)));
  const char* version = first.c_str() + std::min<std::size_t>(first.size(), 22);
  if (std::sscanf(version, "%d.%d", &major, &minor) != 2)
  {
    major = 0;
  }
  std::size_t start = text.find('\n');
  start = start == std::string_view::npos ? text.size() : text.find('\n', start + 1);
  LegacyTokens tokens(text, start == std::string_view::npos ? text.size() : start + 1);
  std::string_view token;
  const bool binary = tokens.Next(token) && ToLower(token.substr(0, 6)) == "binary";
  static const char* const geometry[] = { "points", "x_coordinates", "y_coordinates",
    "z_coordinates", "vertices", "lines", "polygons", "triangle_strips", "cells", "cell_types" };
  while (tokens.Next(token))
  {
    const std::string keyword = ToLower(token.substr(0, 16));
    const auto is = [&keyword](const char* k) {
      return keyword.compare(0, std::strlen(k), k) == 0;
    };
    if (is("point_data") || is("cell_data"))
    {
      return;
    }
    if (is("metadata"))
    {
      tokens.Pos -= token.size();
      tokens.SkipMetadata();
    }
    else if (ToLower(token).find("field") != std::string::npos)
    {
      // Also after a number: `>>` reads "1" of "1field" as a value, then the
      // keyword "field" (the rest of the word).
      CheckFieldBlock(file, tokens, binary);
    }
    else if (std::any_of(std::begin(geometry), std::end(geometry), is))
    {
      // VTK's readers go on after most failures, from where they stopped.
      SkipLegacyGeometry(tokens, keyword, major, binary, file);
    }
  }
}

// vtkDataReader trusts the counts of a legacy file (a huge POINTS count makes
// it fail an allocation and abort, a negative one crashes it), so check them
// against the file size first: every value takes at least one byte. The version
// decides how cells are stored; an unreadable one makes it misread binary cells.
void CheckLegacyFile(const std::string& file, std::string_view text)
{
  const std::string_view magic = "# vtk DataFile Version ";
  const std::string_view first = text.substr(0, text.find('\n'));
  double version = 0;
  if (first.substr(0, magic.size()) != magic ||
    ParseNumber(Trim(first.substr(magic.size())), version) != Number::Ok ||
    !(version > 0 && version < 100))
  {
    Fail(file, 1, "not a legacy VTK file (the first line is not '# vtk DataFile Version x.y')");
  }
  // After each array VTK 9.2 peeks 256 bytes to skip blanks before a possible
  // METADATA line, and peeks the same bytes forever when all 256 are spaces or
  // carriage returns (found by fuzzing). Its writer never writes such a run.
  std::size_t blanks = 0;
  for (std::size_t i = 0; i < text.size(); ++i)
  {
    blanks = text[i] == ' ' || text[i] == '\r' ? blanks + 1 : 0;
    if (blanks == 256)
    {
      Fail(file, static_cast<std::size_t>(std::count(text.begin(), text.begin() + i, '\n')) + 1,
        "256 blanks in a row, which VTK's legacy reader cannot get past");
    }
  }
  static const char* const keywords[] = { "points", "cells", "polygons", "lines", "vertices",
    "triangle_strips", "cell_types", "point_data", "cell_data", "x_coordinates", "y_coordinates",
    "z_coordinates", "dimensions", "lookup_table", "color_scalars", "texture_coordinates", "field",
    "offsets", "connectivity" };
  const auto integer = [](std::string_view token, long long& value) {
    const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && ptr == token.data() + token.size();
  };
  const auto fits = [&text](long long count, long long factor) {
    return count >= 0 && count <= static_cast<long long>(text.size()) / factor;
  };
  std::size_t number = 0;
  std::vector<std::string_view> fields;
  for (std::size_t pos = 0; pos < text.size();)
  {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++number;
    SplitLoose(line, fields, 5);
    if (fields.empty())
    {
      continue;
    }
    const std::string keyword = ToLower(fields[0]);
    long long count = 0, tuples = 0;
    double ignored = 0;
    bool ok = true;
    // vtkDataReader matches keywords by prefix ("POINTSX" is POINTS).
    if (std::find_if(std::begin(keywords), std::end(keywords), [&keyword](const char* k) {
          return keyword.compare(0, std::strlen(k), k) == 0;
        }) != std::end(keywords))
    {
      for (std::size_t i = 1; i < fields.size(); ++i)
      {
        if (integer(fields[i], count))
        {
          ok = ok && fits(count, keyword == "points" ? 3 : 1);
        }
      }
    }
    else if (keyword == "data" && fields.size() > 1 && integer(fields[1], count))
    {
      // The length of a vector in an INFORMATION block (METADATA after an array):
      // VTK reserves room for it.
      ok = fits(count, 1);
    }
    else if (fields.size() == 4 && ParseNumber(fields[0], ignored) == Number::Invalid &&
      integer(fields[1], count) && integer(fields[2], tuples) &&
      std::isalpha(static_cast<unsigned char>(fields[3][0])))
    {
      // A field data array: "name components tuples type".
      ok = fits(count, 1) && fits(tuples, 1) && (count == 0 || fits(tuples, count));
    }
    if (!ok)
    {
      Fail(file, number,
        "invalid count in " + Quote(Trim(line)) + " (negative, or larger than the file)");
    }
  }
  CheckLegacyFieldBlocks(file, text);
}

// Strict base64: false on any character outside the alphabet (padding included).
bool DecodeBase64(std::string_view text, std::string& bytes)
{
  bytes.clear();
  unsigned int buffer = 0;
  int bits = 0;
  for (const char c : text)
  {
    const int v = c >= 'A' && c <= 'Z' ? c - 'A'
      : c >= 'a' && c <= 'z'           ? c - 'a' + 26
      : c >= '0' && c <= '9'           ? c - '0' + 52
      : c == '+'                       ? 62
      : c == '/'                       ? 63
                                       : -1;
    if (v < 0)
    {
      return false;
    }
    buffer = (buffer << 6) | static_cast<unsigned int>(v);
    bits += 6;
    if (bits >= 8)
    {
      bits -= 8;
      bytes += static_cast<char>((buffer >> bits) & 0xff);
    }
  }
  return true;
}

// The largest ratio of uncompressed to compressed bytes each of VTK's
// compressors reaches: LZ4 spends at least a byte per 255 bytes of a run,
// deflate 2 bits per 258 bytes; LZMA reaches about 7100 on zeros (measured;
// 16384 leaves room). 1 when the file is not compressed.
long long RatioOf(const std::string& compressor)
{
  return compressor.empty()                    ? 1
    : compressor == "vtkLZ4DataCompressor"  ? 255
    : compressor == "vtkZLibDataCompressor" ? 1032
                                            : 16384;
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

// The fewest bits a value of an XML data array takes in the file before
// compression: an ASCII value at least a character, a Bit value one bit.
int BitsPerValue(std::string_view type, std::string_view format)
{
  const std::size_t digits = type.find_first_of("123456789");
  return format == "ascii"             ? 8
    : type == "Bit"                    ? 1
    : digits == std::string_view::npos ? 8
                                       : std::atoi(type.data() + digits);
}

// The uncompressed size of a compression header (number of blocks, block size,
// last block size, 0 for a full one) against the bytes of values to be read.
std::string CheckUncompressedSize(unsigned long long blocks, unsigned long long blockSize,
  unsigned long long lastSize, unsigned long long needed)
{
  if (blocks == 0)
  {
    return needed > 0 ? "its compression header announces no block for " +
        std::to_string(needed) + " bytes of values"
      : lastSize > 0
      ? "its compression header announces no block but a last block of " +
        std::to_string(lastSize) + " bytes"
      : std::string();
  }
  // The blocks were checked against the file: no overflow.
  const unsigned long long total = (blocks - 1) * blockSize + (lastSize > 0 ? lastSize : blockSize);
  return total >= needed ? std::string()
                         : "its compression header announces " + std::to_string(total) +
      " bytes, fewer than its " + std::to_string(needed) + " bytes of values";
}

// The block header of a binary data array is its byte count or, compressed,
// (number of blocks, block size, last block size, compressed size of each
// block); vtkXMLDataParser allocates a table of "number of blocks" entries and
// a buffer of "block size" bytes from it unchecked. So each size must fit in
// the `available` bytes (base64: characters, 3 bytes per 4) that follow, and
// each block must not expand more than `ratio` times. read(n) gives the first
// n bytes or characters. The blocks must also hold the `needed` bytes of
// values that will be read: vtkXMLDataParser computes the uncompressed size
// as (blocks - 1) x block size + last block size, which wraps around with no
// block, and then reads a block that is not there. Returns the problem, or "".
template <class Read>
std::string CheckBlockHeader(const Read& read, long long available, bool base64, bool compressed,
  std::size_t wordSize, bool bigEndian, long long ratio, unsigned long long needed = 0)
{
  std::vector<unsigned long long> words;
  const auto decode = [&](std::size_t count) {
    const std::size_t bytes = count * wordSize;
    std::string chunk = read(base64 ? 4 * ((bytes + 2) / 3) : bytes);
    if (base64)
    {
      std::string decoded;
      chunk.erase(chunk.find_last_not_of('=') + 1);
      if (!DecodeBase64(chunk, decoded))
      {
        return false;
      }
      chunk.swap(decoded);
    }
    if (chunk.size() < bytes)
    {
      return false;
    }
    words.assign(count, 0);
    for (std::size_t w = 0; w < bytes; ++w)
    {
      const std::size_t byte =
        w - w % wordSize + (bigEndian ? w % wordSize : wordSize - 1 - w % wordSize);
      words[w / wordSize] = (words[w / wordSize] << 8) | static_cast<unsigned char>(chunk[byte]);
    }
    return true;
  };
  // Bytes the file holds after a header of `count` words.
  const auto after = [&](std::size_t count) {
    const long long bytes = base64 ? available / 4 * 3 : available;
    return static_cast<unsigned long long>(
      std::max(0LL, bytes - static_cast<long long>(count * wordSize)));
  };
  if (!compressed)
  {
    if (!decode(1))
    {
      return "truncated block header";
    }
    return words[0] <= after(1)
      ? std::string()
      : "its header announces " + std::to_string(words[0]) + " bytes, more than the file holds";
  }
  if (!decode(3) || words[0] > after(3) / wordSize || words[2] > words[1] ||
    !decode(3 + static_cast<std::size_t>(words[0])))
  {
    return "corrupt compression header";
  }
  const std::size_t blocks = words.size() - 3;
  const unsigned long long room = after(3 + blocks);
  unsigned long long total = 0;
  for (std::size_t b = 0; b < blocks; ++b)
  {
    const unsigned long long packed = words[3 + b];
    const unsigned long long unpacked = b + 1 == blocks && words[2] > 0 ? words[2] : words[1];
    total += packed;
    if (packed > room || total > room || unpacked > packed * static_cast<unsigned long long>(ratio))
    {
      return "its compression header announces " + std::to_string(unpacked) + " bytes from " +
        std::to_string(packed) + " compressed bytes, which this file cannot hold";
    }
  }
  return CheckUncompressedSize(words[0], words[1], words[2], needed);
}

void CheckParsedXml(const std::string& file, std::string_view text, long long limit);

// vtkXMLReader aborts the process when an allocation fails and loops on absurd
// component counts, so the counts in the XML header (and in the files a .vtm or
// .pvt* refers to) are checked against the file size first: the arrays cannot
// declare more bytes than the file holds times the compressor's best ratio (an
// ASCII value takes at least one character).
void CheckXmlCounts(const std::string& file, int depth = 0)
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

// Collects the messages VTK sends to its output window while installed, so a
// failing VTK reader does not print its multi-line reports. (Messages VTK's
// logger prints to stderr are up to the application: the flowrecon tool turns
// that off.)
class MessageCapture : public vtkOutputWindow
{
public:
  static MessageCapture* New();
  vtkTypeMacro(MessageCapture, vtkOutputWindow);
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char* text) override
  {
    this->Keep(text);
    // VTK built without NDEBUG (Debian's is) aborts after this message when an
    // array cannot be allocated; throw what its release builds throw instead.
    if (text && std::strstr(text, "Unable to allocate "))
    {
      throw std::bad_alloc();
    }
  }
  void DisplayWarningText(const char* text) override { this->Keep(text); }
  void DisplayGenericWarningText(const char* text) override { this->Keep(text); }
  void DisplayDebugText(const char*) override {}

  // The first message, reduced to its text: "ERROR: In file, line N" and the
  // "vtkClass (0x...): " prefix are dropped.
  std::string First;

private:
  void Keep(const char* text)
  {
    if (!this->First.empty() || !text)
    {
      return;
    }
    std::string_view t(text);
    if (t.substr(0, 4) == "ERRO" || t.substr(0, 4) == "Warn" || t.substr(0, 4) == "Gene")
    {
      const std::size_t newline = t.find('\n');
      t = newline == std::string_view::npos ? std::string_view() : t.substr(newline + 1);
    }
    const std::size_t object = t.find(" (0x");
    const std::size_t colon = t.find("): ");
    if (object != std::string_view::npos && colon != std::string_view::npos && object < colon &&
      t.substr(0, object).find_first_of(" \n") == std::string_view::npos)
    {
      t.remove_prefix(colon + 3);
    }
    t = Trim(t.substr(0, t.find('\n')));
    // The detail goes into a one-line message: no control or non-ASCII bytes.
    this->First = t.empty() ? "unknown error" : std::string(t.substr(0, 200));
    for (char& c : this->First)
    {
      c = (c < 0x20 || c > 0x7e) ? '?' : c;
    }
  }
};
vtkStandardNewMacro(MessageCapture);

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
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkNew<MessageCapture> capture;
  vtkOutputWindow::SetInstance(capture);
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
  try
  {
    check();
  }
  catch (...)
  {
    vtkOutputWindow::SetInstance(previous);
    throw;
  }
  vtkOutputWindow::SetInstance(previous);
}

// Runs a VTK reader with a MessageCapture as the output window; fails with
// "FILE: cannot read KIND file (first VTK message)" on any error or warning.
void UpdateCaptured(const std::string& file, vtkAlgorithm* reader, const char* kind)
{
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkNew<MessageCapture> capture;
  vtkOutputWindow::SetInstance(capture);
  int ok = 0;
  try
  {
    ok = reader->GetExecutive()->Update();
  }
  catch (...)
  {
    vtkOutputWindow::SetInstance(previous);
    throw;
  }
  vtkOutputWindow::SetInstance(previous);
  if (!ok || reader->GetErrorCode() != 0 || !capture->First.empty() ||
    !reader->GetOutputDataObject(0))
  {
    Fail(file, 0,
      std::string("cannot read ") + kind + " file" +
        (capture->First.empty() ? std::string() : " (" + capture->First + ")"));
  }
}

// Appends the points of a data set or of every leaf of a composite data set;
// the point data arrays all leaves share go to `pointData`.
void ExtractPoints(
  const std::string& file, vtkDataObject* data, std::vector<double>& xyz, vtkPointData* pointData)
{
  std::vector<vtkDataSet*> leaves;
  if (auto* dataSet = vtkDataSet::SafeDownCast(data))
  {
    leaves.push_back(dataSet);
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
      if (leaf && leaf->GetNumberOfPoints() > 0)
      {
        leaves.push_back(leaf);
      }
    }
  }
  else
  {
    Fail(file, 0, std::string("holds a ") + data->GetClassName() + ", not a data set with points");
  }
  vtkIdType total = 0;
  vtkDataSetAttributes::FieldList arrays(static_cast<int>(leaves.size()));
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    total += leaves[i]->GetNumberOfPoints();
    if (i == 0)
    {
      arrays.InitializeFieldList(leaves[i]->GetPointData());
    }
    else
    {
      arrays.IntersectFieldList(leaves[i]->GetPointData());
    }
  }
  // Image and rectilinear grids have implicit points: bound them before allocating.
  constexpr vtkIdType maximumPoints = vtkIdType(1) << 30;
  if (total > maximumPoints)
  {
    Fail(file, 0, "too many points (" + std::to_string(total) + ")");
  }
  // Below that bound an image of 10^9 implicit points still asks for 24 GB
  // that no file size bounds: ask the memory guard (3 doubles a point and as
  // much again for the point data, a generous guess).
  try
  {
    flowrecon::RequireMemory(48.0 * static_cast<double>(total),
      "reading " + std::to_string(total) + " points", "use a smaller or subsampled file");
  }
  catch (const flowrecon::InputError& e)
  {
    Fail(file, 0, e.what());
  }
  xyz.reserve(3 * static_cast<std::size_t>(total));
  pointData->CopyAllocate(arrays, total);
  vtkIdType next = 0;
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    vtkDataSet* leaf = leaves[i];
    const vtkIdType n = leaf->GetNumberOfPoints();
    for (vtkIdType id = 0; id < n; ++id)
    {
      double p[3];
      leaf->GetPoint(id, p);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        Fail(file, 0, "point " + std::to_string(next + id) + " has a non-finite coordinate");
      }
      xyz.insert(xyz.end(), p, p + 3);
    }
    pointData->CopyData(arrays, leaf->GetPointData(), static_cast<int>(i), next, n, 0);
    next += n;
  }
}

void ReadWithVtk(
  const std::string& file, Format format, std::vector<double>& xyz, vtkPointData* pointData)
{
  if (format == Format::LegacyVtk)
  {
    CheckLegacyFile(file, ReadWholeFile(file));
    auto reader = vtkSmartPointer<vtkGenericDataObjectReader>::New();
    reader->SetFileName(file.c_str());
    // Every array, not only the first scalars/vectors.
    reader->ReadAllScalarsOn();
    reader->ReadAllVectorsOn();
    reader->ReadAllNormalsOn();
    reader->ReadAllTensorsOn();
    reader->ReadAllColorScalarsOn();
    reader->ReadAllTCoordsOn();
    reader->ReadAllFieldsOn();
    UpdateCaptured(file, reader, "legacy VTK");
    ExtractPoints(file, reader->GetOutputDataObject(0), xyz, pointData);
  }
  else
  {
    CheckXmlCounts(file);
    auto reader = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
    reader->SetFileName(file.c_str());
    UpdateCaptured(file, reader, "VTK XML");
    ExtractPoints(file, reader->GetOutputDataObject(0), xyz, pointData);
  }
}

const char* const SupportedExtensions =
  ".xyz .txt .pts .csv .off .ply .obj .vtk .vtp .vtu .vts .vtr .vti .vtm .vthb .pvtp .pvtu "
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
    case Format::Pts:
      ReadXyz(file, ReadWholeFile(file), format == Format::Pts, xyz);
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
    default:
      ReadWithVtk(file, format, xyz, pointData);
      break;
  }
  if (xyz.empty())
  {
    Fail(file, 0, "no points found");
  }
}

} // namespace

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
  return fileName && FormatOf(Extension(fileName)) != Format::Unknown;
}

//------------------------------------------------------------------------------
int vtkPointCloudReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->ErrorMessage.clear();
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  // The whole cloud goes to piece 0; other pieces (parallel runs) stay empty.
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
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
      throw ReadError("no file name given");
    }
    ReadCloud(file, xyz, pointData);
  }
  catch (const ReadError& e)
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
