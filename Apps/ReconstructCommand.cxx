// flowrecon reconstruct: from a cloud through the core (CloudReconstruction),
// from a stored complex through the filters; the same outputs, then reported.
#include "Commands.h"

#include "CliError.h"
#include "CloudReconstruction.h"
#include "CompactConversion.h"
#include "FlowComplexConversion.h"
#include "FlowComplexFromVTK.h"
#include "FlowReconNames.h"
#include "VtkMessageCapture.h"
#include "OutputFiles.h"
#include "PhaseClock.h"
#include "ReconstructionReport.h"
#include "Retriangulation.h"
#include "TopologyConversion.h"
#include "vtkFlowComplexSimplification.h"
#include "vtkFlowReconstruction.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
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
  double Tr = 0;           // the t_r used
  double Limit = 0;        // where the topology profile's last row ends
  std::vector<double> Tps; // the t_p candidates (NaN: the stored file's)
  bool Automatic = false;  // Choice is set
  ThresholdChoice Choice;
  // The default (compact) output: the compact complex at t_r, each node's
  // Threshold (NaN when not in it), and the samples it is written over.
  CompactComplex Compact;
  std::vector<double> NodeThreshold;
  std::vector<Point3> Samples;
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
  r.Tr = report.ReconstructionThreshold;
  r.Limit = settings.Cap;
  r.Tps = settings.AutomaticPersistence ? settings.PersistenceCandidates
                                        : std::vector<double>{ settings.PersistenceThreshold };
  r.Automatic = report.Automatic;
  r.Choice = report.Choice;
  if (settings.Compact)
  {
    r.Compact = std::move(report.Compact);
    r.NodeThreshold = std::move(report.NodeThreshold);
    r.Samples = samples;
  }
  return r;
}

// The compact output from a stored complex (simplified or not: the same nodes and
// samples): the nodes of the written cells below t_r, walked again on the
// samples' triangulation (Retriangulation).
void CompactFromStored(
  vtkMultiBlockDataSet* complex, const std::string& input, Reconstruction& r, ThresholdChoice* rows = nullptr)
{
  FlowComplex stored;
  std::string error;
  if (!FromMultiBlock(complex, stored, error, true) || !ReadSamples(complex, stored, error))
  {
    throw Failure(input + ": " + error);
  }
  vtkDataArray* node = r.Grid->GetCellData()->GetArray(names::NodeId);
  vtkDataArray* threshold = r.Grid->GetCellData()->GetArray(names::Threshold);
  std::vector<Id> selected;
  r.NodeThreshold.assign(stored.Nodes.size(), std::nan(""));
  for (vtkIdType c = 0; node && threshold && c < r.Grid->GetNumberOfCells(); ++c)
  {
    const Id n = static_cast<Id>(node->GetComponent(c, 0));
    const double t = threshold->GetComponent(c, 0);
    if (t < r.Tr && n >= 0 && n < static_cast<Id>(stored.Nodes.size()))
    {
      selected.push_back(n);
      r.NodeThreshold[n] = t;
    }
  }
  vtkSmartPointer<ProgressLine> line = ProgressLine::Make(); // Ctrl-C only
  CallCore(input, *line, "compact output", "out of memory making the compact output", [&]() {
    const std::unique_ptr<Retriangulation> re =
      Retriangulation::OfStoredComplex(stored, line->Core(), "lower --tr");
    r.Compact = CompactReconstruction(*re, stored.Nodes, selected);
  });
  r.Samples.assign(stored.Points.begin(), stored.Points.begin() + stored.NumberOfInputPoints);
  if (rows)
  {
    // The cells' ids are the stored complex's samples: its Gabriel edges, not
    // the light block's (numbered as the input), give their gaps.
    CheckRows(*rows, stored.Nodes, stored.NumberOfInputPoints, r.Compact);
    CheckJoins(*rows, r.Samples, r.Compact);
  }
  if (r.Nodes.empty())
  {
    r.Nodes = std::move(stored.Nodes);
  }
}

