#include "vtkFlowReconstruction.h"

#include "CloudReconstruction.h" // ReconstructionPorts

#include "PipelinePorts.h"
#include "AutomaticThresholds.h"
#include "CompactConversion.h"
#include "CompactFamily.h"
#include "ContractArrays.h" // MakePoints
#include "CoreCall.h"
#include "DeferredReconstruction.h"
#include "FlowComplexConversion.h"
#include "FlowReconNames.h"
#include "MemoryGuard.h"
#include "ReconstructionConversion.h"
#include "ReconstructionReport.h"
#include "TopologyConversion.h"
#include "Retriangulation.h"
#include "Reconstruction.h"
#include "Simplification.h"
#include "StoredComplexTopology.h"
#include "StableManifoldGeometry.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <string>
#include <utility>

using flowrecon::Id;

namespace
{

/// What the input says of t_p: its value (0 without simplification), whether
/// it was chosen from the data, and the warnings of that choice.
struct InputPersistence
{
  double Threshold = 0;
  bool Chosen = false;
  std::vector<std::string> Warnings;
};

InputPersistence PersistenceOf(vtkMultiBlockDataSet* input)
{
  InputPersistence p;
  vtkFieldData* fd = input->GetFieldData();
  if (vtkDataArray* tp = fd->GetArray(flowrecon::names::UsedPersistenceThreshold))
  {
    p.Threshold = tp->GetNumberOfTuples() > 0 ? tp->GetComponent(0, 0) : 0;
  }
  vtkDataArray* chosen = fd->GetArray(flowrecon::names::ThresholdsChosen);
  p.Chosen = chosen && chosen->GetNumberOfTuples() > 1 && chosen->GetComponent(1, 0) != 0;
  if (auto* w = vtkStringArray::SafeDownCast(fd->GetAbstractArray(flowrecon::names::ThresholdWarnings)))
  {
    for (vtkIdType k = 0; k < w->GetNumberOfValues(); ++k)
    {
      p.Warnings.push_back(w->GetValue(k));
    }
  }
  return p;
}

/// The thresholds used and the choice's warnings, in the field data of the
/// reconstruction.
void AddThresholds(const InputPersistence& tp, double tr, const flowrecon::ThresholdChoice* choice,
  vtkUnstructuredGrid* grid)
{
  flowrecon::ThresholdsToVTK(tp.Threshold, tr, tp.Chosen, choice != nullptr,
    choice ? &choice->Window : nullptr, grid);
  // In the command line's order: the choice of t_r's, then t_p's.
  std::vector<std::string> lines;
  if (choice)
  {
    lines = flowrecon::ReconstructionChoiceWarnings(*choice);
  }
  lines.insert(lines.end(), tp.Warnings.begin(), tp.Warnings.end());
  flowrecon::ThresholdWarningsToVTK(lines, grid);
}

} // namespace

/// The t_r = infinity run of one input and what the outputs need from it.
struct vtkFlowReconstruction::Cache
{
  vtkMTimeType InputTime = 0;
  flowrecon::FlowComplex FC;
  flowrecon::ReconstructionResult Run;
  /// Node whose insertion brings each node's cells: itself, the earliest
  /// reconstructed owner of a cancelled node, or -1.
  std::vector<Id> Carrier;
  /// Whether FC.Arcs are simplified (else they give the cones' boundaries).
  bool Simplified = false;
  /// Whether FC holds the input's drawn cells (not read for the compact geometry).
  bool GeometryRead = false;
  /// The T_max whose geometry FC holds (-1: none yet).
  double GeometryThreshold = -1;
  /// Triangles and tetrahedra of each node (compressed rows of cell positions).
  flowrecon::CellsByNode TriangleGroups, TetraGroups;
  /// Persistent homology of the drawn family (below GeometryThreshold) when
  /// HasTopology, computed within TopologyLimit cells; empty with
  /// TopologyError set when it could not be computed.
  bool HasTopology = false;
  vtkIdType TopologyLimit = -1;
  std::vector<flowrecon::Bar> Bars;
  std::vector<Id> CellNodes; ///< node of each cell the bars refer to
  std::string TopologyError;
  /// The bars read off the Hasse diagram (node ids), exact for t_r up to
  /// HasseBelow (0: none): handed on by the simplification, or computed with
  /// the queue on an unsimplified input. They need no drawn cell.
  std::vector<flowrecon::Bar> HasseBars;
  double HasseBelow = 0;

