// flowrecon: the command-line front end of the FlowRecon VTK filters.
//
//   flowrecon complex INPUT -o OUT.vtm [--no-stable] [--no-unstable] [--quiet]
//   flowrecon info    INPUT [--no-stable] [--no-unstable] [--quiet]
//   flowrecon reconstruct INPUT -o OUT.vtu [--tr T] [--tp P] [--profile P.csv] [--jumps K]
//                         [--tr-max T] [--topology-profile B.csv]
//   flowrecon diagram INPUT -o PD.csv|PD.vtu
// Every command also takes --threads N (TBB's limit for the flow complex).
//
// Every command is a function over parsed arguments listed in `Commands`, so
// new ones (reconstruct, diagram) are one function and one table entry each.
// Exit codes: 0 success, 1 bad input or failed computation, 2 usage error,
// 130 interrupted (Ctrl-C). Errors are one line on stderr; VTK's own messages
// are captured, never printed.

#include "FlowComplexConversion.h"
#include "FlowReconNames.h"
#include "CappedReconstruction.h"
#include "DeferredPatches.h"
#include "FlowComplexBuilder.h" // flowrecon diagram calls the core directly
#include "Persistence.h"
#include "PersistenceDiagramConversion.h"
#include "Reconstruction.h"
#include "ReconstructionConversion.h"
#include "Simplification.h"
#include "StableManifoldGeometry.h"
#include "vtkFlowComplex.h"
#include "vtkFlowComplexSimplification.h"
#include "vtkFlowReconstruction.h"
#include "vtkPointCloudReader.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include "vtkCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkLogger.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"
#include "vtkVersion.h"
#include "vtkXMLMultiBlockDataReader.h"
#include "vtkXMLMultiBlockDataWriter.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <unistd.h> // isatty, _exit

#ifndef FLOWRECON_VERSION
#define FLOWRECON_VERSION "unknown"
#endif

namespace
{

constexpr int ExitInputError = 1;
constexpr int ExitUsage = 2;
constexpr int ExitInterrupted = 130;

// A command-line mistake: reported with a hint to the help, exit code 2.
class UsageError : public std::runtime_error
{
public:
  UsageError(const std::string& message, std::string helpCommand = "flowrecon --help")
    : std::runtime_error(message)
    , HelpCommand(std::move(helpCommand))
  {
  }
  std::string HelpCommand;
};

// Bad input or a failed computation: one line, exit code 1.
class Failure : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

// Ctrl-C was pressed: exit code 130.
class Interrupted : public std::exception
{
};

// ---------------------------------------------------------------------------
// Ctrl-C: the first press asks the running filter to stop (the progress
// observer forwards the request); a second one exits at once.

std::atomic<bool> InterruptRequested{ false };

extern "C" void OnInterrupt(int)
{
  if (InterruptRequested.exchange(true))
  {
    _exit(ExitInterrupted);
  }
}

void ThrowIfInterrupted()
{
  if (InterruptRequested)
  {
    throw Interrupted();
  }
}

// ---------------------------------------------------------------------------
// VTK messages: kept instead of printed, so that a failure prints one line.

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
    if (!t.empty() && std::find(this->Warnings.begin(), this->Warnings.end(), t) == this->Warnings.end())
    {
      this->Warnings.push_back(t);
    }
  }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  void DisplayDebugText(const char*) override {}

  // "ERROR: In file.cxx, line 12\nvtkClass (0x...): text\n\n" -> "text".
  static std::string MessageText(const char* text)
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

  std::string FirstError;
  std::vector<std::string> Warnings;
};
vtkStandardNewMacro(CapturingOutputWindow);

vtkSmartPointer<CapturingOutputWindow> Messages;

void CaptureVtkMessages()
{
  // VTK's logger prints errors to stderr by itself, besides the output window.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  Messages = vtkSmartPointer<CapturingOutputWindow>::New();
  vtkOutputWindow::SetInstance(Messages);
}

// ---------------------------------------------------------------------------
// Progress: "\r[command] 42%  phase" on a terminal; also forwards Ctrl-C.

class ProgressLine : public vtkCommand
{
public:
  static ProgressLine* New() { return new ProgressLine; }

  void Execute(vtkObject* caller, unsigned long, void* callData) override
  {
    auto* algorithm = vtkAlgorithm::SafeDownCast(caller);
    if (InterruptRequested && algorithm)
    {
      algorithm->SetAbortExecute(1);
    }
    if (!this->Show || !algorithm || !callData)
    {
      return;
    }
    this->Print(*static_cast<double*>(callData), algorithm->GetProgressText());
  }

  // The same line for the core's progress, which also polls for Ctrl-C.
  flowrecon::Progress Core()
  {
    flowrecon::Progress progress;
    progress.Report = [this](double fraction, const char* phase) {
      if (this->Show)
      {
        this->Print(fraction, phase);
      }
    };
    progress.ShouldAbort = []() { return InterruptRequested.load(); };
    return progress;
  }

  void Print(double fraction, const char* phase)
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

  // Ends the progress line, if one was drawn.
  void Finish()
  {
    if (!this->Last.empty())
    {
      std::fputc('\n', stderr);
      this->Last.clear();
    }
  }

  std::string Label;
  bool Show = false;

private:
  std::string Last;
};

// ---------------------------------------------------------------------------
// Command table and argument parsing.

struct Option
{
  const char* Long;  // "--output"
  const char* Short; // "-o" or nullptr
  const char* Value; // placeholder of its value ("OUT.vtm"), nullptr for a flag
  const char* Help;
};

struct Arguments
{
  std::vector<std::string> Inputs;
  std::map<std::string, std::string> Values; // by long name, flags map to ""
  bool Has(const char* name) const { return this->Values.count(name) > 0; }
};

struct Command
{
  const char* Name;
  const char* Summary;     // one line in 'flowrecon --help'
  const char* Description; // paragraph in 'flowrecon NAME --help'
  const char* Synopsis;    // after "flowrecon NAME"
  std::vector<Option> Options;
  int (*Run)(const Arguments&);
};

const Option QuietOption{ "--quiet", "-q", nullptr,
  "no progress line on the terminal (and no summary line)" };
const Option ThreadsOption{ "--threads", "-j", "N",
  "threads for the flow complex (default: all cores; the output does not depend on it)" };
const Option NoStableOption{ "--no-stable", nullptr, nullptr,
  "skip the triangulated stable manifolds of index-2 and index-3 nodes" };
const Option MaxCellsOption{ "--max-cells", nullptr, "N",
  "draw at most N stable-manifold cells, in order of critical value; 'inf' for all (2e6)" };
const Option NoUnstableOption{ "--no-unstable", nullptr, nullptr,
  "skip the polylines of the unstable manifolds" };

int RunComplex(const Arguments& args);
int RunInfo(const Arguments& args);
int RunReconstruct(const Arguments& args);
int RunDiagram(const Arguments& args);

