// The STL grammar of vtkPointCloudReader (see StlPoints.h) on top of
// PointCloudParsing's lines and numbers.
#include "StlPoints.h"

#include "PointCloudParsing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace flowrecon
{
namespace reader
{
namespace
{

constexpr std::uint64_t HeaderBytes = 84;   // 80 free bytes, then the triangle count
constexpr std::uint64_t TriangleBytes = 50; // normal, 3 vertices (12 floats), 2 attribute bytes

/// "solid" as the first word (after a byte order mark and blanks).
bool StartsWithSolid(std::string_view text)
{
  if (text.substr(0, 3) == "\xEF\xBB\xBF")
  {
    text.remove_prefix(3);
  }
  const std::size_t start = text.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos || Lower(text.substr(start, 5)) != "solid")
  {
    return false;
  }
  return start + 5 == text.size() || IsBlank(text[start + 5]) || text[start + 5] == '\n';
}

/// Control bytes other than blanks and line ends: a binary file.
bool IsBinary(std::string_view text)
{
  return std::any_of(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) < 0x20 && !IsBlank(c) && c != '\n') || c == '\x7f';
  });
}

void ReadBinary(const std::string& file, std::string_view text, std::uint32_t triangles,
  std::vector<double>& all)
{
  all.reserve(9 * static_cast<std::size_t>(triangles));
  for (std::uint32_t t = 0; t < triangles; ++t)
  {
    // Skip the normal: only the vertices are points.
    const std::size_t vertex = HeaderBytes + TriangleBytes * t + 12;
    for (int v = 0; v < 3; ++v)
    {
      for (int k = 0; k < 3; ++k)
      {
        const float c = LittleEndianAt<float>(text, vertex + 12 * v + 4 * k);
        if (!std::isfinite(c))
        {
          Fail(file, 0,
            "triangle " + std::to_string(t + 1) + ", vertex " + std::to_string(v + 1) +
              ": non-finite " + AxisName[k] + " coordinate");
        }
        all.push_back(static_cast<double>(c));
      }
    }
  }
}

void ReadAscii(const std::string& file, std::string_view text, std::vector<double>& all)
{
  // solid name / facet normal n n n / outer loop / vertex x y z (3) / endloop /
  // endfacet ... / endsolid name; a file may hold several solids.
  enum class State
  {
    Outside,
    Solid,
    Facet,
    Loop,
    LoopDone
  };
  State state = State::Outside;
  int vertices = 0;
  Lines lines(file, text);
  std::string_view line;
  std::vector<std::string_view> fields;
  const auto expected = [&](const char* what) {
    Fail(file, lines.Number, std::string("expected ") + what + ", found " + Quote(Trim(line)));
  };
  while (lines.NextData(line))
  {
    SplitLoose(line, fields, std::string_view::npos);
    const std::string keyword = fields.empty() ? std::string() : Lower(fields[0]);
    switch (state)
    {
      case State::Outside:
        if (keyword != "solid")
        {
          expected("'solid' (or the end of the file after 'endsolid')");
        }
        state = State::Solid;
        break;
      case State::Solid:
        if (keyword == "facet")
        {
          state = State::Facet;
        }
        else if (keyword == "endsolid")
        {
          state = State::Outside;
        }
        else
        {
          expected("'facet' or 'endsolid'");
        }
        break;
      case State::Facet:
        if (keyword != "outer" || fields.size() != 2 || Lower(fields[1]) != "loop")
        {
          expected("'outer loop'");
        }
        state = State::Loop;
        vertices = 0;
        break;
      case State::Loop:
        if (keyword == "vertex")
        {
          if (fields.size() != 4)
          {
            Fail(file, lines.Number,
              "expected 3 coordinates after 'vertex', found " + std::to_string(fields.size() - 1));
          }
          for (int k = 0; k < 3; ++k)
          {
            all.push_back(
              Coordinate(file, lines.Number, fields[1 + k], std::string(AxisName[k]) + " coordinate"));
          }
          ++vertices;
        }
        else if (keyword == "endloop")
        {
          if (vertices != 3)
          {
            Fail(file, lines.Number,
              "a facet with " + std::to_string(vertices) + " vertices (STL facets are triangles)");
          }
          state = State::LoopDone;
        }
        else
        {
          expected("'vertex' or 'endloop'");
        }
        break;
      case State::LoopDone:
        if (keyword != "endfacet")
        {
          expected("'endfacet'");
        }
        state = State::Solid;
        break;
    }
  }
  if (state != State::Outside)
  {
    Fail(file, lines.Number, "file ends inside a solid (no 'endsolid'): truncated");
  }
}

/// The points of `all` (x, y, z each) that no earlier point equals, in order.
void AppendDistinct(const std::vector<double>& all, std::vector<double>& xyz)
{
  const std::size_t n = all.size() / 3;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  const auto point = [&all](std::size_t i) {
    return std::array<double, 3>{ { all[3 * i], all[3 * i + 1], all[3 * i + 2] } };
  };
  // Stable: among equal points the first one comes first.
  std::stable_sort(order.begin(), order.end(),
    [&](std::size_t a, std::size_t b) { return point(a) < point(b); });
  std::vector<char> first(n, 0);
  for (std::size_t k = 0; k < n; ++k)
  {
    first[order[k]] = k == 0 || point(order[k - 1]) < point(order[k]) ? 1 : 0;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (first[i])
    {
      xyz.insert(xyz.end(), all.begin() + 3 * i, all.begin() + 3 * i + 3);
    }
  }
}

} // namespace

void ReadStl(const std::string& file, std::string_view text, std::vector<double>& xyz)
{
  const std::uint64_t size = text.size();
  const std::uint32_t announced = size >= HeaderBytes ? LittleEndianAt<std::uint32_t>(text, 80) : 0;
  std::vector<double> all;
  // Many binary files start with "solid" too: the size decides first.
  if (size >= HeaderBytes && size == HeaderBytes + TriangleBytes * announced)
  {
    ReadBinary(file, text, announced, all);
  }
  else if (StartsWithSolid(text) && !(size >= HeaderBytes && IsBinary(text)))
  {
    ReadAscii(file, text, all);
  }
  else if (size >= HeaderBytes)
  {
    Fail(file, 0,
      "binary STL: " + std::to_string(announced) + " triangles announced take " +
        std::to_string(HeaderBytes + TriangleBytes * announced) + " bytes, the file has " +
        std::to_string(size) + " (truncated, or not an STL file)");
  }
  else
  {
    Fail(file, 0, "not an STL file: no 'solid' keyword, and too short for a binary header");
  }
  AppendDistinct(all, xyz);
}

} // namespace reader
} // namespace flowrecon