  bool HasHasse(double tmax) const { return tmax <= this->HasseBelow; }
  const std::vector<flowrecon::Bar>& BarsBelow(double tmax) const
  {
    return this->HasHasse(tmax) ? this->HasseBars : this->Bars;
  }
  std::string ErrorBelow(double tmax) const
  {
    return this->HasHasse(tmax) ? std::string() : this->TopologyError;
  }
  std::vector<Id> NodesOfCells(double tmax) const
  {
    return this->HasHasse(tmax) ? std::vector<Id>() : this->CellNodes; // empty: node ids
  }
  /// With deferred patches: the triangulation their walks used, kept for the
  /// first drawing (then freed).
  std::unique_ptr<flowrecon::Retriangulation> Re;
  /// The output grid at GeometryThreshold, of which every t_r's is a prefix
  /// (GridBelow), and the profile, which only its mark of t_r changes: outputs
  /// share their arrays.
  vtkSmartPointer<vtkUnstructuredGrid> Full;
  vtkSmartPointer<vtkTable> Profile;
  /// With Geometry compact: the walks of the nodes below its T_max, and the
  /// samples' points, the same object at every t_r (ParaView computes the
  /// statistics of a new points array at each update).
  std::unique_ptr<flowrecon::CompactFamily> Compact;
  vtkSmartPointer<vtkPoints> CompactPoints;
  /// What every t_r shows alike, made once: the topology profile below
  /// StepsThreshold (NaN: none yet), and the profile's largest jumps (field
  /// arrays of Jumps, for JumpCount of them).
  std::vector<flowrecon::TopologyStep> Steps;
  double StepsThreshold = std::nan("");
  bool StepsFromHasse = false;
  vtkSmartPointer<vtkTable> Jumps;
  int JumpCount = -1;
  /// The compact cells shown and their nodes' thresholds, kept so that each
  /// t_r refills them instead of faulting in new memory.
  std::vector<double> NodeThresholds;
  flowrecon::CompactComplex Shown;
  /// Each sample's spacing (NeighbourSpacing), made when a t_r's answer is
  /// first checked for parts held by long edges: a new t_r reuses it.
  std::vector<double> Spacing;
  double Noise = -1; ///< the samples' NoiseFlatness, kept the same way (-1: not yet)

  const std::vector<flowrecon::TopologyStep>& StepsBelow(double tmax)
  {
    if (!(this->StepsThreshold == tmax) || this->StepsFromHasse != this->HasHasse(tmax))
    {
      this->Steps = flowrecon::TopologyProfile(this->BarsBelow(tmax), 1, tmax);
      this->StepsThreshold = tmax;
      this->StepsFromHasse = this->HasHasse(tmax);
    }
    return this->Steps;
  }
};

/// The t_r shown, and the automatic choice that gave it (when Chosen).
struct vtkFlowReconstruction::Selection
{
  double Threshold = 0;
  bool Chosen = false;
  flowrecon::ThresholdChoice Choice;
};

namespace
{
// The outputs, in the order of OutputPorts: RECONSTRUCTION, PROFILE, SPONSOR_ARROWS,
// TOPOLOGY_PROFILE, UNDER_SAMPLING, TOPOLOGY_TEXT.
const char* const OutputTypes[] = { "vtkUnstructuredGrid", "vtkTable", "vtkPolyData", "vtkTable",
  "vtkPolyData", "vtkTable" };
} // namespace

vtkStandardNewMacro(vtkFlowReconstruction);

//------------------------------------------------------------------------------
vtkFlowReconstruction::vtkFlowReconstruction()
{
  this->SetNumberOfOutputPorts(flowrecon::PortCount(OutputTypes));
}

//------------------------------------------------------------------------------
vtkFlowReconstruction::~vtkFlowReconstruction() = default;

//------------------------------------------------------------------------------
int vtkFlowReconstruction::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

