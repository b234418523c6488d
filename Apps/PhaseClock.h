// The wall-clock seconds of the phases of a command (flowrecon reconstruct --timings).
#ifndef flowrecon_cli_PhaseClock_h
#define flowrecon_cli_PhaseClock_h

#include <chrono>
#include <iomanip>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace flowrecon::cli
{

class PhaseClock
{
public:
  /// Ends the phase `name`: the seconds since the previous phase ended (or
  /// since the clock was made).
  void operator()(const char* name)
  {
    const auto now = std::chrono::steady_clock::now();
    this->Phases.emplace_back(name, std::chrono::duration<double>(now - this->Last).count());
    this->Last = now;
  }

  /// "timings (s): phase 0.123; ..." on one line.
  void Print(std::ostream& os) const
  {
    const std::streamsize precision = os.precision();
    os << "timings (s):";
    for (const auto& phase : this->Phases)
    {
      os << " " << phase.first << " " << std::fixed << std::setprecision(3) << phase.second << ";";
    }
    os << std::defaultfloat << std::setprecision(static_cast<int>(precision)) << "\n";
  }

private:
  std::vector<std::pair<std::string, double>> Phases;
  std::chrono::steady_clock::time_point Last = std::chrono::steady_clock::now();
};

} // namespace flowrecon::cli

#endif