const std::vector<Command>& Commands()
{
  static const std::vector<Command> commands = {
    { "complex", "compute the flow complex of a point cloud, write it as .vtm",
      "Compute the flow complex of the distance function to the points of INPUT and\n"
      "write its blocks CriticalPoints, HasseDiagram, StableManifolds and\n"
      "UnstableManifolds to OUT.vtm (VTK XML multiblock, binary, compressed).",
      "INPUT -o OUT.vtm [options]",
      { { "--output", "-o", "OUT.vtm", "the multiblock file to write (.vtm)" }, NoStableOption,
        MaxCellsOption, NoUnstableOption, ThreadsOption, QuietOption },
      RunComplex },
    { "info", "print node counts, Euler characteristic, degeneracies, timings",
      "Compute the flow complex of INPUT (or read a .vtm written by 'complex') and\n"
      "print the number of nodes of each index, the Euler characteristic\n"
      "n0 - n1 + n2 - n3 (always 1), the number of arcs, of input points and of\n"
      "merged duplicates, the perturbation applied to degenerate input, and the\n"
      "time of each phase.",
      "INPUT [options]", { NoStableOption, NoUnstableOption, ThreadsOption, QuietOption }, RunInfo },
    { "reconstruct", "reconstruct the sampled shape, write it as .vtu",
      "Compute the flow complex of INPUT (or read a .vtm written by 'complex'),\n"
      "simplify it with the persistence threshold t_p, grow the flow reconstruction\n"
      "with the reconstruction threshold t_r, and write its cells (vertices, Gabriel\n"
      "edges, triangles, tetrahedra; cell data Step, Priority, Threshold, Extension,\n"
      "Sponsor, NodeId, Index, CriticalValue, Multiplicity) to OUT.vtu. Every\n"
      "reconstruction with a smaller t_r is its part with Threshold < t_r. Only the\n"
      "cells written are drawn, from a second Delaunay triangulation of the points.\n"
      "Prints 'Betti numbers: b0 b1 b2' (over Z/2) of the reconstruction at t_r: the\n"
      "homology of the complex its cells span (field data BettiNumbers in the file),\n"
      "and one 'warning: under-sampled near (x, y, z): ...' line for each place where\n"
      "they change for a t_r just above the chosen one (see --warn-window).",
      "INPUT -o OUT.vtu [options]",
      { { "--output", "-o", "OUT.vtu", "the unstructured grid to write (.vtu)" },
        { "--tr", nullptr, "T", "reconstruction threshold t_r > 1, 'inf' for all steps (2)" },
        { "--tr-max", nullptr, "T", "write every cell with Threshold < T >= t_r, so any t_r <= T\n"
          "is a selection of the file; only those cells are drawn (t_r). From a cloud, also\n"
          "the cap below which the run is exact (4 when not given; 'inf': no cap): the\n"
          "patches that cannot matter below it are walked only when needed" },
        { "--tp", nullptr, "P", "persistence threshold t_p, 0 for none (1.1)" },
        { "--profile", nullptr, "P.csv", "write the profile of the t_r = inf run as CSV (from a\n"
          "cloud: its steps below the cap, see --tr-max)" },
        { "--topology-profile", nullptr, "B.csv", "write the Betti numbers for every t_r up to\n"
          "--tr-max (4 when not given) as CSV: threshold,b0,b1,b2, one row per change" },
        { "--warn-window", nullptr, "F", "warn where the Betti numbers change for a t_r in\n"
          "[t_r, F t_r): an under-sampled region (1.1; 1 for none)" },
        { "--betti-max-cells", nullptr, "N", "skip the Betti numbers (with a warning) when the\n"
          "cells below the drawn t_r are more than N (4e6, about 20 s; 'inf' for no limit)" },
        { "--no-betti", nullptr, nullptr, "skip the Betti numbers, the topology profile and the\n"
          "warnings (on solids of millions of tetrahedra they cost about as much as the rest)" },
        { "--jumps", nullptr, "K", "print the K largest jumps of the profile (tracking back)" },
        { "--timings", nullptr, nullptr, "print the seconds of each phase (and, from a cloud,\n"
          "the patches deferred and walked late)" }, ThreadsOption,
        QuietOption },
      RunReconstruct },
    { "diagram", "write the persistence diagram of the flow complex",
      "Compute the flow complex of INPUT (or read a .vtm written by 'complex') and\n"
      "write the persistence diagram of its filtration (equal to the alpha-complex\n"
      "diagram, in distances, not squared radii) to PD.csv (columns dimension,\n"
      "birth, death; 'inf' for essential classes) or PD.vtu (TTK's layout: a segment\n"
      "(birth, birth, 0)-(birth, death, 0) per pair, cell data PairIdentifier,\n"
      "PairType, Persistence, Birth, IsFinite, and the diagonal). Pairs of zero\n"
      "persistence are left out.",
      "INPUT -o PD.csv|PD.vtu [options]",
      { { "--output", "-o", "PD.csv", "the diagram to write (.csv or .vtu)" }, ThreadsOption,
        QuietOption },
      RunDiagram },
  };
  return commands;
}

const char* const InputHelp =
  "INPUT: .xyz .txt .pts (x y z per line, extra columns ignored), .csv, .off, .ply, .obj,\n"
  "       legacy .vtk, VTK XML (.vtp .vtu .vts .vtr .vti .vtm ...): the points are used.\n";

void PrintHelp(std::ostream& os)
{
  os << "Usage: flowrecon COMMAND [options] INPUT\n\n"
        "Flow-complex reconstruction of 3D compact sets (Cazals & Cohen-Steiner 2009).\n\n"
        "Commands:\n";
  for (const Command& command : Commands())
  {
    os << "  " << std::left << std::setw(13) << command.Name << command.Summary << "\n";
  }
  os << "\nOptions:\n"
        "  -h, --help     show this help; 'flowrecon COMMAND --help' for a command\n"
        "  --version      print the version\n\n"
     << InputHelp
     << "\nExit status: 0 success, 1 bad input or failed computation, 2 usage error,\n"
        "130 interrupted.\n";
}

void PrintCommandHelp(const Command& command, std::ostream& os)
{
  os << "Usage: flowrecon " << command.Name << " " << command.Synopsis << "\n\n"
     << command.Description << "\n\nOptions:\n";
  for (const Option& option : command.Options)
  {
    std::string names = option.Short ? std::string(option.Short) + ", " : "    ";
    names += option.Long;
    if (option.Value)
    {
      names += std::string(" ") + option.Value;
    }
    os << "  " << std::left << std::setw(24) << names << option.Help << "\n";
  }
  os << "  " << std::left << std::setw(24) << "-h, --help"
     << "show this help\n\n"
     << InputHelp;
}

// Parses the arguments after the command name; returns false if help was shown.
bool ParseArguments(const Command& command, const std::vector<std::string>& argv, Arguments& args)
{
  const std::string help = std::string("flowrecon ") + command.Name + " --help";
  bool optionsEnded = false;
  for (std::size_t i = 0; i < argv.size(); ++i)
  {
    const std::string& arg = argv[i];
    if (optionsEnded || arg.size() < 2 || arg[0] != '-')
    {
      args.Inputs.push_back(arg);
      continue;
    }
    if (arg == "--")
    {
      optionsEnded = true;
      continue;
    }
    if (arg == "-h" || arg == "--help")
    {
      PrintCommandHelp(command, std::cout);
      return false;
    }
    // "--name=value" or "--name value" / "-n value".
    const std::size_t equal = arg.rfind("--", 0) == 0 ? arg.find('=') : std::string::npos;
    const std::string name = arg.substr(0, equal);
    const auto option = std::find_if(command.Options.begin(), command.Options.end(),
      [&name](const Option& o) { return name == o.Long || (o.Short && name == o.Short); });
    if (option == command.Options.end())
    {
      throw UsageError("unknown option '" + name + "' for '" + command.Name + "'", help);
    }
    if (!option->Value)
    {
      if (equal != std::string::npos)
      {
        throw UsageError("option '" + name + "' takes no value", help);
      }
      args.Values[option->Long] = "";
    }
    else if (equal != std::string::npos)
    {
      args.Values[option->Long] = arg.substr(equal + 1);
    }
    else if (i + 1 < argv.size())
    {
      args.Values[option->Long] = argv[++i];
    }
    else
    {
      throw UsageError("option '" + name + "' needs a value (" + option->Value + ")", help);
    }
  }
  if (args.Inputs.empty())
  {
    throw UsageError(std::string("'") + command.Name + "' needs an INPUT file", help);
  }
  if (args.Inputs.size() > 1)
  {
    throw UsageError("unexpected argument '" + args.Inputs[1] + "'", help);
  }
  return true;
}

