// Progress reporting, cancellation and the errors the core raises.
#ifndef flowrecon_Progress_h
#define flowrecon_Progress_h

#include <functional>
#include <stdexcept>
#include <string>

namespace flowrecon
{

/// Bad input: the message is one line meant for the user.
class InputError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// The caller asked to stop.
class Aborted : public std::runtime_error
{
public:
  Aborted()
    : std::runtime_error("aborted")
  {
  }
};

/// A computation found its input in non-general position (a tie between exact
/// quantities). Internal: the builder catches it and perturbs the input.
class Degenerate : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Callbacks a caller may set; both are optional. Report receives a fraction in
/// [0,1] and a phase name; ShouldAbort is polled regularly.
struct Progress
{
  std::function<void(double, const char*)> Report;
  std::function<bool()> ShouldAbort;

  void operator()(double fraction, const char* phase) const
  {
    if (this->Report)
    {
      this->Report(fraction, phase);
    }
    if (this->ShouldAbort && this->ShouldAbort())
    {
      throw Aborted();
    }
  }

  /// The same callbacks for a stage that covers [from, to] of this progress.
  Progress Range(double from, double to) const
  {
    Progress part;
    part.ShouldAbort = this->ShouldAbort;
    if (this->Report)
    {
      auto report = this->Report;
      part.Report = [report, from, to](double f, const char* phase) {
        report(from + (to - from) * f, phase);
      };
    }
    return part;
  }
};

} // namespace flowrecon

#endif
