// The LAS header and point records of vtkPointCloudReader (see LasPoints.h).
// Offsets are those of the ASPRS LAS 1.4 specification's public header block,
// whose first 227 bytes every version shares.
#include "LasPoints.h"

#include "PointCloudParsing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace flowrecon
{
namespace reader
{
namespace
{

constexpr std::size_t HeaderSize = 94;         // uint16: the public header's size
constexpr std::size_t PointOffset = 96;        // uint32: where the records start
constexpr std::size_t PointFormat = 104;       // uint8; bit 7 (or 6) set: LAZ
constexpr std::size_t RecordLength = 105;      // uint16
constexpr std::size_t LegacyCount = 107;       // uint32
constexpr std::size_t Scales = 131;            // 3 doubles, then 3 offsets
constexpr std::size_t Offsets = 155;
constexpr std::size_t Count64 = 247;           // uint64, LAS 1.4
constexpr std::size_t SharedHeaderBytes = 227; // versions 1.0-1.2
constexpr std::size_t Header14Bytes = 375;

/// The shortest record of each point format (LAS 1.4, table of point formats).
constexpr unsigned MinimumRecord[11] = { 20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67 };

} // namespace

void ReadLas(const std::string& file, std::string_view bytes, std::vector<double>& xyz)
{
  if (bytes.size() < 4 || bytes.substr(0, 4) != "LASF")
  {
    Fail(file, 0, "not a LAS file (it does not start with 'LASF')");
  }
  if (bytes.size() < SharedHeaderBytes)
  {
    Fail(file, 0,
      "the LAS header needs " + std::to_string(SharedHeaderBytes) + " bytes, the file has " +
        std::to_string(bytes.size()) + " (truncated)");
  }
  const int major = static_cast<unsigned char>(bytes[24]);
  const int minor = static_cast<unsigned char>(bytes[25]);
  const std::string version = std::to_string(major) + "." + std::to_string(minor);
  if (major != 1 || minor > 4)
  {
    Fail(file, 0, "LAS version " + version + " is not supported (1.0 to 1.4 are)");
  }
  const std::uint64_t headerSize = LittleEndianAt<std::uint16_t>(bytes, HeaderSize);
  const std::uint64_t start = LittleEndianAt<std::uint32_t>(bytes, PointOffset);
  const unsigned format = static_cast<unsigned char>(bytes[PointFormat]);
  const std::uint64_t length = LittleEndianAt<std::uint16_t>(bytes, RecordLength);
  if (format & 0xC0)
  {
    Fail(file, 0,
      "compressed LAS (LAZ) is not supported: decompress it first (laszip, pdal translate)");
  }
  if (format > 10)
  {
    Fail(file, 0, "unknown LAS point format " + std::to_string(format) + " (0 to 10 are defined)");
  }
  if (length < MinimumRecord[format])
  {
    Fail(file, 0,
      "LAS point format " + std::to_string(format) + " needs records of at least " +
        std::to_string(MinimumRecord[format]) + " bytes, the header says " + std::to_string(length));
  }
  std::uint64_t count = LittleEndianAt<std::uint32_t>(bytes, LegacyCount);
  // LAS 1.4 keeps a 64-bit count; the legacy one is 0 beyond 2^32 points or
  // for the formats 6-10 (and some writers leave the new one 0).
  if (minor >= 4 && headerSize >= Header14Bytes && bytes.size() >= Header14Bytes)
  {
    const std::uint64_t count64 = LittleEndianAt<std::uint64_t>(bytes, Count64);
    if (count == 0 || count64 == 0 || count == count64)
    {
      count = std::max(count, count64);
    }
    else
    {
      Fail(file, 0,
        "the LAS header holds two point counts, " + std::to_string(count) + " and " +
          std::to_string(count64));
    }
  }
  if (headerSize < SharedHeaderBytes || start < headerSize)
  {
    Fail(file, 0,
      "the LAS header says its size is " + std::to_string(headerSize) +
        " bytes and the points start at byte " + std::to_string(start));
  }
  // Never trust a count for an allocation: the records must be in the file.
  if (start > bytes.size() || count > (bytes.size() - start) / length)
  {
    Fail(file, 0,
      std::to_string(count) + " points of " + std::to_string(length) + " bytes from byte " +
        std::to_string(start) + " need more than the file's " + std::to_string(bytes.size()) +
        " bytes (truncated)");
  }
  double scale[3], offset[3];
  for (int k = 0; k < 3; ++k)
  {
    scale[k] = LittleEndianAt<double>(bytes, Scales + 8 * static_cast<std::size_t>(k));
    offset[k] = LittleEndianAt<double>(bytes, Offsets + 8 * static_cast<std::size_t>(k));
    if (!std::isfinite(scale[k]) || scale[k] == 0 || !std::isfinite(offset[k]))
    {
      Fail(file, 0,
        std::string("the LAS header's ") + AxisName[k] + " scale " + std::to_string(scale[k]) +
          " and offset " + std::to_string(offset[k]) + " do not make coordinates");
    }
  }
  xyz.reserve(xyz.size() + 3 * static_cast<std::size_t>(count));
  for (std::uint64_t i = 0; i < count; ++i)
  {
    const std::size_t at = static_cast<std::size_t>(start + i * length);
    for (int k = 0; k < 3; ++k)
    {
      const auto raw = LittleEndianAt<std::int32_t>(bytes, at + 4 * static_cast<std::size_t>(k));
      const double c = static_cast<double>(raw) * scale[k] + offset[k];
      if (!std::isfinite(c))
      {
        Fail(file, 0,
          "point " + std::to_string(i + 1) + ": " + AxisName[k] +
            " coordinate out of the range of doubles (the header's scale and offset)");
      }
      xyz.push_back(c);
    }
  }
}

} // namespace reader
} // namespace flowrecon
