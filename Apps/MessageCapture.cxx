#include "MessageCapture.h"

#include "vtkLogger.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cctype>

namespace flowrecon::cli
{

namespace
{

// "ERROR: In file.cxx, line 12\nvtkClass (0x...): text\n\n" -> "text".
std::string MessageText(const char* text)
{
  std::string t = text ? text : "";
  if (t.rfind("ERROR: In ", 0) == 0 || t.rfind("Warning: In ", 0) == 0)
  {
    const std::size_t newline = t.find('\n');
    t = newline == std::string::npos ? std::string() : t.substr(newline + 1);
  }
  const std::size_t object = t.find(" (0x");
  const std::size_t colon = t.find("): ");
  if (object != std::string::npos && colon != std::string::npos && object < colon &&
    t.find_first_of(" \n") == object)
  {
    t = t.substr(colon + 3);
  }
  t = t.substr(0, t.find('\n'));
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back())))
  {
    t.pop_back();
  }
  return t;
}

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
      this->FirstError = MessageText(text);
    }
  }
  // Kept for the commands that run the filters (a saved complex): a filter's
  // warning is then the only place that says, e.g., why there are no Betti numbers.
  void DisplayWarningText(const char* text) override
  {
    const std::string t = MessageText(text);
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
