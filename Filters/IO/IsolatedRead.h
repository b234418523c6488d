// VTK's readers run in a child process. VTK 9.2's legacy and XML readers crash,
// loop or allocate without bound on some corrupt files (fuzzing found null
// arrays after malformed FIELD blocks and untyped or missing elements, cell
// lists read past their end, a block table of no blocks, a loop on blanks).
// Predicting which files those are ties the prediction to one VTK version's
// parser; a child process contains whatever any version does. Its read is the
// read, not a check: what it read comes back through a pipe (or the child goes
// on as the program), so a valid file is read once. docs/limitations.md says
// where there is no child.
#ifndef IsolatedRead_h
#define IsolatedRead_h

#include <functional>
#include <string>

namespace flowrecon
{
namespace reader
{

/// Runs `read` in a child process and returns the bytes it returned. The child
/// may allocate what this process still could (AvailableMemory), but no more
/// than 1 GB plus 1100 times its input (`file` and the files a .vtm or .pvt*
/// names), and is stopped after 10 s (plus 1 s per 100 MB of input) without
/// reading or writing a byte.
/// Throws read's ReadError as it is, and ReadError("FILE: out of memory (VTK's
/// message)") or ("FILE: cannot read KIND file (VTK's reader crashed: ...)").
/// Where there is no fork(), or FLOWRECON_READ_IN_PROCESS is set (to debug a
/// reader), `read` runs in this process, with the same errors.
std::string ReadIsolated(
  const std::string& file, const char* kind, const std::function<std::string()>& read);

/// For a program that owns its process (the flowrecon tool, before it starts
/// threads): runs `read` in a child process under the same limits, which then
/// goes on with the program while this one waits and ends as it ends; returns
/// in the child only. Throws ReadError here when the child crashes or stalls
/// inside `read`; read's own exceptions are the child's.
void ReadThenGoOnInChild(
  const std::string& file, const char* kind, const std::function<void()>& read);

} // namespace reader
} // namespace flowrecon

#endif
