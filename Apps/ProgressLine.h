// The progress line: "\r[command] 42%  phase" on stderr when it is a terminal,
// for a VTK filter (as a ProgressEvent observer) or for the core. Also forwards
// Ctrl-C: it sets the filter's abort flag, and the core polls it.
#ifndef flowrecon_cli_ProgressLine_h
#define flowrecon_cli_ProgressLine_h

#include "Progress.h" // core progress

#include "vtkCommand.h"
#include "vtkSmartPointer.h"

#include <string>

namespace flowrecon::cli
{

class ProgressLine : public vtkCommand
{
public:
  static ProgressLine* New() { return new ProgressLine; }

  /// A line labelled `label`, drawn unless `quiet` or stderr is not a terminal;
  /// without a label, it only forwards Ctrl-C.
  static vtkSmartPointer<ProgressLine> Make(const std::string& label = std::string(), bool quiet = true);

  void Execute(vtkObject* caller, unsigned long, void* callData) override;

  /// The same line for the core's progress, which also polls for Ctrl-C.
  flowrecon::Progress Core();

  /// Ends the line, if one was drawn.
  void Finish();

private:
  void Print(double fraction, const char* phase);

  std::string Label;
  bool Show = false;
  std::string Last;
};

} // namespace flowrecon::cli

#endif
