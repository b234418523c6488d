// flowrecon: the command-line front end of the FlowRecon VTK filters.
//
//   flowrecon complex INPUT -o OUT.vtm [--no-stable] [--no-unstable] [--quiet]
//   flowrecon info    INPUT [--no-stable] [--no-unstable] [--quiet]
//   flowrecon reconstruct INPUT -o OUT.vtu [--tr T|auto] [--tp P|auto] [--profile P.csv] [--jumps K]
//                         [--exact] [--tr-max T] [--topology-profile B.csv]
//   flowrecon diagram INPUT -o PD.csv|PD.vtu
// Every command also takes --threads N (TBB's limit for the flow complex).
//
// This file is the command line: each command's options and help, bound
// through CLI11 (CommandLine.h) to the Arguments its function takes
// (Commands.h, one file per command), and main. Exit codes: 0 success, 1 bad
// input or failed computation, 2 usage error, 130 interrupted (Ctrl-C). Errors
// are one line on stderr (cli::Error); VTK's own messages are captured, never
// printed (VtkMessageCapture.h).

#include "CliError.h"
#include "CommandLine.h"
#include "Commands.h"
#include "HugePages.h"
#include "Interrupt.h"
#include "VtkMessageCapture.h"

#include "vtkLogger.h"
#include "vtkVersion.h"

#include <tbb/global_control.h>

#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <variant>

#ifndef FLOWRECON_VERSION
#define FLOWRECON_VERSION "unknown"
#endif