// ---------------------------------------------------------------------------
// Pipelines.

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string ExtensionOf(const std::string& path)
{
  return Lower(std::filesystem::path(path).extension().string());
}

// The CriticalPoints block of a flow complex (it carries the report in its
// field data), or nullptr if `data` is not one.
vtkDataObject* CriticalPointsBlock(vtkDataObject* data)
{
  vtkDataObject* block = flowrecon::NamedBlock(vtkMultiBlockDataSet::SafeDownCast(data),
    vtkFlowComplex::BlockName(vtkFlowComplex::CRITICAL_POINTS));
  return block && block->GetFieldData()->GetArray(flowrecon::names::NodeCountByIndex) ? block : nullptr;
}

// A .vtm written by 'complex', or nullptr when `file` is a point cloud. The
// point cloud reader runs first: it rejects corrupt files VTK would crash on.
vtkSmartPointer<vtkMultiBlockDataSet> LoadStoredFlowComplex(const std::string& file)
{
  if (ExtensionOf(file) != ".vtm")
  {
    return nullptr;
  }
  vtkNew<vtkPointCloudReader> check;
  check->SetFileName(file.c_str());
  if (!check->GetExecutive()->Update())
  {
    throw Failure(check->GetErrorMessage());
  }
  vtkNew<vtkXMLMultiBlockDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkSmartPointer<vtkMultiBlockDataSet> data =
    vtkMultiBlockDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  return CriticalPointsBlock(data) ? data : nullptr;
}

struct FlowComplexOptions
{
  bool Stable = true;
  vtkIdType MaxCells = 2000000; // -1: all
  bool Unstable = true;
  bool Quiet = false;
  std::string Label;
};

double NumberOption(const Arguments& args, const char* name, double fallback, const char* command);

FlowComplexOptions CommonOptions(const Arguments& args, const char* label)
{
  FlowComplexOptions options;
  options.Stable = !args.Has("--no-stable");
  if (args.Has("--max-cells"))
  {
    const double cells = NumberOption(args, "--max-cells", 0, label);
    if (!(cells >= 0) || (cells != std::floor(cells) && !std::isinf(cells)))
    {
      throw UsageError("option '--max-cells' needs a whole number >= 0 or 'inf'",
        std::string("flowrecon ") + label + " --help");
    }
    options.MaxCells = std::isinf(cells) || cells >= 9e18 ? -1 : static_cast<vtkIdType>(cells);
  }
  options.Unstable = !args.Has("--no-unstable");
  options.Quiet = args.Has("--quiet");
  options.Label = label;
  return options;
}

// Runs `filter` (already connected) with the progress line; throws on failure.
void RunFilter(vtkAlgorithm* filter, const std::string& input, const FlowComplexOptions& options,
  const char* what)
{
  vtkNew<ProgressLine> progress;
  progress->Label = options.Label;
  progress->Show = !options.Quiet && isatty(2);
  filter->AddObserver(vtkCommand::ProgressEvent, progress);
  Messages->FirstError.clear();
  const int ok = filter->GetExecutive()->Update();
  progress->Finish();
  ThrowIfInterrupted();
  if (!ok)
  {
    throw Failure(input + ": " +
      (Messages->FirstError.empty() ? std::string(what) + " failed" : Messages->FirstError));
  }
}

// Reads the point cloud `file` and computes its flow complex.
vtkSmartPointer<vtkMultiBlockDataSet> ComputeFlowComplex(
  const std::string& file, const FlowComplexOptions& options)
{
  vtkNew<vtkPointCloudReader> reader;
  reader->SetFileName(file.c_str());
  if (!reader->GetExecutive()->Update())
  {
    throw Failure(reader->GetErrorMessage());
  }
  ThrowIfInterrupted();

  vtkNew<vtkFlowComplex> filter;
  filter->SetInputConnection(reader->GetOutputPort());
  filter->SetComputeStableManifolds(options.Stable);
  filter->SetMaximumStableManifoldCells(options.MaxCells);
  filter->SetComputeUnstableManifolds(options.Unstable);
  // complex, diagram and info give the whole Hasse diagram; reconstruct of a
  // cloud defers patches by itself (CappedReconstruction).
  filter->SetDeferPatchesAbove(0);
  RunFilter(filter, file, options, "flow complex computation");
  auto* output = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  if (!output || output->GetNumberOfBlocks() == 0)
  {
    throw Failure(file + ": flow complex computation failed");
  }
  return output;
}

// ---------------------------------------------------------------------------
// Commands.

template <class Writer>
void WriteXML(vtkDataObject* data, const std::string& output);

int RunComplex(const Arguments& args)
{
  const std::string& input = args.Inputs[0];
  if (!args.Has("--output"))
  {
    throw UsageError("'complex' needs an output file: -o OUT.vtm", "flowrecon complex --help");
  }
  const std::string output = args.Values.at("--output");
  if (ExtensionOf(output) != ".vtm")
  {
    throw UsageError(
      "the output file must have the .vtm extension: '" + output + "'", "flowrecon complex --help");
  }
  const std::filesystem::path directory = std::filesystem::path(output).parent_path();
  std::error_code error;
  if (!directory.empty() && !std::filesystem::is_directory(directory, error))
  {
    throw Failure(output + ": directory '" + directory.string() + "' does not exist");
  }
  if (LoadStoredFlowComplex(input))
  {
    throw Failure(input + ": already a flow complex (use 'flowrecon info' to inspect it)");
  }
  const FlowComplexOptions options = CommonOptions(args, "complex");
  vtkSmartPointer<vtkMultiBlockDataSet> complex = ComputeFlowComplex(input, options);

  WriteXML<vtkXMLMultiBlockDataWriter>(complex, output);
  if (!options.Quiet)
  {
    vtkFieldData* fd = CriticalPointsBlock(complex)->GetFieldData();
    vtkDataArray* counts = fd->GetArray(flowrecon::names::NodeCountByIndex);
    std::cout << output << ": nodes by index " << static_cast<long long>(counts->GetComponent(0, 0))
              << " " << static_cast<long long>(counts->GetComponent(0, 1)) << " "
              << static_cast<long long>(counts->GetComponent(0, 2)) << " "
              << static_cast<long long>(counts->GetComponent(0, 3)) << ", "
              << static_cast<long long>(
                   fd->GetArray("ArcCount") ? fd->GetArray("ArcCount")->GetComponent(0, 0) : 0)
              << " arcs\n";
  }
  return 0;
}

