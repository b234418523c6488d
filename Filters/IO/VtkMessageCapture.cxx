// The capturing output window (see VtkMessageCapture.h).
#include "VtkMessageCapture.h"

#include "PointCloudParsing.h"

#include "vtkAlgorithm.h"
#include "vtkExecutive.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"

#include <algorithm>
#include <string_view>

namespace flowrecon
{

std::string VtkMessageText(const char* text)
{
  std::string_view t(text ? text : "");
  if (t.substr(0, 4) == "ERRO" || t.substr(0, 4) == "Warn" || t.substr(0, 4) == "Gene")
  {
    const std::size_t newline = t.find('\n');
    t = newline == std::string_view::npos ? std::string_view() : t.substr(newline + 1);
  }
  const std::size_t object = t.find(" (0x");
  const std::size_t colon = t.find("): ");
  if (object != std::string_view::npos && colon != std::string_view::npos && object < colon &&
    t.substr(0, object).find_first_of(" \n") == std::string_view::npos)
  {
    t.remove_prefix(colon + 3);
  }
  return std::string(reader::Trim(t.substr(0, t.find('\n'))));
}

VtkAllocationFailure::VtkAllocationFailure(std::string message)
  : Message(std::move(message))
{
}

const char* VtkAllocationFailure::what() const noexcept
{
  return this->Message.c_str();
}

namespace
{

// Collects the messages VTK sends to its output window while installed.
// (Messages VTK's logger prints to stderr are up to the application: the
// flowrecon tool turns that off.)
class MessageCapture : public vtkOutputWindow
{
public:
  static MessageCapture* New();
  vtkTypeMacro(MessageCapture, vtkOutputWindow);
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char* text) override
  {
    const std::string t = VtkMessageText(text);
    this->Keep(t);
    if (this->FirstError.empty())
    {
      this->FirstError = t;
    }
    // VTK built without NDEBUG (Debian's is) aborts after this message when an
    // array cannot be allocated; throw what its release builds throw instead.
    // (Only VTK's own message: a reader's error may quote it.)
    if (t.rfind("Unable to allocate ", 0) == 0)
    {
      throw VtkAllocationFailure(t);
    }
  }
  void DisplayWarningText(const char* text) override
  {
    const std::string t = VtkMessageText(text);
    this->Keep(t);
    if (!t.empty() &&
      std::find(this->Warnings.begin(), this->Warnings.end(), t) == this->Warnings.end())
    {
      this->Warnings.push_back(t);
    }
  }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  void DisplayDebugText(const char*) override {}

  std::string First;
  std::string FirstError;
  std::vector<std::string> Warnings;

private:
  void Keep(const std::string& t)
  {
    if (this->First.empty())
    {
      this->First = t.empty() ? "unknown error" : t;
    }
  }
};
vtkStandardNewMacro(MessageCapture);

MessageCapture& Of(const vtkSmartPointer<vtkOutputWindow>& capture)
{
  return *static_cast<MessageCapture*>(capture.Get());
}

} // namespace

CapturedMessages::CapturedMessages()
  : Previous(vtkOutputWindow::GetInstance())
  , Capture(vtkSmartPointer<MessageCapture>::New())
{
  vtkOutputWindow::SetInstance(this->Capture);
}

CapturedMessages::~CapturedMessages()
{
  vtkOutputWindow::SetInstance(this->Previous);
}

const std::string& CapturedMessages::First() const
{
  return Of(this->Capture).First;
}

const std::string& CapturedMessages::FirstError() const
{
  return Of(this->Capture).FirstError;
}

void CapturedMessages::Clear()
{
  Of(this->Capture).First.clear();
  Of(this->Capture).FirstError.clear();
}

const std::vector<std::string>& CapturedMessages::Warnings() const
{
  return Of(this->Capture).Warnings;
}

CapturedMessages& RunMessages()
{
  static CapturedMessages messages;
  return messages;
}

namespace reader
{

std::string OneLine(const std::string& message)
{
  std::string line = message.substr(0, 200);
  for (char& c : line)
  {
    c = (c < 0x20 || c > 0x7e) ? '?' : c;
  }
  return line;
}

void UpdateCaptured(const std::string& file, vtkAlgorithm* reader, const char* kind)
{
  std::string first;
  int ok = 0;
  {
    CapturedMessages capture;
    ok = reader->GetExecutive()->Update();
    first = OneLine(capture.First());
  }
  if (!ok || reader->GetErrorCode() != 0 || !first.empty() || !reader->GetOutputDataObject(0))
  {
    Fail(file, 0,
      std::string("cannot read ") + kind + " file" +
        (first.empty() ? std::string() : " (" + first + ")"));
  }
}

} // namespace reader
} // namespace flowrecon