// CheckFilled on a stored complex's reconstruction up to the cap (`grid`: its
// cells, below t_r those of the reconstruction at `tr`); returns Filled.
bool CheckFilledOnGrid(vtkUnstructuredGrid* grid, vtkMultiBlockDataSet* complex, double tr,
  ThresholdChoice& choice)
{
  FlowComplex stored;
  std::string error;
  // Answers with voids too: a solid around voids takes a window with more
  // (PreferSurface), as on a cloud.
  if (!grid || !FromMultiBlock(complex, stored, error, true) ||
    !ReadSamples(complex, stored, error))
  {
    return false;
  }
  std::set<long long> maxima;
  vtkDataArray* index = grid->GetCellData()->GetArray(names::Index);
  vtkDataArray* node = grid->GetCellData()->GetArray(names::NodeId);
  vtkDataArray* threshold = grid->GetCellData()->GetArray(names::Threshold);
  for (vtkIdType c = 0; index && node && threshold && c < grid->GetNumberOfCells(); ++c)
  {
    if (index->GetComponent(c, 0) == 3 && threshold->GetComponent(c, 0) < tr)
    {
      maxima.insert(static_cast<long long>(node->GetComponent(c, 0)));
    }
  }
  CheckFilled(choice, stored.Points, static_cast<Id>(maxima.size()));
  return choice.Filled;
}

// A stored flow complex, through the filters: one simplification per t_p
// candidate (none when the file is already simplified), the reconstruction
// of each up to the cap, and the choice made on their topology profiles.
Reconstruction FromComplex(const Arguments& args, vtkMultiBlockDataSet* complex,
  const CloudReconstructionSettings& settings, Id cellBudget, const FlowComplexOptions& options,
  PhaseClock& clock, bool nodes)
{
  const std::string& input = args.Input;
  const bool simplifiedFile = IsSimplified(complex);
  if (simplifiedFile && args.Tp.Given && args.Tp.Text != "auto")
  {
    throw Failure(input + ": already simplified; --tp applies to a flow complex only");
  }
  const bool automatic = settings.AutomaticReconstruction ||
    (settings.AutomaticPersistence && !simplifiedFile);
  std::vector<double> tps = simplifiedFile ? std::vector<double>{ std::nan("") }
    : settings.AutomaticPersistence       ? settings.PersistenceCandidates
                                          : std::vector<double>{ settings.PersistenceThreshold };
  std::vector<vtkSmartPointer<vtkMultiBlockDataSet>> simplified;
  std::vector<vtkSmartPointer<vtkFlowReconstruction>> runs;
  std::vector<std::vector<TopologyStep>> profiles;
  for (const double tp : tps)
  {
    vtkSmartPointer<vtkMultiBlockDataSet> s = complex;
    if (!std::isnan(tp) && tp >= 1) // below 1 nothing is cancelled
    {
      vtkNew<vtkFlowComplexSimplification> simplification;
      simplification->SetInputData(complex);
      simplification->SetPersistenceThreshold(tp);
      simplification->SetAutomaticPersistenceThreshold(false); // chosen below, as on a cloud
      // The Betti numbers of the reconstructions below, from the Hasse diagram.
      simplification->SetComputeTopology(settings.Topology);
      simplification->SetMaximumThreshold(automatic ? settings.Cap : settings.DrawThreshold);
      RunFilter(simplification, input, options, "simplification");
      s = vtkMultiBlockDataSet::SafeDownCast(simplification->GetOutputDataObject(0));
    }
    auto reconstruction = vtkSmartPointer<vtkFlowReconstruction>::New();
    reconstruction->SetInputData(s);
    reconstruction->SetAutomaticReconstructionThreshold(false); // chosen below
    reconstruction->SetMaximumThreshold(automatic ? settings.Cap : settings.DrawThreshold);
    reconstruction->SetUnderSamplingWindow(settings.UnderSamplingWindow);
    reconstruction->SetComputeTopology(settings.Topology);
    reconstruction->SetMaximumTopologyCells(cellBudget);
    reconstruction->SetReconstructionThreshold(
      settings.AutomaticReconstruction ? settings.Cap : settings.ReconstructionThreshold);
    if (automatic)
    {
      RunFilter(reconstruction, input, options, "reconstruction");
      profiles.push_back(TopologyRows(vtkTable::SafeDownCast(reconstruction->GetOutputDataObject(3))));
    }
    simplified.push_back(s);
    runs.push_back(reconstruction);
  }
  Reconstruction r;
  std::size_t pick = 0;
  double tr = settings.ReconstructionThreshold;
  if (automatic)
  {
    r.Automatic = true;
    r.Choice = settings.AutomaticReconstruction
      ? ChooseThresholds(profiles, settings.Cap)
      : ChoosePersistence(profiles, settings.ReconstructionThreshold, settings.Cap);
    pick = r.Choice.Candidate;
    if (settings.AutomaticReconstruction)
    {
      tr = r.Choice.ReconstructionThreshold;
      // As on a cloud: a surface filled in, and then a window with a void.
      vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(runs[pick]->GetOutputDataObject(0));
      CheckFilledOnGrid(grid, simplified[pick], tr, r.Choice);
      if (PreferSurface(r.Choice, profiles, settings.Cap))
      {
        pick = r.Choice.Candidate;
        tr = r.Choice.ReconstructionThreshold;
      }
    }
    // The light block, not the diagram: its points are the samples.
    const std::vector<Node> edges = GabrielEdgeNodes(complex);
    CheckFar(r.Choice, edges,
      static_cast<Id>(std::count_if(edges.begin(), edges.end(), [](const Node& n) { return n.Index == 0; })));
  }
  r.Tps = tps;
  r.Tr = tr;
  vtkFlowReconstruction* reconstruction = runs[pick];
  if (settings.AutomaticReconstruction && r.Choice.Short() && r.Choice.Window.To > tr)
  {
    // A short stable window: its end is where the topology changes next.
    reconstruction->SetUnderSamplingWindow(
      std::max(settings.UnderSamplingWindow, r.Choice.Window.To / tr * (1 + 1e-9)));
  }
  const double output = settings.AutomaticReconstruction ? std::max(settings.OutputThreshold, tr)
                                                         : settings.OutputThreshold;
  if (output != tr)
  {
    // The warnings at t_r; then the file's family below T (a selection: the
    // queue and the drawing are cached).
    reconstruction->SetReconstructionThreshold(tr);
    RunFilter(reconstruction, input, options, "reconstruction");
    r.UnderSampling->DeepCopy(reconstruction->GetOutputDataObject(4));
  }
  reconstruction->SetReconstructionThreshold(output);
  RunFilter(reconstruction, input, options, "reconstruction");
  if (output == tr)
  {
    r.UnderSampling = vtkPolyData::SafeDownCast(reconstruction->GetOutputDataObject(4));
  }
  r.Grid = vtkUnstructuredGrid::SafeDownCast(reconstruction->GetOutputDataObject(0));
  r.Profile = vtkTable::SafeDownCast(reconstruction->GetOutputDataObject(1));
  r.Topology = vtkTable::SafeDownCast(reconstruction->GetOutputDataObject(3));
  r.Limit = reconstruction->GetMaximumThreshold();
  clock("flow complex file, simplification, reconstruction");
  for (const std::string& w : RunMessages().Warnings())
  {
    std::cerr << "warning: " << w << "\n";
  }
  std::string error;
  FlowComplex stored;
  if (nodes && FromMultiBlock(simplified[pick], stored, error, true))
  {
    r.Nodes = std::move(stored.Nodes);
  }
  return r;
}

} // namespace