// One value of a field data array as text (`decimals` >= 0: fixed notation);
// "unknown" if the array is absent.
std::string Field(vtkFieldData* fd, const char* name, int component = 0, int decimals = -1)
{
  vtkDataArray* array = fd->GetArray(name);
  if (!array || array->GetNumberOfTuples() < 1 || component >= array->GetNumberOfComponents())
  {
    return "unknown";
  }
  std::ostringstream os;
  const double value = array->GetComponent(0, component);
  if (decimals >= 0)
  {
    os << std::fixed << std::setprecision(decimals) << value;
  }
  else if (value == std::floor(value) && std::fabs(value) < 1e15)
  {
    os << static_cast<long long>(value); // counts: 1000000, not 1e+06
  }
  else
  {
    os << value;
  }
  return os.str();
}

int RunInfo(const Arguments& args)
{
  const std::string& input = args.Inputs[0];
  vtkSmartPointer<vtkMultiBlockDataSet> complex = LoadStoredFlowComplex(input);
  const bool stored = complex != nullptr;
  if (!stored)
  {
    FlowComplexOptions options = CommonOptions(args, "info");
    options.Stable = false; // info prints no geometry
    complex = ComputeFlowComplex(input, options);
  }
  vtkFieldData* fd = CriticalPointsBlock(complex)->GetFieldData();
  const std::string attempts = Field(fd, "PerturbationAttempts");
  std::ostringstream out;
  out << "input:                 " << input << (stored ? " (flow complex file)" : " (point cloud)")
      << "\n"
      << "input points:          " << Field(fd, "InputPointCount") << "\n"
      << "duplicates merged:     " << Field(fd, "DuplicatePointCount") << "\n"
      << "perturbed:             "
      << (attempts == "1" ? std::string("no")
                          : "yes (" + attempts + " attempts, magnitude " +
               Field(fd, "PerturbationMagnitude") + ")")
      << "\n"
      << "nodes by index:        " << Field(fd, flowrecon::names::NodeCountByIndex, 0) << " "
      << Field(fd, flowrecon::names::NodeCountByIndex, 1) << " " << Field(fd, flowrecon::names::NodeCountByIndex, 2) << " "
      << Field(fd, flowrecon::names::NodeCountByIndex, 3)
      << " (n0 n1 n2 n3; finite nodes, the maximum at infinity is not counted)\n"
      << "Euler characteristic:  " << Field(fd, "EulerCharacteristic") << " (n0 - n1 + n2 - n3)\n"
      << "arcs:                  " << Field(fd, "ArcCount") << "\n"
      << "degeneracies:          " << Field(fd, "RightAngleCount") << " right angles, "
      << Field(fd, "ApexOnSphereCount") << " apex on sphere, " << Field(fd, "WalkTieCount")
      << " walk ties, " << Field(fd, "ExactFallbackCount") << " exact fallbacks\n"
      << "timings (s):          ";
  static const char* const phases[6] = { "Delaunay", flowrecon::names::CriticalPoints, flowrecon::names::StableManifolds,
    flowrecon::names::UnstableManifolds, "Assembly", "Total" };
  for (int k = 0; k < 6; ++k)
  {
    out << " " << phases[k] << " " << Field(fd, "Timings", k, 6);
  }
  out << "\n";
  std::cout << out.str();
  return 0;
}

// ---------------------------------------------------------------------------
// reconstruct and diagram.

