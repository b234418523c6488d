// Keeps the messages of the VTK readers and parsers vtkPointCloudReader runs
// out of VTK's output window: while a CapturedMessages lives, the first error
// or warning is kept (to become part of the reader's one-line error) and the
// rest dropped. It also turns VTK's "Unable to allocate" error, after which
// Debian's VTK (built without NDEBUG) aborts, into std::bad_alloc.
#ifndef VtkMessageCapture_h
#define VtkMessageCapture_h

#include "vtkSmartPointer.h"

#include <string>

class vtkAlgorithm;
class vtkOutputWindow;

namespace flowrecon
{

/// The text of a message VTK sends to its output window: "ERROR: In file, line
/// N" (or "Warning: In", "Generic Warning: In") and the "vtkClass (0x...): "
/// prefix dropped, its first line only, without surrounding blanks. Used by the
/// reader and by the flowrecon tool, whose messages are one line each.
std::string VtkMessageText(const char* text);

namespace reader
{

/// Installs a capturing output window for its lifetime, then restores the
/// previous one (also when an exception leaves the scope).
class CapturedMessages
{
public:
  CapturedMessages();
  ~CapturedMessages();
  CapturedMessages(const CapturedMessages&) = delete;
  CapturedMessages& operator=(const CapturedMessages&) = delete;

  /// The first message, reduced to one line of printable ASCII without VTK's
  /// "ERROR: In file, line N" and "vtkClass (0x...): " prefixes; "" if none.
  const std::string& First() const;

private:
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkSmartPointer<vtkOutputWindow> Capture;
};

/// Updates `reader` with its messages captured; throws ReadError
/// "FILE: cannot read KIND file (first VTK message)" on any error or warning.
void UpdateCaptured(const std::string& file, vtkAlgorithm* reader, const char* kind);

} // namespace reader
} // namespace flowrecon

#endif
