// VTK's messages, kept instead of printed in its output window: the one capture
// of the library and of the flowrecon tool. The reader makes the first message
// of a VTK reader part of its one-line error; the tool keeps one capture for its
// whole run, reports a failed step's first error and repeats a filter's warnings
// once each. Every capture turns VTK's "Unable to allocate" error, after which
// Debian's VTK (built without NDEBUG) aborts, into a VtkAllocationFailure.
#ifndef VtkMessageCapture_h
#define VtkMessageCapture_h

#include "vtkSmartPointer.h"

#include <new>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkOutputWindow;

namespace flowrecon
{

/// The text of a message VTK sends to its output window: "ERROR: In file, line
/// N" (or "Warning: In", "Generic Warning: In") and the "vtkClass (0x...): "
/// prefix dropped, its first line only, without surrounding blanks.
std::string VtkMessageText(const char* text);

/// What a capture throws when VTK reports that it cannot allocate an array.
class VtkAllocationFailure : public std::bad_alloc
{
public:
  explicit VtkAllocationFailure(std::string message);
  const char* what() const noexcept override; ///< VTK's message
private:
  std::string Message;
};

/// Installs a capturing output window for its lifetime, then restores the
/// previous one (also when an exception leaves the scope).
class CapturedMessages
{
public:
  CapturedMessages();
  ~CapturedMessages();
  CapturedMessages(const CapturedMessages&) = delete;
  CapturedMessages& operator=(const CapturedMessages&) = delete;

  /// The first error or warning since the start or Clear() (VtkMessageText;
  /// "unknown error" for one without text); "" if none.
  const std::string& First() const;
  /// The first error since the start or Clear() ("" for none).
  const std::string& FirstError() const;
  /// Forgets the first message and error (call it before a step whose error is wanted).
  void Clear();
  /// The distinct warnings so far, in order.
  const std::vector<std::string>& Warnings() const;

private:
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkSmartPointer<vtkOutputWindow> Capture;
};

/// The capture of a program that owns its process (the flowrecon tool): made
/// on the first call, it keeps VTK's messages for the rest of the run.
CapturedMessages& RunMessages();

namespace reader
{

/// A message for a one-line error: printable ASCII, at most 200 characters.
std::string OneLine(const std::string& message);

/// Updates `reader` with its messages captured; throws ReadError
/// "FILE: cannot read KIND file (first VTK message)" on any error or warning.
void UpdateCaptured(const std::string& file, vtkAlgorithm* reader, const char* kind);

} // namespace reader
} // namespace flowrecon

#endif