namespace
{

using namespace flowrecon::cli;

// The options of each command, bound to their fields of `args` (all commands
// also take --threads and --quiet).
void OutputOption(CLI::App* c, Arguments& args, const char* placeholder, const char* help)
{
  c->add_option("-o,--output", args.Output, help)->type_name(placeholder);
}

void ManifoldOptions(CLI::App* c, Arguments& args)
{
  c->add_flag("--no-stable", args.NoStable,
    "skip the triangulated stable manifolds of index-2 and index-3 nodes");
  if (c->get_name() == "complex")
  {
    AddNumber(c, "--max-cells", args.MaxCells, "N",
      "draw at most N stable-manifold cells, in order of critical value; 'inf' for all (2e6)");
  }
  c->add_flag("--no-unstable", args.NoUnstable, "skip the polylines of the unstable manifolds");
}

void ComplexOptions(CLI::App* c, Arguments& args)
{
  OutputOption(c, args, "OUT.vtm", "the multiblock file to write (.vtm)");
  ManifoldOptions(c, args);
}

// An option of a table: a number (NumberArg), a text or a flag of Arguments.
struct OptionRow
{
  const char* Names;
  std::variant<NumberArg Arguments::*, std::string Arguments::*, bool Arguments::*> Field;
  const char* Placeholder; // nullptr for a flag
  const char* Help;
};

// Adds `rows` to `c`, in their order (which is the order of the help).
template <std::size_t N>
void AddOptions(CLI::App* c, Arguments& args, const OptionRow (&rows)[N])
{
  for (const OptionRow& row : rows)
  {
    if (auto number = std::get_if<NumberArg Arguments::*>(&row.Field))
      AddNumber(c, row.Names, args.**number, row.Placeholder, row.Help);
    else if (auto text = std::get_if<std::string Arguments::*>(&row.Field))
      c->add_option(row.Names, args.**text, row.Help)->type_name(row.Placeholder);
    else
      c->add_flag(row.Names, args.*std::get<bool Arguments::*>(row.Field), row.Help);
  }
}

const OptionRow ReconstructRows[] = {
  { "--tr", &Arguments::Tr, "T|auto",
    "reconstruction threshold t_r > 1, 'inf' for all steps; auto (the default): where the Betti "
    "numbers are the most stable" },
  { "--tr-max", &Arguments::TrMax, "T",
    "write the exact cells (implies --exact) of every Threshold < T >= t_r, so any t_r <= T is "
    "a selection of the file; only those cells are drawn (t_r). From a cloud, also the cap below "
    "which the run is exact "
    "(4 when not given; 'inf': no cap): the patches that cannot matter below it are walked only "
    "when needed" },
  { "--tp", &Arguments::Tp, "P|auto",
    "persistence threshold t_p, 0 for none; auto (the default): 1.1 or 0, the more stable" },
  { "--exact", &Arguments::Exact, nullptr,
    "write the exact stable manifolds instead of Delaunay simplices on the samples: about 9 "
    "cells a sample on a surface, over points built on Voronoi edges, with cell data Step, "
    "Priority, Extension, Sponsor, CriticalValue and Multiplicity as well" },
  { "--profile", &Arguments::Profile, "P.csv",
    "write the profile of the t_r = inf run as CSV (from a cloud: its steps below the cap, "
    "see --tr-max)" },
  { "--topology-profile", &Arguments::TopologyProfile, "B.csv",
    "write the Betti numbers for every t_r up to --tr-max (4 when not given) as CSV: "
    "threshold,b0,b1,b2, one row per change" },
  { "--warn-window", &Arguments::WarnWindow, "F",
    "warn where the Betti numbers change for t_r in [t_r, F t_r): under-sampling (1.1; 1: none)" },
  { "--betti-max-cells", &Arguments::BettiMaxCells, "N",
    "from a stored complex (.vtm): skip the Betti numbers (with a warning) when the cells below "
    "the drawn t_r are more than N (4e6; 'inf' for no limit). A cloud's come from its Hasse "
    "diagram, at any size" },
  { "--no-betti", &Arguments::NoBetti, nullptr,
    "skip the Betti numbers, the topology profile and the warnings (on solids of millions of "
    "tetrahedra they cost about as much as the rest)" },
  { "--compact", &Arguments::Compact, nullptr,
    "the default output, accepted for compatibility; excludes --exact and --tr-max" },
  { "--jumps", &Arguments::Jumps, "K", "print the K largest jumps of the profile (tracking back)" },
  { "--timings", &Arguments::Timings, nullptr,
    "print the seconds of each phase (and, from a cloud, the patches deferred and walked late)" },
};

void ReconstructOptions(CLI::App* c, Arguments& args)
{
  OutputOption(c, args, "OUT.vtu", "the unstructured grid to write (.vtu)");
  AddOptions(c, args, ReconstructRows);
}

void DiagramOptions(CLI::App* c, Arguments& args)
{
  OutputOption(c, args, "PD.csv", "the diagram to write (.csv or .vtu)");
}

using Run = int (*)(const Arguments&);

struct Command
{
  const char* Name;
  const char* Summary;     // one line in 'flowrecon --help'
  const char* Synopsis;    // after "Usage: flowrecon NAME" in 'flowrecon NAME --help'
  const char* Description; // the paragraph under it
  void (*Options)(CLI::App*, Arguments&);
  Run Execute;
};

const Command Commands[] = {
  { "complex", "compute the flow complex of a point cloud, write it as .vtm",
    "INPUT -o OUT.vtm [options]",
    "Compute the flow complex of the distance function to the points of INPUT and\n"
    "write its blocks CriticalPoints, HasseDiagram, StableManifolds and\n"
    "UnstableManifolds to OUT.vtm (VTK XML multiblock, binary, compressed).",
    ComplexOptions, RunComplex },
  { "info", "print node counts, Euler characteristic, degeneracies, timings", "INPUT [options]",
    "Compute the flow complex of INPUT (or read a .vtm written by 'complex') and\n"
    "print the number of nodes of each index, the Euler characteristic\n"
    "n0 - n1 + n2 - n3 (always 1), the number of arcs, of input points and of\n"
    "merged duplicates, the perturbation applied to degenerate input, and the\n"
    "time of each phase.",
    ManifoldOptions, RunInfo },
  { "reconstruct", "reconstruct the sampled shape, write it as .vtu", "INPUT -o OUT.vtu [options]",
    "Compute the flow complex of INPUT (or read a .vtm written by 'complex'),\n"
    "simplify it with the persistence threshold t_p, grow the flow reconstruction\n"
    "with the reconstruction threshold t_r, and write it to OUT.vtu as Delaunay\n"
    "simplices on the input points: the triangles its stable manifolds' walks cross,\n"
    "the tetrahedra that flow into its maxima, its Gabriel edges and samples (about\n"
    "2 triangles a sample on a surface; cell data NodeId, Index, Threshold, Claims).\n"
    "--exact writes the exact stable manifolds instead (cell data Step, Priority,\n"
    "Threshold, Extension, Sponsor, NodeId, Index, CriticalValue, Multiplicity);\n"
    "--tr-max T writes them for every t_r up to T, each reconstruction their part\n"
    "with Threshold < t_r. Prints 'Betti numbers: b0 b1 b2' (over Z/2) of the\n"
    "reconstruction at t_r (the homology of the complex its exact cells span), then\n"
    "the compact output's own (field data BettiNumbers in its file; a warning if\n"
    "they differ), and one 'warning: under-sampled near (x, y, z): ...' line for\n"
    "each place where they change for a t_r just above the chosen one (see\n"
    "--warn-window).",
    ReconstructOptions, RunReconstruct },
  { "diagram", "write the persistence diagram of the flow complex",
    "INPUT -o PD.csv|PD.vtu [options]",
    "Compute the flow complex of INPUT (or read a .vtm written by 'complex') and\n"
    "write the persistence diagram of its filtration (equal to the alpha-complex\n"
    "diagram, in distances, not squared radii) to PD.csv (columns dimension,\n"
    "birth, death; 'inf' for essential classes) or PD.vtu (TTK's layout: a segment\n"
    "(birth, birth, 0)-(birth, death, 0) per pair, cell data PairIdentifier,\n"
    "PairType, Persistence, Birth, IsFinite, and the diagonal). Pairs of zero\n"
    "persistence are left out.",
    DiagramOptions, RunDiagram },
};

// The commands in `app`, their options bound to `args`.
std::map<CLI::App*, Run> DefineCommands(CLI::App& app, Arguments& args)
{
  std::map<CLI::App*, Run> commands;
  for (const Command& command : Commands)
  {
    CLI::App* c = AddCommand(
      app, command.Name, command.Summary, command.Synopsis, command.Description, args.Input);
    command.Options(c, args);
    AddNumber(c, "-j,--threads", args.Threads, "N",
      "threads for the flow complex (default: all cores; the output does not depend on it)");
    c->add_flag("-q,--quiet", args.Quiet, "no progress line on the terminal (and no summary line)");
    commands[c] = command.Execute;
  }
  return commands;
}

std::string Version()
{
  return std::string("flowrecon ") + FLOWRECON_VERSION + " (VTK " + vtkVersion::GetVTKVersion()
#ifdef FLOWRECON_CGAL_VERSION
    + ", CGAL " + FLOWRECON_CGAL_VERSION
#endif
    + ")";
}

} // namespace