// A number option: "inf" allowed; a bad value is a usage error.
double NumberOption(const Arguments& args, const char* name, double fallback, const char* command)
{
  if (!args.Has(name))
  {
    return fallback;
  }
  const std::string text = args.Values.at(name);
  const std::string lower = Lower(text);
  if (lower == "inf" || lower == "infinity")
  {
    return HUGE_VAL;
  }
  std::size_t used = 0;
  double value = 0;
  try
  {
    value = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  if (used == 0 || used != text.size() || std::isnan(value))
  {
    throw UsageError(std::string("option '") + name + "' needs a number, not '" + text + "'",
      std::string("flowrecon ") + command + " --help");
  }
  return value;
}

// The output path of -o, with one of `extensions`; its directory must exist.
std::string OutputOption(
  const Arguments& args, const char* command, const std::vector<std::string>& extensions)
{
  const std::string help = std::string("flowrecon ") + command + " --help";
  std::string list;
  for (const std::string& e : extensions)
  {
    list += (list.empty() ? "" : " or ") + e;
  }
  if (!args.Has("--output"))
  {
    throw UsageError(std::string("'") + command + "' needs an output file: -o OUT" +
        extensions.front(), help);
  }
  const std::string output = args.Values.at("--output");
  if (std::find(extensions.begin(), extensions.end(), ExtensionOf(output)) == extensions.end())
  {
    throw UsageError(
      "the output file must have the " + list + " extension: '" + output + "'", help);
  }
  const std::filesystem::path directory = std::filesystem::path(output).parent_path();
  std::error_code error;
  if (!directory.empty() && !std::filesystem::is_directory(directory, error))
  {
    throw Failure(output + ": directory '" + directory.string() + "' does not exist");
  }
  return output;
}

// The stored flow complex `file`, or the one computed from the point cloud.
vtkSmartPointer<vtkMultiBlockDataSet> FlowComplexOf(
  const std::string& file, const FlowComplexOptions& options)
{
  vtkSmartPointer<vtkMultiBlockDataSet> complex = LoadStoredFlowComplex(file);
  return complex ? complex : ComputeFlowComplex(file, options);
}

bool IsSimplified(vtkMultiBlockDataSet* complex)
{
  auto* points = vtkPolyData::SafeDownCast(flowrecon::NamedBlock(complex, flowrecon::names::CriticalPoints));
  return points && points->GetPointData()->GetArray(flowrecon::names::Cancelled);
}

// "PATH: cannot write (why)". VTK's writers report a full disk like any failed
// write; errno, reset before writing, tells it.
Failure WriteFailure(const std::string& path, const std::string& why)
{
  return Failure(
    path + ": cannot write (" + (errno == ENOSPC ? "no space left on device" : why) + ")");
}

// Writes `data` as VTK XML (appended raw binary, LZ4), removing it on Ctrl-C.
template <class Writer>
void WriteXML(vtkDataObject* data, const std::string& output)
{
  vtkNew<Writer> writer;
  writer->SetFileName(output.c_str());
  writer->SetInputData(data);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToLZ4();
  vtkNew<ProgressLine> abortOnly;
  writer->AddObserver(vtkCommand::ProgressEvent, abortOnly);
  Messages->FirstError.clear();
  errno = 0;
  const int written = writer->Write();
  std::error_code error;
  if (InterruptRequested)
  {
    std::filesystem::remove(output, error);
    throw Interrupted();
  }
  if (!written || writer->GetErrorCode() != 0)
  {
    throw WriteFailure(
      output, Messages->FirstError.empty() ? "unknown error" : Messages->FirstError);
  }
}

std::ofstream OpenText(const std::string& path)
{
  errno = 0;
  std::ofstream out(path);
  if (!out)
  {
    throw WriteFailure(path, errno ? std::strerror(errno) : "cannot open");
  }
  out << std::setprecision(17);
  return out;
}

// Text is written when the buffer fills and here: a full disk shows here.
void CloseText(std::ofstream& out, const std::string& path)
{
  out.close();
  if (!out)
  {
    throw WriteFailure(path, errno ? std::strerror(errno) : "write error");
  }
}

// The reconstruction of a point cloud through the core: the flow complex stays
// in the core's compact form (a VTK copy of its Hasse diagram would be most of
// the memory), and only the cells written are drawn. Fills `grid` and `profile`
// as vtkFlowReconstruction does (the tests compare the two paths) and `nodes`.
using PhaseTimes = std::vector<std::pair<std::string, double>>;

// Seconds since the previous call, appended to `times` under `phase`.
class PhaseClock
{
public:
  explicit PhaseClock(PhaseTimes& times)
    : Times(times)
  {
  }
  void operator()(const char* phase)
  {
    const auto now = std::chrono::steady_clock::now();
    this->Times.emplace_back(phase, std::chrono::duration<double>(now - this->Last).count());
    this->Last = now;
  }

private:
  PhaseTimes& Times;
  std::chrono::steady_clock::time_point Last = std::chrono::steady_clock::now();
};

void ReconstructCloud(const std::string& input, double tp, double tr, double twrite, double tdraw,
  double cap, double window, bool betti, flowrecon::Id bettiCells, const FlowComplexOptions& options, vtkUnstructuredGrid* grid, vtkTable* profile,
  vtkTable* topology, vtkPolyData* undersampling, std::vector<flowrecon::Node>& nodes,
  PhaseClock& clock, std::string& work)
{
  vtkNew<vtkPointCloudReader> reader;
  reader->SetFileName(input.c_str());
  if (!reader->GetExecutive()->Update())
  {
    throw Failure(reader->GetErrorMessage());
  }
  ThrowIfInterrupted();
  std::vector<flowrecon::Point3> samples;
  std::string error;
  if (!flowrecon::ExtractSamples(reader->GetOutputDataObject(0), samples, error))
  {
    throw Failure(input + ": " + error);
  }
  clock("reading");
  vtkNew<ProgressLine> line;
  line->Label = options.Label;
  line->Show = !options.Quiet && isatty(2);
  const flowrecon::Progress progress = line->Core();
  auto stage = [&](double from, double to) {
    flowrecon::Progress p = progress;
    p.Report = [&progress, from, to](double f, const char* phase) {
      progress.Report(from + (to - from) * f, phase);
    };
    return p;
  };
  try
  {
    flowrecon::BuildOptions build;
    build.StableManifolds = false;
    build.UnstableManifolds = false;
    const char* advice = "lower --tr (or --tr-max)";
    // Exact below the cap; the patches that cannot matter below it are walked
    // only when needed (DESIGN.md, "Cost follows the output").
    flowrecon::CappedReconstruction r;
    for (bool defer = true;; defer = false)
    {
      try
      {
        r = flowrecon::ReconstructBelow(samples, build, tp, cap, defer, stage(0, 0.7));
        clock("flow complex, simplification, reconstruction queue");
        flowrecon::DrawStableManifolds(samples, build,
          flowrecon::NodesToDraw(r.Complex.Nodes, r.Carriers, r.Run, tdraw), r.Complex,
          stage(0.7, 0.9), advice, &r.Cones, r.Triangulation.get());
        break;
      }
      catch (const flowrecon::Degenerate&)
      {
        if (!defer)
        {
          throw flowrecon::InputError("input too degenerate (a tie in a stable manifold)");
        }
      }
    }
    r.Triangulation.reset();
    work = "patches deferred: " + std::to_string(r.DeferredPatches) + " of " +
      std::to_string(r.Complex.CountByIndex()[2]) + ", walked late: " + std::to_string(r.WalkedLate) +
      ", owners found by replays: " + std::to_string(r.ReplayedOwners);
    {
      const flowrecon::Timings& t = r.Complex.Time;
      std::ostringstream phases;
      phases << std::fixed << std::setprecision(3) << "\nflow complex (s): Delaunay " << t.Delaunay
             << "; critical points " << t.CriticalPoints << "; stable manifolds "
             << t.StableManifolds << "; unstable manifolds " << t.UnstableManifolds
             << "; assembly " << t.Assembly << "; then simplification "
             << r.SimplificationSeconds << "; reconstruction queue " << r.QueueSeconds << ";";
      work += phases.str();
    }
    flowrecon::FlowComplex& fc = r.Complex;
    const flowrecon::ReconstructionResult& run = r.Run;
    const std::vector<flowrecon::Id>& carriers = r.Carriers;
    clock("drawing");
    const flowrecon::CellsByNode triangles(fc.TriangleNode, fc.Nodes.size());
    const flowrecon::CellsByNode tetrahedra(fc.TetrahedronNode, fc.Nodes.size());
    std::vector<flowrecon::Bar> bars;
    std::vector<flowrecon::Id> cellNodes;
    std::string topologyError;
    try
    {
      if (!betti)
      {
        throw flowrecon::InputError("not asked for");
      }
      bars = flowrecon::CellBarcode(flowrecon::ReconstructionCells(fc, carriers, run, tdraw,
                                      triangles, tetrahedra, &cellNodes, bettiCells),
        stage(0.9, 0.95), bettiCells);
    }
    catch (const flowrecon::InputError& e)
    {
      topologyError = e.what(); // the reconstruction is still written
    }
    clock("Betti numbers");
    progress(0.95, "output");
    vtkNew<vtkPolyData> arrows;
    flowrecon::ReconstructionToVTK(
      fc, carriers, run, twrite, triangles, tetrahedra, grid, profile, arrows);
    if (topologyError.empty())
    {
      flowrecon::TopologyToVTK(bars, twrite, tdraw, grid, topology);
      flowrecon::UnderSamplingToVTK(
        flowrecon::TopologyChangesAbove(bars, tr, std::max(1.0, std::min(window, tdraw / tr))),
        cellNodes, fc, undersampling);
    }
    else if (betti)
    {
      std::cerr << "warning: no Betti numbers: " << topologyError << "\n";
    }
    nodes = std::move(fc.Nodes);
    clock("VTK output");
  }
  catch (const flowrecon::Aborted&)
  {
    line->Finish();
    throw Interrupted();
  }
  catch (const flowrecon::InputError& e)
  {
    line->Finish();
    throw Failure(input + ": " + e.what());
  }
  catch (const std::bad_alloc&)
  {
    line->Finish();
    throw Failure(input + ": out of memory reconstructing " + std::to_string(samples.size()) +
      " points; lower --tr, use --tp 0, or fewer points");
  }
  line->Finish();
}

// "Betti numbers: b0 b1 b2" at t_r (scripts read this line) from the topology
// profile, which holds for t_r in (Threshold_k, Threshold_k+1]; the profile as
// CSV when asked.
void ReportTopology(vtkTable* topology, double tr, const std::string& path, bool quiet)
{
  const vtkIdType rows = topology ? topology->GetNumberOfRows() : 0;
  if (rows == 0)
  {
    return; // a warning said why
  }
  vtkDataArray* columns[4];
  const char* names[4] = { flowrecon::names::Threshold, "b0", "b1", "b2" };
  for (int k = 0; k < 4; ++k)
  {
    columns[k] = vtkDataArray::SafeDownCast(topology->GetColumnByName(names[k]));
    if (!columns[k])
    {
      throw Failure(std::string("topology profile without column ") + names[k]);
    }
  }
  vtkIdType row = 0;
  while (row + 1 < rows && columns[0]->GetComponent(row + 1, 0) < tr)
  {
    ++row;
  }
  if (!quiet)
  {
    std::cout << "Betti numbers: " << static_cast<long long>(columns[1]->GetComponent(row, 0))
              << " " << static_cast<long long>(columns[2]->GetComponent(row, 0)) << " "
              << static_cast<long long>(columns[3]->GetComponent(row, 0)) << "\n";
  }
  if (!path.empty())
  {
    std::ofstream csv = OpenText(path);
    csv << "threshold,b0,b1,b2\n" << std::setprecision(17);
    for (vtkIdType r = 0; r < rows; ++r)
    {
      csv << columns[0]->GetComponent(r, 0);
      for (int k = 1; k < 4; ++k)
      {
        csv << "," << static_cast<long long>(columns[k]->GetComponent(r, 0));
      }
      csv << "\n";
    }
    CloseText(csv, path);
  }
}

// One line per place of the under-sampling warnings (vtkFlowReconstruction's
// port 4): changes of the same node, t_r and kind make one line ("2 holes
// close"); the nearest t_r first, at most 10 lines.
void ReportUnderSampling(vtkPolyData* warnings)
{
  const vtkIdType n = warnings ? warnings->GetNumberOfPoints() : 0;
  auto* pd = n > 0 ? warnings->GetPointData() : nullptr;
  vtkDataArray* threshold = pd ? pd->GetArray(flowrecon::names::Threshold) : nullptr;
  vtkDataArray* dimension = pd ? pd->GetArray(flowrecon::names::Dimension) : nullptr;
  vtkDataArray* change = pd ? pd->GetArray(flowrecon::names::Change) : nullptr;
  vtkDataArray* spacing = pd ? pd->GetArray(flowrecon::names::Spacing) : nullptr;
  vtkDataArray* node = pd ? pd->GetArray(flowrecon::names::NodeId) : nullptr;
  if (!threshold || !dimension || !change || !spacing || !node)
  {
    return;
  }
  // (t_r, node, dimension, change) -> first point and count, in point order.
  std::map<std::tuple<double, long long, int, int>, std::size_t> seen;
  std::vector<std::pair<vtkIdType, int>> lines;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const auto key = std::make_tuple(threshold->GetComponent(i, 0),
      static_cast<long long>(node->GetComponent(i, 0)),
      static_cast<int>(dimension->GetComponent(i, 0)), change->GetComponent(i, 0) > 0 ? 1 : 0);
    const auto it = seen.find(key);
    if (it == seen.end())
    {
      seen.emplace(key, lines.size());
      lines.emplace_back(i, 1);
    }
    else
    {
      ++lines[it->second].second;
    }
  }
  const char* what[2][4] = { { "parts join", "hole closes", "void fills", "cavity fills" },
    { "part appears", "hole opens", "void closes in", "cavity closes in" } };
  const char* many[2][4] = { { "parts join", "holes close", "voids fill", "cavities fill" },
    { "parts appear", "holes open", "voids close in", "cavities close in" } };
  const std::size_t shown = std::min<std::size_t>(lines.size(), 10);
  for (std::size_t k = 0; k < shown; ++k)
  {
    const vtkIdType i = lines[k].first;
    const int count = lines[k].second;
    double x[3];
    warnings->GetPoint(i, x);
    const int d = std::max(0, std::min(3, static_cast<int>(dimension->GetComponent(i, 0))));
    const int up = change->GetComponent(i, 0) > 0 ? 1 : 0;
    std::cerr << "warning: under-sampled near (" << x[0] << ", " << x[1] << ", " << x[2]
              << "): spacing " << spacing->GetComponent(i, 0) << "; at t_r "
              << threshold->GetComponent(i, 0) << " ";
    if (count == 1)
    {
      std::cerr << (d == 0 && up == 0 ? "" : "a ") << what[up][d] << "\n";
    }
    else
    {
      std::cerr << count << " " << many[up][d] << "\n";
    }
  }
  if (lines.size() > shown)
  {
    std::cerr << "warning: and " << (lines.size() - shown)
              << " more places where the topology changes just above t_r\n";
  }
}