//------------------------------------------------------------------------------
int vtkFlowReconstruction::FillOutputPortInformation(int port, vtkInformation* info)
{
  return flowrecon::SetOutputType(info, port, OutputTypes) ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkFlowReconstruction::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkMultiBlockDataSet* input = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  if (!input || !flowrecon::HasOutputs(outputVector, OutputTypes))
  {
    vtkErrorMacro("Missing input or output.");
    return 0;
  }
  if (input->GetNumberOfBlocks() == 0)
  {
    // Empty in, empty out: what the other ranks of a parallel run receive
    // (vtkFlowComplex computes on rank 0 only).
    flowrecon::EmptyOutputs(outputVector);
    return 1;
  }
  // The queue runs only for a new input; a new threshold only re-selects.
  if (!this->Cached || this->Cached->InputTime != input->GetMTime())
  {
    bool aborted = false;
    if (!this->RunQueue(input, aborted))
    {
      flowrecon::EmptyOutputs(outputVector);
      return aborted ? 1 : 0; // an abort is no error (nothing cached)
    }
  }
  const double tmax = this->MaximumThreshold >= VTK_DOUBLE_MAX ? HUGE_VAL : this->MaximumThreshold;
  if (!(tmax <= this->Cached->FC.DeferralRatio))
  {
    // The GUI's labels, which also name the Python properties once spaces go.
    vtkErrorMacro(<< "Maximum Threshold (T_max) " << tmax << " is above the input's Defer "
                  << "Patches Above (" << this->Cached->FC.DeferralRatio
                  << "): lower T_max, or raise Defer Patches Above in Flow Complex");
    flowrecon::EmptyOutputs(outputVector);
    return 0;
  }
  // The exact cells are drawn for the exact geometry, and for Betti numbers
  // that the Hasse diagram does not give.
  const bool cellTopology = this->ComputeTopology && !this->Cached->HasHasse(tmax);
  if ((this->Geometry == GEOMETRY_EXACT || cellTopology) &&
    this->Cached->GeometryThreshold != tmax && !this->DrawGeometry(input, tmax))
  {
    flowrecon::EmptyOutputs(outputVector);
    return this->GetAbortExecute() ? 1 : 0;
  }
  // Once per drawing and cell limit, when asked for (also when turned on later).
  if (cellTopology &&
    !(this->Cached->HasTopology && this->Cached->TopologyLimit == this->MaximumTopologyCells))
  {
    this->ComputeBettiNumbers(tmax);
  }
  Selection selection;
  if (!this->SelectThreshold(tmax, selection))
  {
    flowrecon::EmptyOutputs(outputVector);
    return 0;
  }
  // The exact geometry of a solid answer, or of one of several parts, needs
  // the compact cells too: the shallow-solid and side-by-side checks read
  // them, as the command line's --exact does.
  // There only a warning depends on them: when they cannot be made, the exact
  // output is still given, unmeasured.
  const bool compactGeometry = this->Geometry == GEOMETRY_COMPACT;
  if ((compactGeometry ||
        (selection.Chosen && (selection.Choice.NeedsDepth() || selection.Choice.NeedsRows() ||
                                 selection.Choice.NeedsJoins()))) &&
    !this->PrepareCompact(tmax, !compactGeometry))
  {
    flowrecon::EmptyOutputs(outputVector);
    return this->GetAbortExecute() ? 1 : 0;
  }
  this->UsedReconstructionThreshold = selection.Threshold;
  this->SetProgressText("output");
  this->UpdateProgress(0.9);
  this->FillOutputs(input, tmax, selection, outputVector);
  this->SetProgressText(nullptr);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkFlowReconstruction::RunQueue(vtkMultiBlockDataSet* input, bool& aborted)
{
  this->Cached.reset();
  auto cache = std::unique_ptr<Cache>(new Cache);
  cache->InputTime = input->GetMTime();
  flowrecon::SimplificationResult s;
  std::string error;
  // The compact geometry needs the samples, not the input's drawn cells: they
  // are read when the exact ones are drawn (ReadManifoldGeometry).
  cache->GeometryRead = this->Geometry == GEOMETRY_EXACT;
  if (!flowrecon::FromMultiBlock(input, cache->FC, error, !cache->GeometryRead,
        /*flowLines=*/false) ||
    (!cache->GeometryRead && !flowrecon::ReadSamples(input, cache->FC, error)))
  {
    vtkErrorMacro(<< error);
    return false;
  }
  cache->Simplified = flowrecon::SimplificationFromMultiBlock(
    input, static_cast<Id>(cache->FC.Nodes.size()), s, error);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return false;
  }
  const auto& nodes = cache->FC.Nodes;
  flowrecon::FlowComplex& fc = cache->FC;
  const bool deferred = !fc.DeferredPatches.empty();
  if (deferred && cache->Simplified && !s.HasLowers)
  {
    vtkErrorMacro(<< "the input's simplification lacks what its deferred patches need "
                     "(PairLowers, PairOwners): simplify it again with this version");
    return false;
  }
  // The queue is 30% of the work, drawing 60%, the selection the rest.
  const flowrecon::Progress progress = flowrecon::AlgorithmProgress(this, 0.3);
  bool finished = false;
  flowrecon::CallCore(
    this, "reconstruction",
    [&]() {
      const std::vector<Id> init = flowrecon::InitializationEdgesFromDiagram(nodes, fc.Arcs);
      ++this->NumberOfQueueRuns;
      if (!deferred)
      {
        cache->Run = flowrecon::Reconstruct(nodes, fc.Arcs, s.Survives, init, HUGE_VAL, progress);
        cache->Carrier = flowrecon::CellCarriers(cache->Run, &s);
        finished = true;
        return;
      }
      // The run up to the deferral ratio, exact for every T_max below it: the
      // deferred patches it needs are walked on the recomputed triangulation.
      cache->Re = flowrecon::Retriangulation::OfStoredComplex(fc, progress.Range(0, 0.5),
        "lower Defer Patches Above in Flow Complex, or the cloud's size");
      try
      {
        flowrecon::DeferredReconstruction late = flowrecon::ReconstructDeferred(fc,
          cache->Simplified ? &s : nullptr, *cache->Re, init, fc.DeferralRatio,
          progress.Range(0.5, 1));
        cache->Run = std::move(late.Run);
        cache->Carrier = std::move(late.Carriers);
      }
      catch (const flowrecon::Degenerate&)
      {
        throw flowrecon::InputError("a deferred patch met a tie the flow complex did not "
                                    "see: set Defer Patches Above to 0 in Flow Complex");
      }
      finished = true;
    },
    [&]() { aborted = true; });
  if (!finished)
  {
    return false;
  }
  cache->Profile = vtkSmartPointer<vtkTable>::New();
  flowrecon::ReconstructionToVTK(cache->FC, cache->Carrier, cache->Run, HUGE_VAL,
    cache->TriangleGroups, cache->TetraGroups, nullptr, cache->Profile, nullptr);
  if (cache->Simplified)
  {
    // The simplification's bars are those of this very run (same diagram, same queue).
    if (!flowrecon::ReconstructionBarsFromVTK(input->GetFieldData(),
          static_cast<Id>(cache->FC.Nodes.size()), cache->HasseBars, cache->HasseBelow, error))
    {
      cache->HasseBelow = 0;
      if (!error.empty())
      {
        vtkWarningMacro(<< error << ": the Betti numbers come from the drawn cells");
      }
    }
  }
  else if (this->ComputeTopology && !this->HasseTopology(*cache, aborted))
  {
    return false;
  }
  this->Cached = std::move(cache);
  return true;
}

