#include "vtkFlowComplex.h"

#include "PipelinePorts.h"
#include "FlowComplexBuilder.h"
#include "CoreCall.h"
#include "FlowReconNames.h"
#include "FlowComplexConversion.h"

#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>
#include <string>

vtkStandardNewMacro(vtkFlowComplex);

//------------------------------------------------------------------------------
vtkFlowComplex::vtkFlowComplex() = default;
vtkFlowComplex::~vtkFlowComplex() = default;

//------------------------------------------------------------------------------
const char* vtkFlowComplex::BlockName(int block)
{
  static const char* names[NUMBER_OF_BLOCKS] = { flowrecon::names::CriticalPoints, flowrecon::names::HasseDiagram,
    flowrecon::names::StableManifolds, flowrecon::names::UnstableManifolds,
    flowrecon::names::GabrielEdges };
  return (block >= 0 && block < NUMBER_OF_BLOCKS) ? names[block] : nullptr;
}

//------------------------------------------------------------------------------
int vtkFlowComplex::FillInputPortInformation(int, vtkInformation* info)
{
  flowrecon::AcceptPointCloud(info);
  return 1;
}

//------------------------------------------------------------------------------
int vtkFlowComplex::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  flowrecon::RequestWholeInput(inputVector);
  return 1;
}

//------------------------------------------------------------------------------
int vtkFlowComplex::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
  if (!output)
  {
    vtkErrorMacro("Missing output.");
    return 0;
  }
  if (flowrecon::IsLaterPiece(outputVector))
  {
    output->Initialize(); // piece 0 holds the whole (global) flow complex
    return 1;
  }
  std::vector<flowrecon::Point3> samples;
  std::string error;
  if (!flowrecon::ExtractSamples(input, samples, error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }

  flowrecon::BuildOptions options;
  options.StableManifolds = this->ComputeStableManifolds;
  options.MaximumGeometryCells = this->MaximumStableManifoldCells;
  options.UnstableManifolds = this->ComputeUnstableManifolds;
  options.DeferPatchesAboveRatio = this->DeferPatchesAbove > 1 ? this->DeferPatchesAbove : HUGE_VAL;
  options.Seed = static_cast<std::uint64_t>(static_cast<unsigned int>(this->PerturbationSeed));
  // The copy into VTK data takes about a fifth of the time when cells are drawn.
  const flowrecon::Progress progress = flowrecon::AlgorithmProgress(this);
  return flowrecon::CallCore(
    this, "flow complex construction",
    [&]() {
      const flowrecon::FlowComplex fc =
        flowrecon::BuildFlowComplex(samples, options, progress.Range(0, 0.8));
      flowrecon::RequireMemoryForVTK(fc);
      flowrecon::ToMultiBlock(fc, output, progress.Range(0.8, 1));
      flowrecon::SetDefaultScalars(output);
    },
    [&]() { output->Initialize(); });
}

//------------------------------------------------------------------------------
void vtkFlowComplex::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ComputeStableManifolds: " << this->ComputeStableManifolds << "\n";
  os << indent << "MaximumStableManifoldCells: " << this->MaximumStableManifoldCells << "\n";
  os << indent << "ComputeUnstableManifolds: " << this->ComputeUnstableManifolds << "\n";
  os << indent << "DeferPatchesAbove: " << this->DeferPatchesAbove << "\n";
  os << indent << "PerturbationSeed: " << this->PerturbationSeed << "\n";
}
