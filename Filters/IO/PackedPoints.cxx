// Points and point data as bytes (see PackedPoints.h), in this machine's byte
// order: the child and its parent are the same program.
#include "PackedPoints.h"

#include "PointCloudParsing.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkVariantArray.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace flowrecon
{
namespace reader
{
namespace
{

struct Packer
{
  std::string Bytes;
  template <class T>
  void Put(T value)
  {
    this->Bytes.append(reinterpret_cast<const char*>(&value), sizeof(value));
  }
  void PutText(const std::string& text) // NUL bytes included
  {
    this->Put<std::int64_t>(static_cast<std::int64_t>(text.size()));
    this->Bytes.append(text);
  }
  void PutText(const char* text) // length -1 for none
  {
    text ? this->PutText(std::string(text)) : this->Put<std::int64_t>(-1);
  }
};

struct Unpacker
{
  const std::string& File;
  const std::string& Bytes;
  std::size_t At = 0;
  const char* Take(std::uint64_t n)
  {
    if (n > this->Bytes.size() - this->At)
    {
      Fail(this->File, 0, "the reader's child process sent garbled points");
    }
    this->At += static_cast<std::size_t>(n);
    return this->Bytes.data() + this->At - n;
  }
  template <class T>
  T Get()
  {
    T value;
    std::memcpy(&value, this->Take(sizeof(T)), sizeof(T));
    return value;
  }
  bool GetText(std::string& text)
  {
    const auto n = this->Get<std::int64_t>();
    text = n < 0 ? std::string() : std::string(this->Take(static_cast<std::uint64_t>(n)), n);
    return n >= 0;
  }
};

// A variant as its kind of value ('s'tring, 'd'ouble, 'i'nt64, 'u'int64, 'n'one)
// and its type, which restores it exactly.
void PutVariant(Packer& out, const vtkVariant& v)
{
  const unsigned type = v.GetType();
  const bool isUnsigned = type == VTK_UNSIGNED_CHAR || type == VTK_UNSIGNED_SHORT ||
    type == VTK_UNSIGNED_INT || type == VTK_UNSIGNED_LONG || type == VTK_UNSIGNED_LONG_LONG;
  const char kind = v.IsString()  ? 's'
    : v.IsFloat() || v.IsDouble() ? 'd'
    : !v.IsNumeric()              ? 'n'
    : isUnsigned                  ? 'u'
                                  : 'i';
  out.Put(kind);
  out.Put(type);
  kind == 's'     ? out.PutText(v.ToString())
    : kind == 'd' ? out.Put(v.ToDouble())
    : kind == 'u' ? out.Put(v.ToTypeUInt64())
    : kind == 'i' ? out.Put(v.ToTypeInt64())
                  : void();
}

vtkVariant GetVariant(Unpacker& in)
{
  const char kind = in.Get<char>();
  const unsigned type = in.Get<unsigned>();
  std::string text;
  const vtkVariant value = kind == 's' ? (in.GetText(text), vtkVariant(text))
    : kind == 'd'                      ? vtkVariant(in.Get<double>())
    : kind == 'u'                      ? vtkVariant(in.Get<vtkTypeUInt64>())
    : kind == 'i'                      ? vtkVariant(in.Get<vtkTypeInt64>())
                                       : vtkVariant();
  return kind == 'n' ? value : vtkVariant(value, type);
}

} // namespace

std::string PackPoints(const std::vector<double>& xyz, vtkPointData* pointData)
{
  Packer out;
  out.Put<std::uint64_t>(xyz.size());
  out.Bytes.append(reinterpret_cast<const char*>(xyz.data()), xyz.size() * sizeof(double));
  out.Put<std::int32_t>(pointData->GetNumberOfArrays());
  for (int i = 0; i < pointData->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* array = pointData->GetAbstractArray(i);
    std::int32_t roles = 0; // the attributes (scalars, normals...) it is
    for (int a = 0; a < vtkDataSetAttributes::NUM_ATTRIBUTES; ++a)
    {
      roles |= pointData->GetAbstractAttribute(a) == array ? 1 << a : 0;
    }
    out.Put<std::int32_t>(array->GetDataType());
    out.Put<std::int32_t>(roles);
    out.Put<std::int32_t>(array->GetNumberOfComponents());
    out.Put<std::int64_t>(array->GetNumberOfTuples());
    out.PutText(array->GetName());
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      out.PutText(array->GetComponentName(c));
    }
    const vtkIdType values = array->GetNumberOfValues();
    if (auto* strings = vtkStringArray::SafeDownCast(array))
    {
      for (vtkIdType v = 0; v < values; ++v)
      {
        out.PutText(strings->GetValue(v));
      }
    }
    else if (auto* variants = vtkVariantArray::SafeDownCast(array))
    {
      for (vtkIdType v = 0; v < values; ++v)
      {
        PutVariant(out, variants->GetValue(v));
      }
    }
    else if (values > 0) // a vtkDataArray, bits packed
    {
      const std::size_t bytes = array->GetDataType() == VTK_BIT
        ? static_cast<std::size_t>(values + 7) / 8
        : static_cast<std::size_t>(values) * static_cast<std::size_t>(array->GetDataTypeSize());
      out.Bytes.append(static_cast<const char*>(array->GetVoidPointer(0)), bytes);
    }
  }
  return std::move(out.Bytes);
}

void UnpackPoints(const std::string& file, const std::string& bytes, std::vector<double>& xyz,
  vtkPointData* pointData)
{
  Unpacker in{ file, bytes };
  const auto coordinates = in.Get<std::uint64_t>();
  const char* values = in.Take(std::min<std::uint64_t>(coordinates, bytes.size()) * sizeof(double));
  xyz.resize(static_cast<std::size_t>(coordinates));
  if (!xyz.empty())
  {
    std::memcpy(xyz.data(), values, xyz.size() * sizeof(double));
  }
  const auto arrays = in.Get<std::int32_t>();
  for (std::int32_t i = 0; i < arrays; ++i)
  {
    const auto type = in.Get<std::int32_t>();
    const auto roles = in.Get<std::int32_t>();
    const auto components = in.Get<std::int32_t>();
    const auto tuples = in.Get<std::int64_t>();
    vtkSmartPointer<vtkAbstractArray> array;
    array.TakeReference(vtkAbstractArray::CreateArray(type));
    // Every value takes a bit at least.
    if (!array || components < 1 || tuples < 0 ||
      static_cast<std::uint64_t>(tuples) / 8 > (bytes.size() - in.At) / components)
    {
      Fail(file, 0, "the reader's child process sent garbled points");
    }
    std::string text;
    array->SetNumberOfComponents(components);
    array->SetName(in.GetText(text) ? text.c_str() : nullptr);
    for (int c = 0; c < components; ++c)
    {
      if (in.GetText(text))
      {
        array->SetComponentName(c, text.c_str());
      }
    }
    array->SetNumberOfTuples(tuples);
    const vtkIdType count = array->GetNumberOfValues();
    if (auto* strings = vtkStringArray::SafeDownCast(array))
    {
      for (vtkIdType v = 0; v < count; ++v)
      {
        in.GetText(text);
        strings->SetValue(v, text);
      }
    }
    else if (auto* variants = vtkVariantArray::SafeDownCast(array))
    {
      for (vtkIdType v = 0; v < count; ++v)
      {
        variants->SetValue(v, GetVariant(in));
      }
    }
    else if (count > 0)
    {
      const std::uint64_t size = type == VTK_BIT
        ? static_cast<std::uint64_t>(count + 7) / 8
        : static_cast<std::uint64_t>(count) * static_cast<std::uint64_t>(array->GetDataTypeSize());
      std::memcpy(array->GetVoidPointer(0), in.Take(size), static_cast<std::size_t>(size));
    }
    const int index = pointData->AddArray(array);
    for (int a = 0; a < vtkDataSetAttributes::NUM_ATTRIBUTES; ++a)
    {
      if (roles & (1 << a))
      {
        pointData->SetActiveAttribute(index, a);
      }
    }
  }
}

} // namespace reader
} // namespace flowrecon