//------------------------------------------------------------------------------
bool vtkFlowReconstruction::HasseTopology(Cache& cache, bool& aborted)
{
  this->SetProgressText("Betti numbers");
  const int ok = flowrecon::CallCore(
    this, "Betti numbers",
    [&]() {
      try
      {
        cache.HasseBars = flowrecon::BarsOfStoredRun(
          cache.FC, cache.Carrier, cache.Run, cache.Re.get(), flowrecon::AlgorithmProgress(this));
        cache.HasseBelow = cache.FC.DeferredPatches.empty() ? HUGE_VAL : cache.FC.DeferralRatio;
      }
      catch (const flowrecon::InputError& e)
      {
        // Not a closed decomposition (a file cut short): the drawn cells still tell.
        vtkWarningMacro(<< "no Betti numbers from the Hasse diagram (" << e.what()
                        << "): computing them from the drawn cells");
        cache.HasseBars.clear();
        cache.HasseBelow = 0;
      }
      catch (const flowrecon::Degenerate&)
      {
        vtkWarningMacro(<< "no Betti numbers from the Hasse diagram (a deferred patch met a "
                           "tie): computing them from the drawn cells");
        cache.HasseBars.clear();
        cache.HasseBelow = 0;
      }
    },
    [&]() { aborted = true; });
  return ok == 1 && !aborted;
}