// The automatic range of t_r: the cap of the reconstruction, and where the
// topology profile is searched for its most stable Betti numbers.
constexpr double AutomaticCap = 5;

namespace
{

// What `reconstruct` is asked for, beyond the settings of the run.
struct Request
{
  CloudReconstructionSettings Settings;
  double Jumps = 0;  // --jumps
  Id CellBudget = 0; // --betti-max-cells
};

// The cap of the run, and the threshold below which nodes are drawn.
void SetCapAndDrawn(const Arguments& args, double trmax, bool automatic,
  CloudReconstructionSettings& settings)
{
  const double tr = settings.ReconstructionThreshold;
  if (settings.AutomaticReconstruction)
  {
    settings.Cap = std::max(AutomaticCap, trmax);
    settings.DrawThreshold = std::max(trmax, 1.0); // raised to the chosen t_r's needs
    return;
  }
  // Drawn: what is written, what the profile shows, and the warnings' window.
  const double tdraw = settings.DrawThreshold = std::max(
    !args.TopologyProfile.empty() && !args.TrMax.Given ? std::max(tr, 4.0) : trmax,
    tr * settings.UnderSamplingWindow);
  // The cap of the output-sensitive reconstruction of a cloud: every t_r a
  // user would try, as the profile shows them.
  settings.Cap = std::max(tdraw, args.TrMax.Given ? trmax : automatic ? AutomaticCap : 4.0);
}

// The options, checked in this order (the first error is the one reported).
Request ReadRequest(const Arguments& args)
{
  const std::string& command = args.Command;
  Request request;
  CloudReconstructionSettings& settings = request.Settings;
  settings.AutomaticReconstruction = IsAutomatic(args.Tr);
  settings.AutomaticPersistence = IsAutomatic(args.Tp);
  const bool automatic = settings.AutomaticReconstruction || settings.AutomaticPersistence;
  const double tr = settings.ReconstructionThreshold =
    settings.AutomaticReconstruction ? 2.0 : Number(args.Tr, 2.0, command);
  const double tp = settings.PersistenceThreshold =
    settings.AutomaticPersistence ? 1.1 : Number(args.Tp, 1.1, command);
  if (!(tr > 1))
  {
    throw Usage("the reconstruction threshold --tr must be greater than 1", command);
  }
  if (!(tp >= 0) || std::isinf(tp))
  {
    throw Usage("the persistence threshold --tp must be a finite number >= 0", command);
  }
  if (automatic && args.NoBetti)
  {
    throw Usage("--no-betti needs numbers for --tr and --tp: their automatic choice reads "
                "the topology",
      command);
  }
  const double jumps = request.Jumps = Number(args.Jumps, 0, command);
  if (args.Jumps.Given && (!(jumps >= 1) || jumps != std::floor(jumps) || std::isinf(jumps)))
  {
    throw Usage("option '--jumps' needs a positive integer", command);
  }
  if (!args.Profile.empty())
  {
    RequireDirectory(args.Profile);
  }
  const double trmax = settings.OutputThreshold =
    Number(args.TrMax, settings.AutomaticReconstruction ? 0 : tr, command);
  if (args.TrMax.Given && !(trmax >= (settings.AutomaticReconstruction ? 1 : tr)))
  {
    throw Usage("--tr-max must be at least the reconstruction threshold --tr", command);
  }
  if (!args.TopologyProfile.empty())
  {
    RequireDirectory(args.TopologyProfile);
  }
  const double window = Number(args.WarnWindow, 1.1, command);
  if (!(window >= 1) || std::isinf(window))
  {
    throw Usage("--warn-window must be a finite number >= 1", command);
  }
  settings.Topology = !args.NoBetti;
  // A stored complex's Betti numbers come from its drawn cells: the homology
  // of millions of tetrahedra costs about twice the rest, hence a budget.
  request.CellBudget = CountOption(args, args.BettiMaxCells, 4000000, "a count >= 0 or 'inf'");
  if (args.NoBetti && (!args.TopologyProfile.empty() || args.WarnWindow.Given))
  {
    throw Usage("--no-betti excludes --topology-profile and --warn-window", command);
  }
  settings.UnderSamplingWindow = args.NoBetti ? 1 : window;
  SetCapAndDrawn(args, trmax, automatic, settings);
  settings.Advice = "lower --tr (or --tr-max)";
  // The compact output is the default; --tr-max's file is the exact family.
  if (args.Compact && (args.Exact || args.TrMax.Given))
  {
    throw Usage("--compact (the default) excludes --exact and --tr-max, which write the exact "
                "cells",
      command);
  }
  settings.Compact = !args.Exact && !args.TrMax.Given;
  return request;
}

// The summary line, then "Betti numbers: b0 b1 b2" at t_r (scripts read this
// line), the thresholds chosen and their warnings; the topology profile.
void ReportResult(const Arguments& args, const Reconstruction& r, const std::string& output,
  vtkIdType written, bool automaticTr, bool tpChosen, const std::vector<std::string>& choiceWarnings)
{
  if (!args.Quiet)
  {
    std::cout << output << ": " << written << " cells, "
              << StepsBelow(r.Profile, r.Tr) << " of " << r.Profile->GetNumberOfRows()
              << " steps at t_r " << r.Tr << "\n";
  }
  std::array<long long, 3> betti;
  if (!BettiNumbersAt(r.Topology, r.Tr, betti))
  {
    return;
  }
  if (!args.Quiet)
  {
    std::cout << "Betti numbers: " << betti[0] << " " << betti[1] << " " << betti[2] << "\n";
    if (r.Automatic)
    {
      std::cout << DescribeChoice(r.Choice, r.Tps, automaticTr, tpChosen) << "\n";
      for (const std::string& w : choiceWarnings)
      {
        std::cerr << "warning: " << w << "\n";
      }
    }
  }
  if (!args.TopologyProfile.empty())
  {
    WriteCsv(r.Topology, { names::Threshold, "b0", "b1", "b2" }, "threshold,b0,b1,b2",
      args.TopologyProfile);
  }
}

// The compact output: what it holds, its Betti numbers, and a warning when
// they are not the exact reconstruction's (without --no-betti).
void ReportCompact(const Reconstruction& r, bool topology)
{
  const CompactComplex& c = r.Compact;
  const std::array<Id, 4>& betti = c.Betti;
  std::cout << "compact output: " << c.Triangles.size() << " triangles, " << c.Tetrahedra.size()
            << " tetrahedra, " << c.Edges.size() << " edges, " << c.Vertices.size()
            << " samples, "
            << static_cast<double>(c.NumberOfCells()) /
      static_cast<double>(std::max<std::size_t>(1, r.Samples.size()))
            << " cells per sample; " << c.SharedTriangles << " triangles shared by two patches, "
            << c.RevisitedTriangles << " crossed twice by one walk, " << c.FilledVoids
            << " voids without a maximum filled\n";
  if (!topology)
  {
    return;
  }
  std::cout << "compact output's Betti numbers " << betti[0] << " " << betti[1] << " " << betti[2]
            << "\n";
  std::array<long long, 3> exact;
  if (BettiNumbersAt(r.Topology, r.Tr, exact) &&
    (exact[0] != betti[0] || exact[1] != betti[1] || exact[2] != betti[2]))
  {
    std::cerr << "warning: the compact output's Betti numbers " << betti[0] << " " << betti[1]
              << " " << betti[2] << " differ from the reconstruction's " << exact[0] << " "
              << exact[1] << " " << exact[2] << "\n";
  }
}

// The places where the topology changes just above t_r: the nearest t_r
// first, at most 10 lines.
void WarnUnderSampled(const Reconstruction& r)
{
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

// --jumps: the largest jumps of the profile, and the nodes that made them.
void PrintJumps(const Reconstruction& r, double jumps)
{
  std::cout << "largest jumps of the profile (step: threshold before -> after, node, index, "
               "critical value, location):\n";
  // Locations to 10^-5 of the nodes' extent, wherever the cloud sits.
  std::array<double, 3> lo{ { HUGE_VAL, HUGE_VAL, HUGE_VAL } }, hi{ { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL } };
  for (const Node& n : r.Nodes)
  {
    for (int k = 0; k < 3 && !n.IsInfinity(); ++k)
    {
      lo[k] = std::min(lo[k], n.Location[k]);
      hi[k] = std::max(hi[k], n.Location[k]);
    }
  }
  const double extent = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  for (const ProfileJumpNode& j : LargestProfileJumps(r.Profile, static_cast<std::size_t>(jumps)))
  {
    const bool known = j.Node >= 0 && j.Node < static_cast<Id>(r.Nodes.size());
    const Point3 x = known ? r.Nodes[j.Node].Location : Point3{ { 0, 0, 0 } };
    std::cout << "  step " << j.Jump.Step << ": " << j.Jump.Before << " -> " << j.Jump.After
              << ", node " << j.Node << ", index " << j.Index << ", value "
              << (known ? r.Nodes[j.Node].Value : std::nan("")) << ", at "
              << PlaceText(x, 1e-5 * extent) << "\n";
  }
}

// The default output: the compact complex at t_r over the input points, with
// the exact grid's field data of the answer (thresholds, their warnings,
// Topology) and its own Betti numbers (none with --no-betti).
vtkSmartPointer<vtkUnstructuredGrid> CompactOutput(const Reconstruction& r, bool topology)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  CompactToVTK(r.Compact, r.Samples, r.Nodes, r.NodeThreshold, r.Compact.Betti, grid);
  vtkFieldData* answer = r.Grid->GetFieldData();
  for (int k = 0; k < answer->GetNumberOfArrays(); ++k)
  {
    vtkAbstractArray* a = answer->GetAbstractArray(k);
    if (a->GetName() && std::string(a->GetName()) != names::BettiNumbers)
    {
      grid->GetFieldData()->AddArray(a);
    }
  }
  if (!topology)
  {
    grid->GetFieldData()->RemoveArray(names::BettiNumbers);
  }
  return grid;
}

} // namespace

