// The text formats of vtkPointCloudReader (see PointCloudTextFormats.h): the
// grammar of each format on top of PointCloudParsing's lines and numbers.
#include "PointCloudTextFormats.h"

#include "PointCloudParsing.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <exception>

namespace flowrecon
{
namespace reader
{
namespace
{

// Appends the point of the fields from `first` on (SplitLoose keeps first + 3 at most),
// each coordinate checked in turn; too few fields fail with "EXPECTED, found N".
void AppendPoint(const std::string& file, std::size_t line,
  const std::vector<std::string_view>& fields, std::size_t first, const std::string& expected,
  std::vector<double>& xyz)
{
  double p[3];
  for (std::size_t k = first; k < fields.size(); ++k)
  {
    p[k - first] =
      Coordinate(file, line, fields[k], std::string(AxisName[k - first]) + " coordinate");
  }
  if (fields.size() < first + 3)
  {
    Fail(file, line, expected + ", found " + std::to_string(fields.size() - first));
  }
  xyz.insert(xyz.end(), p, p + 3);
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
  const std::string n = Lower(name);
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

/// A whole number without its leading zeros ("0" stays).
std::string TrimZeros(std::string_view digits)
{
  const std::size_t nonzero = digits.find_first_not_of('0');
  return nonzero == std::string_view::npos ? "0" : std::string(digits.substr(nonzero));
}

} // namespace

namespace
{

constexpr const char* XyzExpected = "expected 3 coordinates (x y z)";

/// The points of `rest` (whole lines, after the first point), parsed in
/// parallel chunks split at line ends and appended in order. False, with
/// `xyz` unchanged, when a chunk fails: the caller then reads on line by line,
/// which names the line. Parsing is most of reading a large cloud (0.5 s for
/// 10^6 points).
bool ReadXyzInParallel(const std::string& file, std::string_view rest, std::vector<double>& xyz)
{
  constexpr std::size_t ChunkBytes = std::size_t(1) << 20;
  std::vector<std::size_t> begin{ 0 };
  for (std::size_t at = ChunkBytes; at < rest.size(); at = begin.back() + ChunkBytes)
  {
    const std::size_t end = rest.find('\n', at);
    if (end == std::string_view::npos || end + 1 >= rest.size())
    {
      break;
    }
    // A byte-order mark is skipped at the start of a text only (Lines).
    if (rest.substr(end + 1, 3) == "\xEF\xBB\xBF")
    {
      return false;
    }
    begin.push_back(end + 1);
  }
  begin.push_back(rest.size());
  const std::size_t chunks = begin.size() - 1;
  std::vector<std::vector<double>> parts(chunks);
  std::atomic<bool> failed{ false };
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t k) {
    try
    {
      Lines lines(file, rest.substr(begin[k], begin[k + 1] - begin[k]));
      std::string_view line;
      std::vector<std::string_view> fields;
      parts[k].reserve((begin[k + 1] - begin[k]) / 16);
      while (!failed.load(std::memory_order_relaxed) && lines.NextData(line))
      {
        SplitLoose(line, fields, 3);
        AppendPoint(file, lines.Number, fields, 0, XyzExpected, parts[k]);
      }
    }
    catch (const std::exception&)
    {
      failed = true;
    }
  });
  if (failed)
  {
    return false;
  }
  std::size_t total = xyz.size();
  for (const std::vector<double>& part : parts)
  {
    total += part.size();
  }
  xyz.reserve(total);
  for (std::vector<double>& part : parts)
  {
    xyz.insert(xyz.end(), part.begin(), part.end());
    std::vector<double>().swap(part);
  }
  return true;
}

} // namespace

void ReadXyz(const std::string& file, std::string_view text, std::vector<double>& xyz)
{
  Lines lines(file, text);
  std::string_view line;
  std::vector<std::string_view> fields;
  bool first = true;
  std::string_view announced; // the count on the first line, if any
  std::size_t countLine = 0;
  while (lines.NextData(line))
  {
    SplitLoose(line, fields, 3);
    if (first && fields.size() == 1 &&
      fields[0].find_first_not_of("0123456789") == std::string_view::npos)
    {
      first = false; // the point count
      announced = fields[0];
      countLine = lines.Number;
      continue;
    }
    first = false;
    AppendPoint(file, lines.Number, fields, 0, XyzExpected, xyz);
    // After the first point every data line is a point: the rest of a large
    // file in parallel (as it would be read here, or not at all).
    if (xyz.size() == 3 && text.size() - lines.Offset() > (std::size_t(4) << 20) &&
      ReadXyzInParallel(file, text.substr(lines.Offset()), xyz))
    {
      break;
    }
  }
  // A count that disagrees with the points read: a truncated file, or lines
  // the count does not cover; either way not the cloud that was written.
  const std::size_t read = xyz.size() / 3;
  if (!announced.empty() && std::to_string(read) != TrimZeros(announced))
  {
    Fail(file, countLine,
      "the first line announces " + std::string(announced) + " points, the file holds " + std::to_string(read) +
        " (truncated?)");
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
    AppendPoint(file, lines.Number, fields, 0, "expected 3 coordinates (x y z)", xyz);
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
    AppendPoint(file, lines.Number, fields, 1, "expected 3 coordinates after 'v'", xyz);
  }
}

} // namespace reader
} // namespace flowrecon
