#include "vtkPointCloudReconstruction.h"

#include "PipelinePorts.h"
#include "CloudReconstruction.h"
#include "CompactConversion.h"
#include "CoreCall.h"
#include "FlowComplexBuilder.h"
#include "FlowReconNames.h"
#include "PersistenceDiagramConversion.h"
#include "ReconstructionConversion.h"
#include "ReconstructionReport.h"
#include "SamplesFromVTK.h"
#include "TopologyConversion.h"

#include "vtkCellData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <new>
#include <string>
#include <vector>

namespace
{
// The outputs, in the order of OutputPorts: RECONSTRUCTION, PROFILE,
// PERSISTENCE_DIAGRAM, TOPOLOGY_PROFILE, UNDER_SAMPLING, TOPOLOGY_TEXT.
const char* const OutputTypes[] = { "vtkUnstructuredGrid", "vtkTable", "vtkUnstructuredGrid",
  "vtkTable", "vtkPolyData", "vtkTable" };
} // namespace

vtkStandardNewMacro(vtkPointCloudReconstruction);

//------------------------------------------------------------------------------
vtkPointCloudReconstruction::vtkPointCloudReconstruction()
{
  this->SetNumberOfOutputPorts(flowrecon::PortCount(OutputTypes));
}

vtkPointCloudReconstruction::~vtkPointCloudReconstruction() = default;

//------------------------------------------------------------------------------
int vtkPointCloudReconstruction::FillInputPortInformation(int, vtkInformation* info)
{
  flowrecon::AcceptPointCloud(info);
  return 1;
}

//------------------------------------------------------------------------------
int vtkPointCloudReconstruction::FillOutputPortInformation(int port, vtkInformation* info)
{
  return flowrecon::SetOutputType(info, port, OutputTypes) ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkPointCloudReconstruction::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  flowrecon::RequestWholeInput(inputVector);
  return 1;
}

namespace
{

// The persistence pairs of the cloud's whole flow complex; false with `error`
// when it does not fit, since the reconstruction is still worth having (it
// never holds the whole flow complex).
bool CloudDiagramPairs(const std::vector<flowrecon::Point3>& samples,
  const flowrecon::Progress& progress, std::vector<flowrecon::PersistencePair>& pairs,
  std::string& error)
{
  try
  {
    flowrecon::BuildOptions build;
    build.StableManifolds = false;
    build.UnstableManifolds = false;
    pairs = flowrecon::DiagramPairs(flowrecon::BuildFlowComplex(samples, build, progress));
    return true;
  }
  catch (const flowrecon::InputError& e)
  {
    error = e.what();
  }
  catch (const std::bad_alloc&)
  {
    error = "out of memory";
  }
  return false;
}

// The choice's warnings and the answer in words, as the command line writes
// them, and the chosen t_r marked on the profile.
void AnswerToVTK(const flowrecon::CloudReconstructionReport& report,
  const flowrecon::CloudReconstructionSettings& settings, vtkUnstructuredGrid* grid,
  vtkTable* profile, vtkTable* topology, vtkPolyData* undersampling, vtkTable* text)
{
  const double tr = report.ReconstructionThreshold;
  const std::vector<double>& tps = settings.PersistenceCandidates;
  if (report.Automatic)
  {
    flowrecon::ThresholdWarningsToVTK(
      flowrecon::ChoiceWarnings(report.Choice, tps, true, tps.size() > 1), grid);
  }
  flowrecon::TopologyTextToVTK(
    flowrecon::TopologyLine(grid, topology, undersampling, tr, settings.Cap,
      report.TopologyError.empty() ? "" : ": " + report.TopologyError),
    grid, text);
  flowrecon::MarkProfile(profile, tr);
}

} // namespace