int RunReconstruct(const Arguments& args)
{
  const std::string& command = args.Command;
  const std::string output = OutputPath(args.Output, command, { ".vtu" });
  const Request request = ReadRequest(args);
  const CloudReconstructionSettings& settings = request.Settings;
  FlowComplexOptions options;
  options.Quiet = args.Quiet;
  options.Label = command;
  // The reconstruction draws the cells it writes by itself: the complex needs
  // only its Hasse diagram (docs/design.md, "Cost follows the output").
  options.Stable = false;
  options.Unstable = false;
  vtkSmartPointer<vtkMultiBlockDataSet> complex = LoadStoredFlowComplex(args.Input);
  PhaseClock clock;
  Reconstruction r = complex
    ? FromComplex(args, complex, settings, request.CellBudget, options, clock, args.Jumps.Given)
    : FromCloud(args.Input, settings, options, clock);
  if (complex && settings.Compact)
  {
    // Its nodes are the simplified ones'; the side-by-side check as on a cloud.
    CompactFromStored(complex, args.Input, r, r.Automatic ? &r.Choice : nullptr);
    clock("compact output");
    if (r.Automatic)
    {
      CheckShallow(r.Choice, r.Compact.Tetrahedra); // as on a cloud
    }
  }
  else if (complex && r.Automatic &&
    (r.Choice.NeedsDepth() || r.Choice.NeedsRows() || r.Choice.NeedsJoins()))
  {
    // --exact of a solid answer: the compact tetrahedra of the same cells,
    // made for this measure only (as on a cloud).
    Reconstruction probe;
    probe.Grid = r.Grid;
    probe.Tr = r.Tr;
    try
    {
      CompactFromStored(complex, args.Input, probe, &r.Choice);
      CheckShallow(r.Choice, probe.Compact.Tetrahedra);
    }
    catch (const Error& e)
    {
      if (e.ExitCode == ExitInterrupted)
      {
        throw; // Ctrl-C stops the command, as anywhere else
      }
      std::cerr << "warning: the answer's cells on the samples are not made (no shallow-solid, side-by-side or long-join check): "
                << e.what() << "\n";
    }
    catch (const std::exception& e)
    {
      // Only a warning needed them: the exact output is still written.
      std::cerr << "warning: the answer's cells on the samples are not made (no shallow-solid, side-by-side or long-join check): "
                << e.what() << "\n";
    }
  }
  const bool tpChosen = settings.AutomaticPersistence && r.Tps.size() > 1;
  const std::vector<std::string> choiceWarnings = r.Automatic
    ? ChoiceWarnings(r.Choice, r.Tps, settings.AutomaticReconstruction, tpChosen)
    : std::vector<std::string>();
  if (r.Automatic)
  {
    ThresholdWarningsToVTK(choiceWarnings, r.Grid); // in the file, as in the filter's output
  }
  // The filter's line, if any, is at the file's threshold (--tr-max): this one
  // says what is printed, at t_r.
  TopologyTextToVTK(TopologyLine(r.Grid, r.Topology, r.UnderSampling, r.Tr, r.Limit,
                      settings.Topology ? "" : " (--no-betti)"),
    r.Grid, nullptr);
  vtkSmartPointer<vtkUnstructuredGrid> written = r.Grid;
  if (settings.Compact)
  {
    written = CompactOutput(r, settings.Topology);
    clock("compact output's VTK grid");
  }
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  WriteXML(writer, written, output);
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
  ReportResult(args, r, output, written->GetNumberOfCells(), settings.AutomaticReconstruction,
    tpChosen, choiceWarnings);
  if (settings.Compact && !args.Quiet)
  {
    ReportCompact(r, settings.Topology);
  }
  if (!args.Quiet)
  {
    WarnUnderSampled(r);
  }
  if (args.Jumps.Given)
  {
    PrintJumps(r, request.Jumps);
  }
  return 0;
}

} // namespace flowrecon::cli
