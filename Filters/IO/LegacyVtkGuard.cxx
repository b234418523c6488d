// Checks of a legacy VTK file (see LegacyVtkGuard.h): a walk over its tokens
// as vtkDataReader reads them (keywords by case-insensitive prefix, `>>`
// numbers, binary blocks), refusing what would crash or hang VTK 9.2.
#include "LegacyVtkGuard.h"

#include "PointCloudParsing.h"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <vector>

namespace flowrecon
{
namespace reader
{
namespace
{

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
    if (Lower(this->Text.substr(this->Pos, 8)) != "metadata")
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
  const std::string t = Lower(type);
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
      const std::string lower = Lower(type);
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
  const bool binary = tokens.Next(token) && Lower(token.substr(0, 6)) == "binary";
  static const char* const geometry[] = { "points", "x_coordinates", "y_coordinates",
    "z_coordinates", "vertices", "lines", "polygons", "triangle_strips", "cells", "cell_types" };
  while (tokens.Next(token))
  {
    const std::string keyword = Lower(token.substr(0, 16));
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
    else if (Lower(token).find("field") != std::string::npos)
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

} // namespace

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
    const std::string keyword = Lower(fields[0]);
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

} // namespace reader
} // namespace flowrecon
