// VTK's messages, kept instead of printed: a failure prints one line (its first
// error), and a filter's warnings can be repeated once each.
#ifndef flowrecon_cli_MessageCapture_h
#define flowrecon_cli_MessageCapture_h

#include <string>
#include <vector>

namespace flowrecon::cli
{

/// Routes VTK's output window (and silences its logger on stderr) into the
/// capture, for the rest of the run.
void CaptureVtkMessages();

/// Forgets the errors captured so far: call it before a step whose error is wanted.
void ClearVtkError();

/// The text of the first VTK error since ClearVtkError ("" for none), without
/// VTK's "ERROR: In file, line" header and the object's name.
std::string FirstVtkError();

/// The distinct warnings captured so far, in order.
std::vector<std::string> VtkWarnings();

} // namespace flowrecon::cli

#endif