int main(int argc, char* argv[])
{
  // Before anything else: the restarted process must see the same start.
  flowrecon::cli::RestartWithHugePages(argv);
  // First thing: a Ctrl-C during start-up (loading VTK can take a while on a
  // busy machine) must also end with the one-line message, not a bare kill.
  CatchInterrupt();
  try
  {
    CLI::App app;
    SetUpApp(
      app, "Flow-complex reconstruction of 3D compact sets (Cazals & Cohen-Steiner 2009).", Version());
    Arguments args;
    const std::map<CLI::App*, Run> commands = DefineCommands(app, args);
    CLI::App* command = ParseCommandLine(app, argc, argv);
    if (!command)
    {
      return 0; // the help or the version was printed
    }
    args.Command = command->get_name();
    // The flow complex runs on TBB; a limit holds for the rest of the run.
    std::unique_ptr<tbb::global_control> threads;
    if (args.Threads.Given)
    {
      long n = 0;
      if (!CLI::detail::lexical_cast(args.Threads.Text, n) || n < 1 || n > 4096)
      {
        throw Usage("option '--threads' needs an integer from 1 to 4096, not '" +
            args.Threads.Text + "'", args.Command);
      }
      threads = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(n));
    }
    // VTK's logger prints errors to stderr by itself, besides the output window.
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    flowrecon::RunMessages();
    return commands.at(command)(args);
  }
  catch (const Error& e)
  {
    std::cerr << "flowrecon: " << e.what() << "\n";
    if (!e.Help.empty())
    {
      std::cerr << "Try '" << e.Help << "' for more information.\n";
    }
    return e.ExitCode;
  }
  catch (const std::bad_alloc&)
  {
    std::cerr << "flowrecon: out of memory\n";
    return ExitFailure;
  }
  catch (const std::exception& e)
  {
    std::cerr << "flowrecon: " << e.what() << "\n";
    return ExitFailure;
  }
}
