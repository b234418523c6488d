// The commands of flowrecon, each a function over the parsed Arguments
// (flowrecon.cxx binds the options to them through CLI11). Each returns the
// exit code, or throws a cli::Error.
#ifndef flowrecon_cli_Commands_h
#define flowrecon_cli_Commands_h

#include "CommandLine.h" // NumberArg
#include "FlowComplex.h" // core: Id
#include "Pipeline.h"    // FlowComplexOptions

#include <string>

namespace flowrecon::cli
{

/// The options of every command; each command declares the ones it takes.
struct Arguments
{
  std::string Command; ///< the command given
  std::string Input, Output, Profile, TopologyProfile;
  bool Quiet = false, NoStable = false, NoUnstable = false, NoBetti = false, Timings = false,
       Compact = false, Exact = false;
  NumberArg Threads{ "--threads" }, MaxCells{ "--max-cells" }, Tr{ "--tr" }, TrMax{ "--tr-max" },
    Tp{ "--tp" }, WarnWindow{ "--warn-window" }, BettiMaxCells{ "--betti-max-cells" },
    Jumps{ "--jumps" };
};

/// A whole number >= 0 or 'inf' (-1), `fallback` when not given; `what` words
/// the usage error ("a count >= 0 or 'inf'").
Id CountOption(const Arguments& args, const NumberArg& arg, Id fallback, const char* what);

/// --no-stable, --max-cells, --no-unstable, --quiet and the command's label.
FlowComplexOptions FlowComplexOptionsOf(const Arguments& args);

int RunComplex(const Arguments& args);     ///< flowrecon complex (FlowComplexCommands.cxx)
int RunInfo(const Arguments& args);        ///< flowrecon info (FlowComplexCommands.cxx)
int RunReconstruct(const Arguments& args); ///< flowrecon reconstruct (ReconstructCommand.cxx)
int RunDiagram(const Arguments& args);     ///< flowrecon diagram (DiagramCommand.cxx)

} // namespace flowrecon::cli

#endif
