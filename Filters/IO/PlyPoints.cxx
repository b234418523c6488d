// The vertex element of a PLY file (see PlyPoints.h): header, ASCII and binary
// values (either byte order), and the grouping of normals and colours.
#include "PlyPoints.h"

#include "PointCloudParsing.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace flowrecon
{
namespace reader
{
namespace
{

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
  switch (type) // one of PlyType's
  {
    vtkTemplateMacro(value = Load<VTK_TT>(bytes));
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

struct PlyHeader
{
  std::string Format;
  std::vector<PlyElement> Elements;
};

// The header, up to end_header; `lines` is left at the data.
PlyHeader ReadPlyHeader(const std::string& file, Lines& lines)
{
  std::string_view line;
  std::vector<std::string_view> fields;
  if (!lines.Next(line) || Trim(line) != "ply")
  {
    Fail(file, 0, "not a PLY file (it does not start with 'ply')");
  }
  PlyHeader header;
  std::vector<PlyElement>& elements = header.Elements;
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
      header.Format = fields[1];
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
  if (header.Format.empty())
  {
    Fail(file, 0, "the PLY header has no format line");
  }
  return header;
}

// Which vertex properties are x, y and z; refuses a count the data cannot hold,
// so that nothing is allocated for it.
std::array<int, 3> VertexAxes(
  const std::string& file, const PlyHeader& header, const PlyElement& vertex, std::size_t dataBytes)
{
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
    minimumBytes += header.Format == "ascii"
      ? 2
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
  if (vertex.Count > 0 && static_cast<unsigned long long>(vertex.Count) > dataBytes / minimumBytes)
  {
    Fail(file, 0,
      "the PLY header announces " + std::to_string(vertex.Count) + " vertices but only " +
        std::to_string(dataBytes) + " bytes of data follow (truncated?)");
  }
  return axis;
}

// One point data array per scalar vertex property other than x, y, z.
std::vector<vtkSmartPointer<vtkDataArray>> VertexArrays(
  const PlyElement& vertex, const std::array<int, 3>& axis)
{
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
  return arrays;
}

// The elements' values up to the vertices' end: coordinates to xyz, the other
// scalar properties to their arrays.
void ReadVertices(const std::string& file, const PlyHeader& header, const PlyElement& vertex,
  const std::array<int, 3>& axis, PlyCursor& cursor, std::vector<double>& xyz,
  std::vector<vtkSmartPointer<vtkDataArray>>& arrays)
{
  xyz.reserve(3 * static_cast<std::size_t>(vertex.Count));
  std::vector<double> values(vertex.Properties.size());
  for (const PlyElement& element : header.Elements)
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
}

} // namespace

void ReadPly(
  const std::string& file, std::string_view text, std::vector<double>& xyz, vtkPointData* pointData)
{
  Lines lines(file, text);
  const PlyHeader header = ReadPlyHeader(file, lines);
  const auto vertex = std::find_if(header.Elements.begin(), header.Elements.end(),
    [](const PlyElement& e) { return e.Name == "vertex"; });
  if (vertex == header.Elements.end())
  {
    Fail(file, 0, "the PLY file has no vertex element");
  }
  const std::array<int, 3> axis = VertexAxes(file, header, *vertex, text.size() - lines.Offset());
  std::vector<vtkSmartPointer<vtkDataArray>> arrays = VertexArrays(*vertex, axis);
  PlyCursor cursor(file, lines, text, header.Format);
  ReadVertices(file, header, *vertex, axis, cursor, xyz, arrays);
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

} // namespace reader
} // namespace flowrecon
