#include "vtkFlowComplexSimplification.h"

#include "CoreCall.h"
#include "FlowComplexConversion.h"
#include "Simplification.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"

#include <string>

vtkStandardNewMacro(vtkFlowComplexSimplification);

//------------------------------------------------------------------------------
vtkFlowComplexSimplification::vtkFlowComplexSimplification() = default;
vtkFlowComplexSimplification::~vtkFlowComplexSimplification() = default;

//------------------------------------------------------------------------------
int vtkFlowComplexSimplification::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

//------------------------------------------------------------------------------
int vtkFlowComplexSimplification::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkMultiBlockDataSet* input = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output.");
    return 0;
  }
  if (input->GetNumberOfBlocks() == 0)
  {
    // Empty in, empty out: what the other ranks of a parallel run receive
    // (vtkFlowComplex computes on rank 0 only).
    output->Initialize();
    return 1;
  }
  flowrecon::FlowComplex fc;
  flowrecon::SimplificationResult previous;
  std::string error;
  // The simplification changes the arcs only: the drawn geometry is neither
  // read nor copied (ReplaceHasseDiagram shares it with the input).
  if (!flowrecon::FromMultiBlock(input, fc, error, /*diagramOnly=*/true))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (flowrecon::SimplificationFromMultiBlock(
        input, static_cast<flowrecon::Id>(fc.Nodes.size()), previous, error) ||
    !error.empty())
  {
    vtkErrorMacro(<< (error.empty() ? std::string("the input is already simplified; simplify the "
                                                  "flow complex itself instead")
                                    : error));
    return 0;
  }

  const bool deferred = !fc.DeferredPatches.empty();
  if (deferred && !(this->PersistenceThreshold < fc.DeferralRatio))
  {
    // Cancellations at t_p could then use the arcs the complex does not have.
    vtkErrorMacro(<< "Persistence Threshold (t_p) " << this->PersistenceThreshold
                  << " must be below the input's Defer Patches Above (" << fc.DeferralRatio
                  << "): lower t_p, or raise Defer Patches Above in Flow Complex");
    return 0;
  }
  const flowrecon::Progress progress = flowrecon::AlgorithmProgress(this);
  return flowrecon::CallCore(
    this, "simplification",
    [&]() {
      // With deferred patches, what a replay on them needs is recorded too.
      const flowrecon::SimplificationResult s = flowrecon::Simplify(fc.Nodes,
        std::vector<flowrecon::Arc>(fc.Arcs), this->PersistenceThreshold, progress.Range(0, 0.6),
        deferred);
      fc.Arcs = s.Arcs; // the HasseDiagram block shows the simplified diagram
      flowrecon::ReplaceHasseDiagram(input, fc, output);
      flowrecon::AddSimplification(fc, s, this->PersistenceThreshold, output);
      flowrecon::SetDefaultScalars(output);
    },
    [&]() { output->Initialize(); });
}

//------------------------------------------------------------------------------
void vtkFlowComplexSimplification::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PersistenceThreshold: " << this->PersistenceThreshold << "\n";
}
