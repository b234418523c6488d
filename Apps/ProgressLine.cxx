#include "ProgressLine.h"

#include "Interrupt.h"

#include "vtkAlgorithm.h"

#include <algorithm>
#include <cstdio>

#include <unistd.h> // isatty

namespace flowrecon::cli
{

vtkSmartPointer<ProgressLine> ProgressLine::Make(const std::string& label, bool quiet)
{
  auto line = vtkSmartPointer<ProgressLine>::Take(ProgressLine::New());
  line->Label = label;
  line->Show = !label.empty() && !quiet && isatty(2);
  return line;
}

void ProgressLine::Execute(vtkObject* caller, unsigned long, void* callData)
{
  auto* algorithm = vtkAlgorithm::SafeDownCast(caller);
  if (InterruptRequested() && algorithm)
  {
    algorithm->SetAbortExecute(1);
  }
  if (this->Show && algorithm && callData)
  {
    this->Print(*static_cast<double*>(callData), algorithm->GetProgressText());
  }
}

flowrecon::Progress ProgressLine::Core()
{
  flowrecon::Progress progress;
  progress.Report = [this](double fraction, const char* phase) {
    if (this->Show)
    {
      this->Print(fraction, phase);
    }
  };
  progress.ShouldAbort = []() { return InterruptRequested(); };
  return progress;
}

void ProgressLine::Print(double fraction, const char* phase)
{
  const int percent = static_cast<int>(100 * fraction);
  std::string line =
    "[" + this->Label + "] " + std::to_string(percent) + "%  " + (phase ? phase : "");
  line = line.substr(0, 79);
  if (line == this->Last)
  {
    return;
  }
  // Pad with blanks to erase the rest of a longer previous line.
  const std::size_t width = std::max(line.size(), this->Last.size());
  std::fprintf(stderr, "\r%-*s", static_cast<int>(width), line.c_str());
  std::fflush(stderr);
  this->Last = line;
}

void ProgressLine::Finish()
{
  if (!this->Last.empty())
  {
    std::fputc('\n', stderr);
    this->Last.clear();
  }
}

} // namespace flowrecon::cli