// The path given to a CSV option ("" when absent), refused before the long
// computation when its directory does not exist.
std::string CsvOption(const Arguments& args, const char* option)
{
  if (!args.Has(option))
  {
    return std::string();
  }
  const std::string path = args.Values.at(option);
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  std::error_code error;
  if (!directory.empty() && !std::filesystem::is_directory(directory, error))
  {
    throw Failure(path + ": directory '" + directory.string() + "' does not exist");
  }
  return path;
}

int RunReconstruct(const Arguments& args)
{
  const char* help = "flowrecon reconstruct --help";
  const std::string& input = args.Inputs[0];
  const std::string output = OutputOption(args, "reconstruct", { ".vtu" });
  const double tr = NumberOption(args, "--tr", 2.0, "reconstruct");
  const double tp = NumberOption(args, "--tp", 1.1, "reconstruct");
  if (!(tr > 1))
  {
    throw UsageError("the reconstruction threshold --tr must be greater than 1", help);
  }
  if (!(tp >= 0) || std::isinf(tp))
  {
    throw UsageError("the persistence threshold --tp must be a finite number >= 0", help);
  }
  long jumps = 0;
  if (args.Has("--jumps"))
  {
    const double k = NumberOption(args, "--jumps", 0, "reconstruct");
    if (!(k >= 1) || k != std::floor(k) || std::isinf(k))
    {
      throw UsageError("option '--jumps' needs a positive integer", help);
    }
    jumps = static_cast<long>(k);
  }
  const std::string profilePath = CsvOption(args, "--profile");

  const double trmax = args.Has("--tr-max") ? NumberOption(args, "--tr-max", tr, "reconstruct") : tr;
  if (!(trmax >= tr))
  {
    throw UsageError("--tr-max must be at least the reconstruction threshold --tr", help);
  }
  const std::string topologyPath = CsvOption(args, "--topology-profile");
  // The file holds the cells below `trmax`; the Betti numbers of every t_r up
  // to `tdraw` come from one barcode of the family drawn below it.
  double window = 1.1;
  if (args.Has("--warn-window"))
  {
    window = NumberOption(args, "--warn-window", 1.1, "reconstruct");
    if (!(window >= 1) || std::isinf(window))
    {
      throw UsageError("--warn-window must be a finite number >= 1", help);
    }
  }
  const bool betti = !args.Has("--no-betti");
  // The homology of millions of tetrahedra costs about twice the rest: a
  // budget, above which the Betti numbers are skipped with a warning.
  flowrecon::Id bettiCells = 4000000;
  if (args.Has("--betti-max-cells"))
  {
    const double k = NumberOption(args, "--betti-max-cells", 4e6, "reconstruct");
    if (!(k >= 0) || (k != std::floor(k) && !std::isinf(k)))
    {
      throw UsageError("option '--betti-max-cells' needs a count >= 0 or 'inf'", help);
    }
    bettiCells = std::isinf(k) ? -1 : static_cast<flowrecon::Id>(k);
  }
  if (!betti && (args.Has("--topology-profile") || args.Has("--warn-window")))
  {
    throw UsageError("--no-betti excludes --topology-profile and --warn-window", help);
  }
  if (!betti)
  {
    window = 1;
  }
  // Drawn: what is written, what the profile shows, and the warnings' window.
  double tdraw = !topologyPath.empty() && !args.Has("--tr-max") ? std::max(tr, 4.0) : trmax;
  tdraw = std::max(tdraw, tr * window);
  FlowComplexOptions options = CommonOptions(args, "reconstruct");
  // The reconstruction draws the cells it writes by itself: the complex needs
  // only its Hasse diagram (DESIGN.md, "Cost follows the output").
  options.Stable = false;
  options.Unstable = false;
  vtkSmartPointer<vtkMultiBlockDataSet> complex = LoadStoredFlowComplex(input);
  vtkSmartPointer<vtkMultiBlockDataSet> simplified = complex;
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  vtkSmartPointer<vtkTable> profile;
  vtkSmartPointer<vtkTable> topology;
  vtkSmartPointer<vtkPolyData> undersampling;
  std::vector<flowrecon::Node> nodes; // for --jumps
  PhaseTimes times;
  PhaseClock clock(times);
  std::string work; // what the output-sensitive path did, for --timings
  if (!complex)
  {
    grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    profile = vtkSmartPointer<vtkTable>::New();
    topology = vtkSmartPointer<vtkTable>::New();
    undersampling = vtkSmartPointer<vtkPolyData>::New();
    // The cap of the output-sensitive reconstruction: every t_r a user would
    // try, as the profile shows them.
    const double cap = std::max(tdraw, args.Has("--tr-max") ? trmax : 4.0);
    ReconstructCloud(input, tp, tr, trmax, tdraw, cap, window, betti, bettiCells, options, grid, profile, topology,
      undersampling, nodes, clock, work);
  }
  else
  {
    if (IsSimplified(complex))
    {
      if (args.Has("--tp"))
      {
        throw Failure(input + ": already simplified; --tp applies to a flow complex only");
      }
    }
    else if (tp >= 1) // below 1 nothing is cancelled
    {
      vtkNew<vtkFlowComplexSimplification> simplification;
      simplification->SetInputData(complex);
      simplification->SetPersistenceThreshold(tp);
      RunFilter(simplification, input, options, "simplification");
      simplified = vtkMultiBlockDataSet::SafeDownCast(simplification->GetOutputDataObject(0));
    }
    vtkNew<vtkFlowReconstruction> reconstruction;
    reconstruction->SetInputData(simplified);
    reconstruction->SetMaximumThreshold(tdraw);
    reconstruction->SetUnderSamplingWindow(window);
    reconstruction->SetComputeTopology(betti);
    reconstruction->SetMaximumTopologyCells(bettiCells);
    if (trmax != tr)
    {
      // The warnings at t_r; then the file's family below T (a selection: the
      // queue and the drawing are cached).
      reconstruction->SetReconstructionThreshold(tr);
      RunFilter(reconstruction, input, options, "reconstruction");
      undersampling = vtkSmartPointer<vtkPolyData>::New();
      undersampling->DeepCopy(reconstruction->GetOutputDataObject(4));
    }
    reconstruction->SetReconstructionThreshold(trmax);
    RunFilter(reconstruction, input, options, "reconstruction");
    if (trmax == tr)
    {
      undersampling = vtkPolyData::SafeDownCast(reconstruction->GetOutputDataObject(4));
    }
    grid = vtkUnstructuredGrid::SafeDownCast(reconstruction->GetOutputDataObject(0));
    profile = vtkTable::SafeDownCast(reconstruction->GetOutputDataObject(1));
    topology = vtkTable::SafeDownCast(reconstruction->GetOutputDataObject(3));
    clock("flow complex file, simplification, reconstruction");
    for (const std::string& w : Messages ? Messages->Warnings : std::vector<std::string>())
    {
      std::cerr << "warning: " << w << "\n";
    }
    std::string error;
    flowrecon::FlowComplex stored;
    if (jumps > 0 && flowrecon::FromMultiBlock(simplified, stored, error))
    {
      nodes = std::move(stored.Nodes);
    }
  }
  WriteXML<vtkXMLUnstructuredGridWriter>(grid, output);
  clock("writing");
  if (args.Has("--timings"))
  {
    std::cout << "timings (s):";
    for (const auto& phase : times)
    {
      std::cout << " " << phase.first << " " << std::fixed << std::setprecision(3)
                << phase.second << ";";
    }
    std::cout << std::defaultfloat << "\n";
    if (!work.empty())
    {
      std::cout << work << "\n";
    }
  }

  const char* columns[5] = { flowrecon::names::Step, flowrecon::names::NodeId, flowrecon::names::Index, flowrecon::names::Priority, flowrecon::names::Threshold };
  vtkDataArray* column[5];
  for (int k = 0; k < 5; ++k)
  {
    column[k] = vtkDataArray::SafeDownCast(profile->GetColumnByName(columns[k]));
  }
  const vtkIdType steps = profile->GetNumberOfRows();
  if (!profilePath.empty())
  {
    std::ofstream csv = OpenText(profilePath);
    csv << "Step,NodeId,Index,Priority,Threshold\n";
    for (vtkIdType r = 0; r < steps; ++r)
    {
      csv << static_cast<long long>(column[0]->GetComponent(r, 0)) << ","
          << static_cast<long long>(column[1]->GetComponent(r, 0)) << ","
          << static_cast<int>(column[2]->GetComponent(r, 0)) << ","
          << column[3]->GetComponent(r, 0) << "," << column[4]->GetComponent(r, 0) << "\n";
    }
    CloseText(csv, profilePath);
  }
  vtkIdType kept = 0;
  while (kept < steps && column[4]->GetComponent(kept, 0) < tr)
  {
    ++kept;
  }
  if (!options.Quiet)
  {
    std::cout << output << ": " << grid->GetNumberOfCells() << " cells, " << kept << " of "
              << steps << " steps at t_r " << tr << "\n";
  }
  ReportTopology(topology, tr, topologyPath, options.Quiet);
  if (!options.Quiet)
  {
    ReportUnderSampling(undersampling);
  }
  if (jumps > 0)
  {
    // Paper §5.2: a jump of the profile is a step whose priority exceeds all
    // earlier ones; its node is where the sampling is poorest.
    std::vector<std::pair<double, vtkIdType>> rises;
    for (vtkIdType r = 1; r < steps; ++r)
    {
      const double rise = column[4]->GetComponent(r, 0) - column[4]->GetComponent(r - 1, 0);
      if (rise > 0)
      {
        rises.emplace_back(-rise, r);
      }
    }
    std::sort(rises.begin(), rises.end());
    std::cout << "largest jumps of the profile (step: threshold before -> after, node, index, "
                 "critical value, location):\n";
    for (std::size_t j = 0; j < rises.size() && static_cast<long>(j) < jumps; ++j)
    {
      const vtkIdType r = rises[j].second;
      const vtkIdType node = static_cast<vtkIdType>(column[1]->GetComponent(r, 0));
      const bool known = node >= 0 && node < static_cast<vtkIdType>(nodes.size());
      const flowrecon::Point3 x = known ? nodes[node].Location : flowrecon::Point3{ { 0, 0, 0 } };
      std::cout << "  step " << r << ": " << column[4]->GetComponent(r - 1, 0) << " -> "
                << column[4]->GetComponent(r, 0) << ", node " << node << ", index "
                << static_cast<int>(column[2]->GetComponent(r, 0)) << ", value "
                << (known ? nodes[node].Value : std::nan("")) << ", at (" << x[0] << ", "
                << x[1] << ", " << x[2] << ")\n";
    }
  }
  return 0;
}

