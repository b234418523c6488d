// The block headers of binary data arrays in VTK XML files, checked before
// vtkXMLDataParser reads them: it allocates a table of "number of blocks"
// entries and a buffer of "block size" bytes from a header unchecked, and
// reads blocks that are not there when the header announces too few. Also the
// bounds these checks use (compressor ratios, the bits of a value).
#ifndef XmlBlockHeaders_h
#define XmlBlockHeaders_h

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace flowrecon
{
namespace reader
{

/// The largest ratio of uncompressed to compressed bytes the compressor named
/// reaches (1 for "", none).
long long RatioOf(const std::string& compressor);

/// The fewest bits a value of a data array of `type` ("Float32", "Bit"...) in
/// `format` ("ascii", "binary", "appended") takes in the file before compression.
int BitsPerValue(std::string_view type, std::string_view format);

/// The problem with a block header, or "". The header is the array's byte
/// count or, `compressed`, (number of blocks, block size, last block size,
/// compressed size of each block), in words of `wordSize` bytes. Each size must
/// fit in the `available` bytes (`base64`: characters, 3 bytes per 4) that
/// follow, no block may expand more than `ratio` times, and the blocks must
/// hold the `needed` bytes of values that will be read. read(n) gives the
/// first n bytes (or characters) of the header.
std::string CheckBlockHeader(const std::function<std::string(std::size_t)>& read,
  long long available, bool base64, bool compressed, std::size_t wordSize, bool bigEndian,
  long long ratio, unsigned long long needed = 0);

} // namespace reader
} // namespace flowrecon

#endif
