// Shared pieces of the point cloud parsers (see PointCloudParsing.h): the
// error, tokens, numbers, lines and fields, whole-file reads.
#include "PointCloudParsing.h"

#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>

namespace flowrecon
{
namespace reader
{

void Fail(const std::string& file, std::size_t line, const std::string& message)
{
  std::string where = file;
  if (line > 0)
  {
    where += ":" + std::to_string(line);
  }
  throw ReadError(where + ": " + message);
}

namespace
{
constexpr std::string_view Blanks = " \t\v\f\r";
constexpr std::string_view Separators = " \t\v\f\r,"; // of SplitLoose's fields
}

bool IsBlank(char c)
{
  return Blanks.find(c) != std::string_view::npos;
}

std::string_view Trim(std::string_view s)
{
  const std::size_t first = s.find_first_not_of(Blanks);
  return first == std::string_view::npos ? std::string_view()
                                         : s.substr(first, s.find_last_not_of(Blanks) - first + 1);
}

std::string Lower(std::string_view s)
{
  return vtksys::SystemTools::LowerCase(std::string(s));
}

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

Lines::Lines(const std::string& file, std::string_view text)
  : File(file)
  , Text(text)
{
  if (this->Text.substr(0, 3) == "\xEF\xBB\xBF")
  {
    this->Pos = 3;
  }
}

bool Lines::Next(std::string_view& line)
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

bool Lines::NextData(std::string_view& line)
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

void SplitLoose(std::string_view line, std::vector<std::string_view>& fields, std::size_t maxFields)
{
  fields.clear();
  std::size_t start = line.find_first_not_of(Separators);
  while (start != std::string_view::npos && fields.size() < maxFields)
  {
    const std::size_t end = std::min(line.find_first_of(Separators, start), line.size());
    fields.push_back(line.substr(start, end - start));
    start = line.find_first_not_of(Separators, end);
  }
}

bool ParseCount(std::string_view token, long long& count)
{
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, count);
  return !token.empty() && ec == std::errc() && ptr == end && count >= 0;
}

std::string ReadWholeFile(const std::string& file, std::string_view stopAfter)
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

} // namespace reader
} // namespace flowrecon