//------------------------------------------------------------------------------
int vtkPointCloudReconstruction::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  if (!flowrecon::HasOutputs(outputVector, OutputTypes))
  {
    vtkErrorMacro("Missing output.");
    return 0;
  }
  static_assert(RECONSTRUCTION == 0 && PROFILE == 1 && TOPOLOGY_PROFILE == 3 && UNDER_SAMPLING == 4,
    "the ports ReconstructionPorts reads");
  const flowrecon::CloudReconstructionOutputs ports = flowrecon::ReconstructionPorts(outputVector);
  const auto& [grid, profile, topology, undersampling] = ports;
  auto* diagram = vtkUnstructuredGrid::GetData(outputVector, PERSISTENCE_DIAGRAM);
  auto* text = vtkTable::GetData(outputVector, TOPOLOGY_TEXT);
  const auto empty = [outputVector]() { flowrecon::EmptyOutputs(outputVector); };
  empty();
  if (flowrecon::IsLaterPiece(outputVector))
  {
    return 1; // piece 0 holds the whole reconstruction (as vtkFlowComplex's)
  }
  std::vector<flowrecon::Point3> samples;
  std::string error;
  if (!flowrecon::ExtractSamples(input, samples, error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }

  // What `flowrecon reconstruct CLOUD` runs at its defaults, T_max and the
  // warnings' window aside.
  flowrecon::CloudReconstructionSettings settings;
  settings.AutomaticReconstruction = true;
  settings.AutomaticPersistence = true;
  settings.OutputThreshold = 0;    // raised to the chosen t_r
  settings.DrawThreshold = 1;      // raised to what the chosen t_r needs
  settings.Cap = this->MaximumThreshold;
  settings.UnderSamplingWindow = this->UnderSamplingWindow;
  settings.Advice = "lower Maximum Threshold, or use fewer points";
  settings.Compact = this->Geometry == GEOMETRY_COMPACT;

  // The diagram first: its flow complex is freed before the reconstruction's
  // is built, so the peak is the larger of the two, not their sum.
  const double diagramShare = this->ComputePersistenceDiagram ? 0.45 : 0.0;
  const flowrecon::Progress progress = flowrecon::AlgorithmProgress(this);
  std::vector<flowrecon::PersistencePair> pairs;
  bool diagramDone = false;
  std::string diagramError;
  flowrecon::CloudReconstructionReport report;
  const int ok = flowrecon::CallCore(
    this, "point cloud reconstruction",
    [&]() {
      diagramDone = this->ComputePersistenceDiagram &&
        CloudDiagramPairs(samples, progress.Range(0, diagramShare), pairs, diagramError);
      report = flowrecon::ReconstructCloud(samples, settings,
        ports, progress.Range(diagramShare, 0.95),
        [](const char*) {});
    },
    empty);
  if (!ok || this->GetAbortExecute())
  {
    empty();
    return ok;
  }
  this->SetProgressText("output");
  this->UpdateProgress(0.95);
  const double tr = report.ReconstructionThreshold;
  const double tp = report.PersistenceThreshold;
  this->UsedReconstructionThreshold = tr;
  this->UsedPersistenceThreshold = tp;
  if (!report.TopologyError.empty())
  {
    vtkWarningMacro(<< "no Betti numbers: " << report.TopologyError);
  }
  AnswerToVTK(report, settings, grid, profile, topology, undersampling, text);
  if (settings.Compact)
  {
    flowrecon::CompactCellsToVTK(report.Compact, samples, report.Nodes, report.NodeThreshold, grid);
  }
  if (!diagramError.empty())
  {
    vtkWarningMacro(<< "no persistence diagram: " << diagramError
                    << " (turn Compute Persistence Diagram off to skip it)");
  }
  if (diagramDone)
  {
    flowrecon::DiagramToVTK(pairs, diagram);
    flowrecon::AddThresholdLine(tp, diagram);
    flowrecon::DiagramChartToVTK(pairs, tp, diagram);
  }
  // What a render view colours by: the reconstruction by Index, the
  // under-sampling points by nothing (one colour legend), as Flow Reconstruction.
  grid->GetCellData()->SetActiveScalars(flowrecon::names::Index);
  undersampling->GetPointData()->SetActiveScalars(nullptr);
  this->SetProgressText(nullptr);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkPointCloudReconstruction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumThreshold: " << this->MaximumThreshold << "\n";
  os << indent << "Geometry: " << (this->Geometry == GEOMETRY_COMPACT ? "compact" : "exact") << "\n";
  os << indent << "UnderSamplingWindow: " << this->UnderSamplingWindow << "\n";
  os << indent << "ComputePersistenceDiagram: " << this->ComputePersistenceDiagram << "\n";
  os << indent << "UsedReconstructionThreshold: " << this->UsedReconstructionThreshold << "\n";
  os << indent << "UsedPersistenceThreshold: " << this->UsedPersistenceThreshold << "\n";
}