//------------------------------------------------------------------------------
bool vtkFlowReconstruction::SelectThreshold(double tmax, Selection& selection)
{
  Cache& c = *this->Cached;
  const flowrecon::FlowComplex& fc = c.FC;
  double& t = selection.Threshold;
  flowrecon::ThresholdChoice& choice = selection.Choice;
  t = this->ReconstructionThreshold >= VTK_DOUBLE_MAX ? HUGE_VAL : this->ReconstructionThreshold;
  // The automatic t_r: the most stable topology of the family below T_max.
  if (this->AutomaticReconstructionThreshold && !this->EveryStep)
  {
    if (!this->ComputeTopology)
    {
      vtkErrorMacro(<< "Automatic Reconstruction Threshold needs Compute Topology: turn "
                       "Compute Topology on, or set t_r yourself");
      return false;
    }
    if (c.ErrorBelow(tmax).empty() && tmax > choice.Rule.Lowest)
    {
      const std::vector<std::vector<flowrecon::TopologyStep>> profiles{ c.StepsBelow(tmax) };
      choice = flowrecon::ChooseThresholds(profiles, tmax);
      t = choice.ReconstructionThreshold;
      selection.Chosen = true;
      flowrecon::CheckFilled(choice,
        std::vector<flowrecon::Point3>(fc.Points.begin(), fc.Points.begin() + fc.NumberOfInputPoints),
        flowrecon::MaximaBelow(fc.Nodes, c.Carrier, c.Run, t));
      flowrecon::CheckFar(choice, fc.Nodes, fc.NumberOfInputPoints);
      if (flowrecon::PreferSurface(choice, profiles, tmax))
      {
        t = choice.ReconstructionThreshold;
      }
    }
    else
    {
      vtkWarningMacro(<< "no automatic t_r ("
                      << (c.ErrorBelow(tmax).empty() ? "Maximum Threshold is at most 1.5"
                                                  : "no Betti numbers")
                      << "): showing the Reconstruction Threshold " << t);
    }
  }
  if (this->EveryStep)
  {
    t = tmax;
  }
  else if (t > tmax)
  {
    // The GUI's labels, which also name the Python properties once spaces go.
    vtkWarningMacro(<< "Reconstruction Threshold (t_r) " << t << " is above Maximum Threshold "
                    << "(T_max) " << tmax << ": showing the reconstruction at " << tmax
                    << "; raise Maximum Threshold to see more");
    t = tmax;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkFlowReconstruction::FillOutputs(vtkMultiBlockDataSet* input, double tmax,
  const Selection& selection, vtkInformationVector* outputVector)
{
  const double t = selection.Threshold;
  const flowrecon::ThresholdChoice* choice = selection.Chosen ? &selection.Choice : nullptr;
  static_assert(RECONSTRUCTION == 0 && PROFILE == 1 && TOPOLOGY_PROFILE == 3 && UNDER_SAMPLING == 4,
    "the ports ReconstructionPorts reads");
  const auto [grid, profile, topology, undersampling] = flowrecon::ReconstructionPorts(outputVector);
  auto* arrows = vtkPolyData::GetData(outputVector, SPONSOR_ARROWS);
  auto* text = vtkTable::GetData(outputVector, TOPOLOGY_TEXT);
  Cache& c = *this->Cached;
  const flowrecon::FlowComplex& fc = c.FC;
  if (this->SponsorArrows)
  {
    flowrecon::ReconstructionToVTK(fc, c.Carrier, c.Run, t, c.TriangleGroups, c.TetraGroups,
      nullptr, nullptr, arrows);
  }
  else
  {
    arrows->Initialize();
  }
  profile->ShallowCopy(c.Profile);
  flowrecon::MarkProfile(profile, t);
  if (!c.Jumps || c.JumpCount != this->NumberOfJumps)
  {
    c.Jumps = vtkSmartPointer<vtkTable>::New();
    flowrecon::ProfileJumpsToVTK(fc, c.Run, static_cast<std::size_t>(this->NumberOfJumps), c.Jumps);
    c.JumpCount = this->NumberOfJumps;
  }
  vtkFieldData* jumps = c.Jumps->GetFieldData();
  for (int k = 0; k < jumps->GetNumberOfArrays(); ++k)
  {
    profile->GetFieldData()->AddArray(jumps->GetAbstractArray(k));
  }
  if (this->Geometry == GEOMETRY_EXACT)
  {
    flowrecon::GridBelow(c.Full, t, flowrecon::EdgeMultiplicities(fc.Nodes, fc.Arcs, c.Run, t), grid);
  }
  else
  {
    grid->Initialize(); // the compact cells go in below, after the field data
  }
  flowrecon::ReleaseFreedMemory(); // the previous output's arrays, replaced just now
  // The compact cells at t, written below once the field data is; their
  // tetrahedra tell whether a solid answer is shallow (as the command line's).
  flowrecon::CompactComplex& compact = c.Shown;
  std::vector<double>& thresholds = c.NodeThresholds;
  const bool withCompact = this->Geometry == GEOMETRY_COMPACT && c.Compact;
  const bool measure = choice && c.Compact &&
    (choice->NeedsDepth() || choice->NeedsRows() || withCompact || choice->NeedsJoins());
  if (withCompact || measure)
  {
    try
    {
      c.Compact->At(t, thresholds, compact);
    }
    catch (const std::exception& e)
    {
      // Not expected (the family agrees with the selection of one t_r at every
      // tested threshold), but an error message beats an exception through
      // the pipeline: the cells are left out, the rest is shown.
      vtkErrorMacro(<< "compact cells at t_r " << t << ": " << e.what());
      compact = flowrecon::CompactComplex();
      thresholds.assign(fc.Nodes.size(), std::nan(""));
    }
  }
  flowrecon::ThresholdChoice measured;
  if (measure)
  {
    measured = *choice;
    flowrecon::CheckShallow(measured, compact.Tetrahedra);
    flowrecon::CheckRows(measured, fc.Nodes, fc.NumberOfInputPoints, compact);
    if (measured.Window.Betti[2] >= 1) // CheckJoins measures nothing else
    {
      flowrecon::CheckJoins(measured,
        std::vector<flowrecon::Point3>(fc.Points.begin(), fc.Points.begin() + fc.NumberOfInputPoints), compact,
        &c.Spacing, &c.Noise);
    }
    choice = &measured;
  }
  std::string why; // no Betti numbers
  if (!this->ComputeTopology)
  {
    topology->Initialize();
    undersampling->Initialize();
    why = " (Compute Topology is off)";
  }
  else if (c.ErrorBelow(tmax).empty())
  {
    const std::vector<flowrecon::Bar>& bars = c.BarsBelow(tmax);
    flowrecon::TopologyToVTK(bars, c.StepsBelow(tmax), t, tmax, grid, topology);
    // Changes beyond T_max are not known: the window stops there. A short
    // stable window: its end is where the topology changes next.
    double window = std::min(this->UnderSamplingWindow, tmax / t);
    if (choice && choice->Short() && choice->Window.To > t)
    {
      window = std::max(window, choice->Window.To / t * (1 + 1e-9));
    }
    flowrecon::UnderSamplingToVTK(
      flowrecon::TopologyChangesAbove(bars, t, std::max(1.0, window)), c.NodesOfCells(tmax), fc,
      undersampling);
    AddThresholds(PersistenceOf(input), t, choice, grid);
  }
  else
  {
    topology->Initialize();
    undersampling->Initialize();
    vtkWarningMacro(<< "no Betti numbers: " << c.ErrorBelow(tmax));
    why = ": " + c.ErrorBelow(tmax);
  }
  flowrecon::TopologyTextToVTK(
    flowrecon::TopologyLine(grid, topology, undersampling, t, tmax, why,
      c.ErrorBelow(tmax).empty() && this->ComputeTopology ? &c.StepsBelow(tmax) : nullptr),
    grid, text);
  // The compact cells in place of the exact ones, once the field data is
  // written (its counts go after the arrays the states' spreadsheets show).
  if (withCompact)
  {
    // The family's points are shared, not copied (nor the samples).
    flowrecon::CompactCellsToVTK(compact,
      c.CompactPoints ? std::vector<flowrecon::Point3>()
                      : std::vector<flowrecon::Point3>(
                          fc.Points.begin(), fc.Points.begin() + fc.NumberOfInputPoints),
      fc.Nodes, thresholds, grid, c.CompactPoints);
  }
  // What ParaView colours by in a render view: the reconstruction by Index (the
  // array Flow Complex's critical points and stable manifolds are coloured by),
  // the under-sampling points by nothing, so that the view has one colour legend.
  grid->GetCellData()->SetActiveScalars(flowrecon::names::Index);
  undersampling->GetPointData()->SetActiveScalars(nullptr);
}

//------------------------------------------------------------------------------
bool vtkFlowReconstruction::DrawGeometry(vtkMultiBlockDataSet* input, double tmax)
{
  Cache& cache = *this->Cached;
  flowrecon::FlowComplex& fc = cache.FC;
  cache.GeometryThreshold = -1;
  std::string error;
  if (!cache.GeometryRead && !flowrecon::ReadManifoldGeometry(input, fc, error))
  {
    vtkErrorMacro(<< error);
    return false;
  }
  cache.GeometryRead = true;
  // The nodes whose cells the output can show: carriers below T_max.
  const std::vector<Id> draw = flowrecon::NodesToDraw(fc.Nodes, cache.Carrier, cache.Run, tmax);
  // The input's own cells do when they cover every such node (a complex
  // computed with all its geometry); otherwise draw them from the samples.
  std::vector<char> drawn(fc.Nodes.size(), 0);
  for (const Id node : fc.TriangleNode)
  {
    drawn[node] = 1;
  }
  for (const Id node : fc.TetrahedronNode)
  {
    drawn[node] = 1;
  }
  const bool covered =
    std::all_of(draw.begin(), draw.end(), [&](Id node) { return drawn[node] != 0; });
  if (!covered)
  {
    const std::vector<flowrecon::Point3> samples(
      fc.Points.begin(), fc.Points.begin() + fc.NumberOfInputPoints);
    flowrecon::BuildOptions options;
    options.Seed = fc.Report.Seed;
    flowrecon::Progress progress = flowrecon::AlgorithmProgress(this);
    progress.Report = [this](double f, const char* phase) {
      this->SetProgressText(phase);
      this->UpdateProgress(0.3 + 0.6 * f);
    };
    bool finished = false;
    const int ok = flowrecon::CallCore(
      this, "drawing the stable manifolds",
      [&]() {
        flowrecon::DrawStableManifolds(samples, options, draw, fc, progress,
          "lower MaximumThreshold (flowrecon --tr-max), or the cloud's size",
          cache.Simplified ? nullptr : &fc.Arcs, cache.Re.get());
        finished = true;
      },
      []() {});
    if (!finished)
    {
      (void)ok;
      return false;
    }
  }
  cache.Re.reset(); // about 1.5 KB per point; a later drawing computes it again
  flowrecon::ReleaseFreedMemory();
  cache.TriangleGroups = flowrecon::PositionsByRow(fc.TriangleNode, fc.Nodes.size());
  cache.TetraGroups = flowrecon::PositionsByRow(fc.TetrahedronNode, fc.Nodes.size());
  cache.Full = vtkSmartPointer<vtkUnstructuredGrid>::New();
  try
  {
    flowrecon::ReconstructionToVTK(fc, cache.Carrier, cache.Run, tmax, cache.TriangleGroups,
      cache.TetraGroups, cache.Full, nullptr, nullptr);
  }
  catch (const flowrecon::InputError& e)
  {
    vtkErrorMacro(<< e.what());
    return false;
  }
  cache.HasTopology = false; // of the family drawn before
  cache.Bars.clear();
  cache.StepsThreshold = std::nan(""); // the profile of the old bars
  cache.GeometryThreshold = tmax;
  return true;
}

//------------------------------------------------------------------------------
bool vtkFlowReconstruction::PrepareCompact(double tmax, bool forWarning)
{
  Cache& c = *this->Cached;
  if (c.Compact && c.Compact->MaximumThreshold() == tmax)
  {
    return true;
  }
  c.Compact.reset();
  flowrecon::Progress progress = flowrecon::AlgorithmProgress(this);
  progress.Report = [this](double f, const char* phase) {
    this->SetProgressText(phase);
    this->UpdateProgress(0.3 + 0.6 * f);
  };
  bool finished = false;
  const auto make = [&]() {
    // The queue's triangulation when the drawing did not free it.
    c.Compact = std::make_unique<flowrecon::CompactFamily>(c.FC, c.Carrier, c.Run, tmax,
      std::move(c.Re), progress, "lower MaximumThreshold, or choose the exact Geometry");
    if (!c.CompactPoints)
    {
      c.CompactPoints = flowrecon::MakePoints(std::vector<flowrecon::Point3>(
        c.FC.Points.begin(), c.FC.Points.begin() + c.FC.NumberOfInputPoints));
    }
    finished = true;
  };
  if (!forWarning)
  {
    flowrecon::CallCore(this, "compact geometry", make, []() {});
    return finished;
  }
  try
  {
    make();
  }
  catch (const flowrecon::Aborted&)
  {
    vtkWarningMacro(<< "compact walks aborted: the output is empty (AbortExecute stays set "
                       "until cleared)");
    return false;
  }
  catch (const std::exception& e)
  {
    // Only the shallow-solid and side-by-side warnings needed them: the exact output goes on.
    c.Compact.reset();
    flowrecon::ReleaseFreedMemory();
    vtkWarningMacro(<< "the answer's cells on the samples are not made (no shallow-solid or side-by-side check): "
                    << e.what());
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkFlowReconstruction::ComputeBettiNumbers(double tmax)
{
  // The Betti numbers of every t_r <= T_max at once: one barcode of the family.
  Cache& cache = *this->Cached;
  cache.Bars.clear();
  cache.StepsThreshold = std::nan(""); // the profile of the old bars
  cache.TopologyError.clear();
  cache.HasTopology = true;
  cache.TopologyLimit = this->MaximumTopologyCells;
  try
  {
    this->SetProgressText("Betti numbers");
    this->UpdateProgress(0.9);
    cache.Bars = flowrecon::CellBarcode(flowrecon::ReconstructionCells(cache.FC, cache.Carrier,
      cache.Run, tmax, cache.TriangleGroups, cache.TetraGroups, &cache.CellNodes,
        this->MaximumTopologyCells),
      flowrecon::Progress(), this->MaximumTopologyCells);
  }
  catch (const flowrecon::InputError& e)
  {
    cache.TopologyError = e.what(); // the reconstruction itself is still shown
  }
  catch (const std::bad_alloc&)
  {
    cache.TopologyError = "out of memory";
  }
}

//------------------------------------------------------------------------------
void vtkFlowReconstruction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ReconstructionThreshold: " << this->ReconstructionThreshold << "\n";
  os << indent << "AutomaticReconstructionThreshold: "
     << (this->AutomaticReconstructionThreshold ? "on" : "off") << "\n";
  os << indent << "EveryStep: " << this->EveryStep << "\n";
  os << indent << "MaximumThreshold: " << this->MaximumThreshold << "\n";
  os << indent << "UnderSamplingWindow: " << this->UnderSamplingWindow << "\n";
  os << indent << "ComputeTopology: " << (this->ComputeTopology ? "on" : "off") << "\n";
  os << indent << "NumberOfJumps: " << this->NumberOfJumps << "\n";
  os << indent << "Geometry: " << (this->Geometry == GEOMETRY_COMPACT ? "compact" : "exact") << "\n";
  os << indent << "SponsorArrows: " << (this->SponsorArrows ? "on" : "off") << "\n";
  os << indent << "NumberOfQueueRuns: " << this->NumberOfQueueRuns << "\n";
}