int RunDiagram(const Arguments& args)
{
  const std::string& input = args.Inputs[0];
  const std::string output = OutputOption(args, "diagram", { ".csv", ".vtu" });
  FlowComplexOptions options = CommonOptions(args, "diagram");
  // Nodes and arcs suffice: a point cloud goes to the core directly (no manifold
  // geometry, no VTK round trip); a stored complex is read back.
  flowrecon::FlowComplex fc;
  if (vtkSmartPointer<vtkMultiBlockDataSet> stored = LoadStoredFlowComplex(input))
  {
    if (IsSimplified(stored))
    {
      throw Failure(input + ": simplified; the diagram needs the flow complex itself");
    }
    std::string error;
    if (!flowrecon::FromMultiBlock(stored, fc, error))
    {
      throw Failure(input + ": " + error);
    }
    try
    {
      // A complex saved from ParaView defers its far patches by default.
      flowrecon::WalkEveryDeferredPatch(
        fc, flowrecon::Progress(), "use the cloud itself, or fewer points");
    }
    catch (const flowrecon::InputError& e)
    {
      throw Failure(input + ": " + e.what());
    }
  }
  else
  {
    std::vector<flowrecon::Point3> samples;
    {
      vtkNew<vtkPointCloudReader> reader;
      reader->SetFileName(input.c_str());
      if (!reader->GetExecutive()->Update())
      {
        throw Failure(reader->GetErrorMessage());
      }
      ThrowIfInterrupted();
      std::string error;
      if (!flowrecon::ExtractSamples(reader->GetOutputDataObject(0), samples, error))
      {
        throw Failure(input + ": " + error);
      }
    }
    vtkNew<ProgressLine> line;
    line->Label = options.Label;
    line->Show = !options.Quiet && isatty(2);
    flowrecon::BuildOptions build;
    build.StableManifolds = false;
    build.UnstableManifolds = false;
    try
    {
      fc = flowrecon::BuildFlowComplex(samples, build, line->Core());
    }
    catch (const flowrecon::InputError& e)
    {
      line->Finish();
      throw Failure(input + ": " + e.what());
    }
    catch (const flowrecon::Aborted&)
    {
      line->Finish();
      throw Interrupted();
    }
    catch (const std::bad_alloc&)
    {
      line->Finish();
      throw;
    }
    catch (const std::exception& e)
    {
      line->Finish();
      throw Failure(input + ": flow complex construction failed: " + e.what());
    }
    line->Finish();
    ThrowIfInterrupted();
  }
  const std::vector<flowrecon::PersistencePair> pairs = flowrecon::DiagramPairs(fc);
  fc = flowrecon::FlowComplex();
  ThrowIfInterrupted();
  if (ExtensionOf(output) == ".csv")
  {
    // As ostream << setprecision(17) would write them (printf's %.17g), faster.
    std::ofstream csv = OpenText(output);
    csv << "dimension,birth,death\n";
    std::string text;
    char number[32];
    auto append = [&](double value) {
      const auto end = std::to_chars(number, number + sizeof number, value,
        std::chars_format::general, 17).ptr;
      text.append(number, end);
    };
    for (const auto& p : pairs)
    {
      text += std::to_string(p.Dimension);
      text += ',';
      append(p.BirthValue);
      text += ',';
      if (std::isinf(p.DeathValue))
      {
        text += "inf";
      }
      else
      {
        append(p.DeathValue);
      }
      text += '\n';
      if (text.size() > (1 << 20))
      {
        csv.write(text.data(), static_cast<std::streamsize>(text.size()));
        text.clear();
      }
    }
    csv.write(text.data(), static_cast<std::streamsize>(text.size()));
    CloseText(csv, output);
  }
  else
  {
    vtkNew<vtkUnstructuredGrid> grid;
    flowrecon::DiagramToVTK(pairs, grid);
    WriteXML<vtkXMLUnstructuredGridWriter>(grid.GetPointer(), output);
  }
  if (!options.Quiet)
  {
    long count[4] = { 0, 0, 0, 0 };
    for (const auto& p : pairs)
    {
      ++count[std::min(3, std::max(0, p.Dimension))];
    }
    std::cout << output << ": " << pairs.size() << " pairs (" << count[0] << " " << count[1]
              << " " << count[2] << " in dimensions 0 1 2)\n";
  }
  return 0;
}

} // namespace

