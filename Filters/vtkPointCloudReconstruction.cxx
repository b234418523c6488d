#include "vtkPointCloudReconstruction.h"

#include "CloudReconstruction.h"
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

vtkStandardNewMacro(vtkPointCloudReconstruction);

//------------------------------------------------------------------------------
vtkPointCloudReconstruction::vtkPointCloudReconstruction()
{
  this->SetNumberOfOutputPorts(6);
}

vtkPointCloudReconstruction::~vtkPointCloudReconstruction() = default;

//------------------------------------------------------------------------------
int vtkPointCloudReconstruction::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkTable");
  return 1;
}

//------------------------------------------------------------------------------
int vtkPointCloudReconstruction::FillOutputPortInformation(int port, vtkInformation* info)
{
  const char* types[6] = { "vtkUnstructuredGrid", "vtkTable", "vtkUnstructuredGrid", "vtkTable",
    "vtkPolyData", "vtkTable" };
  if (port < 0 || port > 5)
  {
    return 0;
  }
  info->Set(vtkDataObject::DATA_TYPE_NAME(), types[port]);
  return 1;
}

//------------------------------------------------------------------------------
int vtkPointCloudReconstruction::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The distance function depends on all samples: ask for the whole input.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  return 1;
}

//------------------------------------------------------------------------------
int vtkPointCloudReconstruction::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  auto* grid = vtkUnstructuredGrid::GetData(outputVector, RECONSTRUCTION);
  auto* profile = vtkTable::GetData(outputVector, PROFILE);
  auto* diagram = vtkUnstructuredGrid::GetData(outputVector, PERSISTENCE_DIAGRAM);
  auto* topology = vtkTable::GetData(outputVector, TOPOLOGY_PROFILE);
  auto* undersampling = vtkPolyData::GetData(outputVector, UNDER_SAMPLING);
  auto* text = vtkTable::GetData(outputVector, TOPOLOGY_TEXT);
  if (!grid || !profile || !diagram || !topology || !undersampling || !text)
  {
    vtkErrorMacro("Missing output.");
    return 0;
  }
  auto empty = [&]() {
    for (vtkDataObject* output :
      std::vector<vtkDataObject*>{ grid, profile, diagram, topology, undersampling, text })
    {
      output->Initialize();
    }
  };
  empty();
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
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
      if (this->ComputePersistenceDiagram)
      {
        // Without it the reconstruction is still worth having (a cloud too
        // large for the whole flow complex, which the reconstruction never holds).
        try
        {
          flowrecon::BuildOptions build;
          build.StableManifolds = false;
          build.UnstableManifolds = false;
          pairs = flowrecon::DiagramPairs(
            flowrecon::BuildFlowComplex(samples, build, progress.Range(0, diagramShare)));
          diagramDone = true;
        }
        catch (const flowrecon::InputError& e)
        {
          diagramError = e.what();
        }
        catch (const std::bad_alloc&)
        {
          diagramError = "out of memory";
        }
      }
      report = flowrecon::ReconstructCloud(samples, settings,
        { grid, profile, topology, undersampling }, progress.Range(diagramShare, 0.95),
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
  // The choice's warnings and the answer in words, as the command line writes them.
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
  os << indent << "UnderSamplingWindow: " << this->UnderSamplingWindow << "\n";
  os << indent << "ComputePersistenceDiagram: " << this->ComputePersistenceDiagram << "\n";
  os << indent << "UsedReconstructionThreshold: " << this->UsedReconstructionThreshold << "\n";
  os << indent << "UsedPersistenceThreshold: " << this->UsedPersistenceThreshold << "\n";
}
