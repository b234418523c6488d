#include "MessageCapture.h"

#include "VtkMessageCapture.h"

#include "vtkLogger.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"

#include <algorithm>

namespace flowrecon::cli
{

namespace
{

class CapturingOutputWindow : public vtkOutputWindow
{
public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char* text) override
  {
    if (this->FirstError.empty())
    {
      this->FirstError = VtkMessageText(text);
    }
  }
  // Kept for the commands that run the filters (a saved complex): a filter's
  // warning is then the only place that says, e.g., why there are no Betti numbers.
  void DisplayWarningText(const char* text) override
  {
    const std::string t = VtkMessageText(text);
    if (!t.empty() &&
      std::find(this->Warnings.begin(), this->Warnings.end(), t) == this->Warnings.end())
    {
      this->Warnings.push_back(t);
    }
  }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  void DisplayDebugText(const char*) override {}

  std::string FirstError;
  std::vector<std::string> Warnings;
};
vtkStandardNewMacro(CapturingOutputWindow);

vtkSmartPointer<CapturingOutputWindow> Messages;

} // namespace

void CaptureVtkMessages()
{
  // VTK's logger prints errors to stderr by itself, besides the output window.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  Messages = vtkSmartPointer<CapturingOutputWindow>::New();
  vtkOutputWindow::SetInstance(Messages);
}

void ClearVtkError()
{
  if (Messages)
  {
    Messages->FirstError.clear();
  }
}

std::string FirstVtkError()
{
  return Messages ? Messages->FirstError : std::string();
}

std::vector<std::string> VtkWarnings()
{
  return Messages ? Messages->Warnings : std::vector<std::string>();
}

} // namespace flowrecon::cli
