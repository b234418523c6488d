// flowrecon reconstruct: from a cloud through the core (CloudReconstruction),
// from a stored complex through the filters; the same outputs, then reported.
#include "Commands.h"

#include "CliError.h"
#include "CloudReconstruction.h"
#include "FlowComplexConversion.h"
#include "FlowReconNames.h"
#include "MessageCapture.h"
#include "OutputFiles.h"
#include "PhaseClock.h"
#include "ReconstructionReport.h"
#include "vtkFlowComplexSimplification.h"
#include "vtkFlowReconstruction.h"

#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

namespace flowrecon::cli
{

namespace
{

// vtkFlowReconstruction's outputs (however made), and the nodes the profile names.
struct Reconstruction
{
  vtkSmartPointer<vtkUnstructuredGrid> Grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkSmartPointer<vtkTable> Profile = vtkSmartPointer<vtkTable>::New();
  vtkSmartPointer<vtkTable> Topology = vtkSmartPointer<vtkTable>::New();
  vtkSmartPointer<vtkPolyData> UnderSampling = vtkSmartPointer<vtkPolyData>::New();
  std::vector<Node> Nodes; // for --jumps
  std::string Work;        // what the cloud's path did, for --timings
};

// A point cloud, through the core (CloudReconstruction).
Reconstruction FromCloud(const std::string& input,
  const CloudReconstructionSettings& settings, const FlowComplexOptions& options,
  PhaseClock& clock)
{
  const std::vector<Point3> samples = ReadSamples(input);
  clock("reading");
  Reconstruction r;
  CloudReconstructionReport report;
  vtkSmartPointer<ProgressLine> line = ProgressLine::Make(options.Label, options.Quiet);
  CallCore(input, *line, "reconstruction",
    "out of memory reconstructing " + std::to_string(samples.size()) +
      " points; lower --tr, use --tp 0, or fewer points",
    [&]() {
      report = flowrecon::ReconstructCloud(samples, settings,
        { r.Grid, r.Profile, r.Topology, r.UnderSampling }, line->Core(),
        [&clock](const char* phase) { clock(phase); });
    });
  if (!report.TopologyError.empty() && settings.Topology)
  {
    std::cerr << "warning: no Betti numbers: " << report.TopologyError << "\n";
  }
  r.Nodes = std::move(report.Nodes);
  r.Work = std::move(report.Work);
  return r;
}

// A stored flow complex, through the filters.
Reconstruction FromComplex(const Arguments& args, vtkMultiBlockDataSet* complex,
  const CloudReconstructionSettings& settings, const FlowComplexOptions& options,
  PhaseClock& clock, bool nodes)
{
  const std::string& input = args.Input;
  vtkSmartPointer<vtkMultiBlockDataSet> simplified = complex;
  if (IsSimplified(complex))
  {
    if (args.Tp.Given)
    {
      throw Failure(input + ": already simplified; --tp applies to a flow complex only");
    }
  }
  else if (settings.PersistenceThreshold >= 1) // below 1 nothing is cancelled
  {
    vtkNew<vtkFlowComplexSimplification> simplification;
    simplification->SetInputData(complex);
    simplification->SetPersistenceThreshold(settings.PersistenceThreshold);
    RunFilter(simplification, input, options, "simplification");
    simplified = vtkMultiBlockDataSet::SafeDownCast(simplification->GetOutputDataObject(0));
  }
  vtkNew<vtkFlowReconstruction> reconstruction;
  reconstruction->SetInputData(simplified);
  reconstruction->SetMaximumThreshold(settings.DrawThreshold);
  reconstruction->SetUnderSamplingWindow(settings.UnderSamplingWindow);
  reconstruction->SetComputeTopology(settings.Topology);
  reconstruction->SetMaximumTopologyCells(settings.MaximumTopologyCells);
  Reconstruction r;
  const double tr = settings.ReconstructionThreshold;
  if (settings.OutputThreshold != tr)
  {
    // The warnings at t_r; then the file's family below T (a selection: the
    // queue and the drawing are cached).
    reconstruction->SetReconstructionThreshold(tr);
    RunFilter(reconstruction, input, options, "reconstruction");
    r.UnderSampling->DeepCopy(reconstruction->GetOutputDataObject(4));
  }
  reconstruction->SetReconstructionThreshold(settings.OutputThreshold);
  RunFilter(reconstruction, input, options, "reconstruction");
  if (settings.OutputThreshold == tr)
  {
    r.UnderSampling = vtkPolyData::SafeDownCast(reconstruction->GetOutputDataObject(4));
  }
  r.Grid = vtkUnstructuredGrid::SafeDownCast(reconstruction->GetOutputDataObject(0));
  r.Profile = vtkTable::SafeDownCast(reconstruction->GetOutputDataObject(1));
  r.Topology = vtkTable::SafeDownCast(reconstruction->GetOutputDataObject(3));
  clock("flow complex file, simplification, reconstruction");
  for (const std::string& w : VtkWarnings())
  {
    std::cerr << "warning: " << w << "\n";
  }
  std::string error;
  FlowComplex stored;
  if (nodes && FromMultiBlock(simplified, stored, error, true))
  {
    r.Nodes = std::move(stored.Nodes);
  }
  return r;
}

} // namespace

int RunReconstruct(const Arguments& args)
{
  const std::string& command = args.Command;
  const std::string output = OutputPath(args.Output, command, { ".vtu" });
  CloudReconstructionSettings settings;
  const double tr = settings.ReconstructionThreshold = Number(args.Tr, 2.0, command);
  const double tp = settings.PersistenceThreshold = Number(args.Tp, 1.1, command);
  if (!(tr > 1))
  {
    throw Usage("the reconstruction threshold --tr must be greater than 1", command);
  }
  if (!(tp >= 0) || std::isinf(tp))
  {
    throw Usage("the persistence threshold --tp must be a finite number >= 0", command);
  }
  const double jumps = Number(args.Jumps, 0, command);
  if (args.Jumps.Given && (!(jumps >= 1) || jumps != std::floor(jumps) || std::isinf(jumps)))
  {
    throw Usage("option '--jumps' needs a positive integer", command);
  }
  if (!args.Profile.empty())
  {
    RequireDirectory(args.Profile);
  }
  const double trmax = settings.OutputThreshold = Number(args.TrMax, tr, command);
  if (!(trmax >= tr))
  {
    throw Usage("--tr-max must be at least the reconstruction threshold --tr", command);
  }
  if (!args.TopologyProfile.empty())
  {
    RequireDirectory(args.TopologyProfile);
  }
  // The file holds the cells below `trmax`; the Betti numbers of every t_r up
  // to the drawn threshold come from one barcode of the family drawn below it.
  double window = Number(args.WarnWindow, 1.1, command);
  if (!(window >= 1) || std::isinf(window))
  {
    throw Usage("--warn-window must be a finite number >= 1", command);
  }
  settings.Topology = !args.NoBetti;
  // The homology of millions of tetrahedra costs about twice the rest: a
  // budget, above which the Betti numbers are skipped with a warning.
  settings.MaximumTopologyCells =
    CountOption(args, args.BettiMaxCells, 4000000, "a count >= 0 or 'inf'");
  if (args.NoBetti && (!args.TopologyProfile.empty() || args.WarnWindow.Given))
  {
    throw Usage("--no-betti excludes --topology-profile and --warn-window", command);
  }
  settings.UnderSamplingWindow = window = args.NoBetti ? 1 : window;
  // Drawn: what is written, what the profile shows, and the warnings' window.
  const double tdraw = settings.DrawThreshold = std::max(
    !args.TopologyProfile.empty() && !args.TrMax.Given ? std::max(tr, 4.0) : trmax, tr * window);
  // The cap of the output-sensitive reconstruction of a cloud: every t_r a user
  // would try, as the profile shows them.
  settings.Cap = std::max(tdraw, args.TrMax.Given ? trmax : 4.0);
  settings.Advice = "lower --tr (or --tr-max)";
  FlowComplexOptions options;
  options.Quiet = args.Quiet;
  options.Label = command;
  // The reconstruction draws the cells it writes by itself: the complex needs
  // only its Hasse diagram (DESIGN.md, "Cost follows the output").
  options.Stable = false;
  options.Unstable = false;
  vtkSmartPointer<vtkMultiBlockDataSet> complex = LoadStoredFlowComplex(args.Input);
  PhaseClock clock;
  const Reconstruction r = complex
    ? FromComplex(args, complex, settings, options, clock, args.Jumps.Given)
    : FromCloud(args.Input, settings, options, clock);
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  WriteXML(writer, r.Grid, output);
  clock("writing");
  if (args.Timings)
  {
    clock.Print(std::cout);
    std::cout << r.Work << (r.Work.empty() ? "" : "\n");
  }
  if (!args.Profile.empty())
  {
    WriteCsv(r.Profile,
      { names::Step, names::NodeId, names::Index, names::Priority, names::Threshold },
      "Step,NodeId,Index,Priority,Threshold", args.Profile);
  }
  if (!args.Quiet)
  {
    std::cout << output << ": " << r.Grid->GetNumberOfCells() << " cells, "
              << StepsBelow(r.Profile, tr) << " of " << r.Profile->GetNumberOfRows()
              << " steps at t_r " << tr << "\n";
  }
  // "Betti numbers: b0 b1 b2" at t_r (scripts read this line).
  std::array<long long, 3> betti;
  if (BettiNumbersAt(r.Topology, tr, betti))
  {
    if (!args.Quiet)
    {
      std::cout << "Betti numbers: " << betti[0] << " " << betti[1] << " " << betti[2] << "\n";
    }
    if (!args.TopologyProfile.empty())
    {
      WriteCsv(r.Topology, { names::Threshold, "b0", "b1", "b2" },
        "threshold,b0,b1,b2", args.TopologyProfile);
    }
  }
  if (!args.Quiet)
  {
    // The nearest t_r first, at most 10 lines.
    const std::vector<UnderSampledPlace> places = UnderSampledPlaces(r.UnderSampling);
    for (std::size_t k = 0; k < places.size() && k < 10; ++k)
    {
      std::cerr << "warning: " << Describe(places[k]) << "\n";
    }
    if (places.size() > 10)
    {
      std::cerr << "warning: and " << (places.size() - 10)
                << " more places where the topology changes just above t_r\n";
    }
  }
  if (args.Jumps.Given)
  {
    std::cout << "largest jumps of the profile (step: threshold before -> after, node, index, "
                 "critical value, location):\n";
    for (const ProfileJumpNode& j : LargestProfileJumps(r.Profile, static_cast<std::size_t>(jumps)))
    {
      const bool known = j.Node >= 0 && j.Node < static_cast<Id>(r.Nodes.size());
      const Point3 x = known ? r.Nodes[j.Node].Location : Point3{ { 0, 0, 0 } };
      std::cout << "  step " << j.Jump.Step << ": " << j.Jump.Before << " -> " << j.Jump.After
                << ", node " << j.Node << ", index " << j.Index << ", value "
                << (known ? r.Nodes[j.Node].Value : std::nan("")) << ", at (" << x[0] << ", "
                << x[1] << ", " << x[2] << ")\n";
    }
  }
  return 0;
}

} // namespace flowrecon::cli
