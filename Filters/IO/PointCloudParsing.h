// The pieces every parser of vtkPointCloudReader shares: the one-line error it
// throws (`FILE:LINE: message`), quoting of bad tokens, locale-independent
// number parsing, line and field splitting, and reading a whole file. Kept
// apart so that each format's parser is only its own grammar.
#ifndef PointCloudParsing_h
#define PointCloudParsing_h

#include "vtkByteSwap.h"

#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace flowrecon
{
namespace reader
{

/// A failure to report; what() is the complete one-line message.
class ReadError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Throws ReadError("FILE:LINE: message"), or "FILE: message" when `line` is 0.
[[noreturn]] void Fail(const std::string& file, std::size_t line, const std::string& message);

/// Blanks of a line: space, tab, vertical tab, form feed and carriage return.
bool IsBlank(char c);
std::string_view Trim(std::string_view s);

/// The lowercase copy (vtksys::SystemTools::LowerCase) of a view.
std::string Lower(std::string_view s);

/// A token for an error message: quoted, control bytes escaped, long ones cut.
std::string Quote(std::string_view token);

/// Control bytes other than blanks (a binary file read as text).
bool HasControlBytes(std::string_view text);

enum class Number
{
  Ok,
  Invalid,
  Overflow
};

/// Locale-independent (std::from_chars). Accepts a leading '+', which from_chars
/// does not; NaN and infinities parse (the caller rejects them with a clear
/// message); magnitudes below the smallest double become zero.
Number ParseNumber(std::string_view token, double& value);

/// A non-negative decimal integer, the whole token.
bool ParseCount(std::string_view token, long long& count);

/// Parses one finite coordinate; `what` names it for the message ("y coordinate").
double Coordinate(
  const std::string& file, std::size_t line, std::string_view token, const std::string& what);

extern const char* const AxisName[3]; // "x", "y", "z"

/// Iterates over the lines of a buffer ("\n", "\r\n" or "\r" endings), numbered
/// from 1; a UTF-8 byte order mark is dropped.
class Lines
{
public:
  Lines(const std::string& file, std::string_view text);

  bool Next(std::string_view& line);

  /// The next line that is neither blank nor a comment (# or //). Control
  /// bytes mean a binary file: stop there rather than report odd numbers.
  bool NextData(std::string_view& line);

  /// Byte offset of the next line.
  std::size_t Offset() const { return this->Pos; }

  std::size_t Number = 0;

private:
  const std::string& File;
  std::string_view Text;
  std::size_t Pos = 0;
};

/// The first `maxFields` fields of a line separated by runs of blanks and commas.
void SplitLoose(std::string_view line, std::vector<std::string_view>& fields, std::size_t maxFields);

/// The little-endian value of type T (an arithmetic type vtkByteSwap knows) at
/// byte `at` of `bytes`, which must hold it: binary STL and LAS are little-endian.
template <class T>
T LittleEndianAt(std::string_view bytes, std::size_t at)
{
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof(T));
  vtkByteSwap::SwapLE(&value);
  return value;
}

/// The bytes of a file; with `stopAfter`, reading may stop a little after that text.
std::string ReadWholeFile(const std::string& file, std::string_view stopAfter = {});

} // namespace reader
} // namespace flowrecon

#endif
