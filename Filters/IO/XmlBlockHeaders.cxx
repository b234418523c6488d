// Checks of the block headers of binary data arrays in VTK XML files (see
// XmlBlockHeaders.h), decoded as vtkXMLDataParser decodes them.
#include "XmlBlockHeaders.h"

#include "vtkBase64Utilities.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace flowrecon
{
namespace reader
{
namespace
{

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

} // namespace

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

// vtkXMLDataParser computes the uncompressed size as (blocks - 1) x block size
// + last block size, which wraps around with no block, and then reads a block
// that is not there: CheckUncompressedSize.
std::string CheckBlockHeader(const std::function<std::string(std::size_t)>& read,
  long long available, bool base64, bool compressed, std::size_t wordSize, bool bigEndian,
  long long ratio, unsigned long long needed)
{
  std::vector<unsigned long long> words;
  const auto decode = [&](std::size_t count) {
    const std::size_t bytes = count * wordSize;
    std::string chunk = read(base64 ? 4 * ((bytes + 2) / 3) : bytes);
    if (base64)
    {
      // As vtkBase64InputStream decodes it: whole groups of 4 characters, up
      // to the first one outside the alphabet or the padding.
      std::string decoded(bytes, '\0');
      decoded.resize(vtkBase64Utilities::DecodeSafely(
        reinterpret_cast<const unsigned char*>(chunk.data()), chunk.size(),
        reinterpret_cast<unsigned char*>(&decoded[0]), decoded.size()));
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

} // namespace reader
} // namespace flowrecon
