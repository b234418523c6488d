// The capturing output window of vtkPointCloudReader (see VtkMessageCapture.h).
#include "VtkMessageCapture.h"

#include "PointCloudParsing.h"

#include "vtkAlgorithm.h"
#include "vtkExecutive.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"

#include <cstring>
#include <new>
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

namespace reader
{
namespace
{

// Collects the messages VTK sends to its output window while installed, so a
// failing VTK reader does not print its multi-line reports. (Messages VTK's
// logger prints to stderr are up to the application: the flowrecon tool turns
// that off.)
class MessageCapture : public vtkOutputWindow
{
public:
  static MessageCapture* New();
  vtkTypeMacro(MessageCapture, vtkOutputWindow);
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char* text) override
  {
    this->Keep(text);
    // VTK built without NDEBUG (Debian's is) aborts after this message when an
    // array cannot be allocated; throw what its release builds throw instead.
    if (text && std::strstr(text, "Unable to allocate "))
    {
      throw std::bad_alloc();
    }
  }
  void DisplayWarningText(const char* text) override { this->Keep(text); }
  void DisplayGenericWarningText(const char* text) override { this->Keep(text); }
  void DisplayDebugText(const char*) override {}

  // The first message, reduced to its text (VtkMessageText).
  std::string First;

private:
  void Keep(const char* text)
  {
    if (!this->First.empty() || !text)
    {
      return;
    }
    const std::string t = VtkMessageText(text);
    // The detail goes into a one-line message: no control or non-ASCII bytes.
    this->First = t.empty() ? "unknown error" : t.substr(0, 200);
    for (char& c : this->First)
    {
      c = (c < 0x20 || c > 0x7e) ? '?' : c;
    }
  }
};
vtkStandardNewMacro(MessageCapture);

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
  return static_cast<MessageCapture*>(this->Capture.Get())->First;
}

void UpdateCaptured(const std::string& file, vtkAlgorithm* reader, const char* kind)
{
  std::string first;
  int ok = 0;
  {
    CapturedMessages capture;
    ok = reader->GetExecutive()->Update();
    first = capture.First();
  }
  if (!ok || reader->GetErrorCode() != 0 || !first.empty() || !reader->GetOutputDataObject(0))
  {
    Fail(file, 0,
      std::string("cannot read ") + kind + " file" + (first.empty() ? std::string() : " (" + first + ")"));
  }
}

} // namespace reader
} // namespace flowrecon