int main(int argc, char* argv[])
{
  // First thing: a Ctrl-C during start-up (loading VTK can take a while on a
  // busy machine) must also end with the one-line message, not a bare kill.
  std::signal(SIGINT, OnInterrupt);
  const std::vector<std::string> argv1(argv + 1, argv + argc);
  try
  {
    if (argv1.empty())
    {
      throw UsageError("missing command");
    }
    const std::string& first = argv1[0];
    if (first == "-h" || first == "--help" || first == "help")
    {
      PrintHelp(std::cout);
      return 0;
    }
    if (first == "--version")
    {
      std::cout << "flowrecon " << FLOWRECON_VERSION << " (VTK " << vtkVersion::GetVTKVersion()
#ifdef FLOWRECON_CGAL_VERSION
                << ", CGAL " << FLOWRECON_CGAL_VERSION
#endif
                << ")\n";
      return 0;
    }
    const auto& commands = Commands();
    const auto command = std::find_if(
      commands.begin(), commands.end(), [&first](const Command& c) { return first == c.Name; });
    if (command == commands.end())
    {
      throw UsageError((first[0] == '-' ? "unknown option '" : "unknown command '") + first + "'");
    }
    Arguments args;
    if (!ParseArguments(*command, { argv1.begin() + 1, argv1.end() }, args))
    {
      return 0;
    }
    // The flow complex runs on TBB; a limit holds for the rest of the run.
    std::unique_ptr<tbb::global_control> threads;
    if (args.Has("--threads"))
    {
      const std::string& text = args.Values.at("--threads");
      char* end = nullptr;
      const long n = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || n < 1 || n > 4096)
      {
        throw UsageError("option '--threads' needs an integer from 1 to 4096, not '" + text + "'",
          std::string("flowrecon ") + command->Name + " --help");
      }
      threads = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(n));
    }
    CaptureVtkMessages();
    return command->Run(args);
  }
  catch (const UsageError& e)
  {
    std::cerr << "flowrecon: " << e.what() << "\nTry '" << e.HelpCommand
              << "' for more information.\n";
    return ExitUsage;
  }
  catch (const Failure& e)
  {
    std::cerr << "flowrecon: " << e.what() << "\n";
    return ExitInputError;
  }
  catch (const Interrupted&)
  {
    std::cerr << "flowrecon: aborted\n";
    return ExitInterrupted;
  }
  catch (const std::bad_alloc&)
  {
    std::cerr << "flowrecon: out of memory\n";
    return ExitInputError;
  }
  catch (const std::exception& e)
  {
    std::cerr << "flowrecon: " << e.what() << "\n";
    return ExitInputError;
  }
}
