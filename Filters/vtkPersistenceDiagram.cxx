#include "vtkPersistenceDiagram.h"

#include "PipelinePorts.h"
#include "CoreCall.h"
#include "DeferredPatches.h"
#include "FlowComplexConversion.h"
#include "PersistenceDiagramConversion.h"
#include "Simplification.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <string>
#include <vector>

namespace
{
// The outputs, in the order of OutputPorts: DIAGRAM, CURVE.
const char* const OutputTypes[] = { "vtkUnstructuredGrid", "vtkTable" };
} // namespace

vtkStandardNewMacro(vtkPersistenceDiagram);

//------------------------------------------------------------------------------
vtkPersistenceDiagram::vtkPersistenceDiagram()
{
  this->SetNumberOfOutputPorts(flowrecon::PortCount(OutputTypes));
}

//------------------------------------------------------------------------------
vtkPersistenceDiagram::~vtkPersistenceDiagram() = default;

//------------------------------------------------------------------------------
int vtkPersistenceDiagram::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

//------------------------------------------------------------------------------
int vtkPersistenceDiagram::FillOutputPortInformation(int port, vtkInformation* info)
{
  return flowrecon::SetOutputType(info, port, OutputTypes) ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkPersistenceDiagram::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkMultiBlockDataSet* input = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  auto* diagram = vtkUnstructuredGrid::GetData(outputVector, DIAGRAM);
  auto* curve = vtkTable::GetData(outputVector, CURVE);
  if (!input || !diagram || !curve)
  {
    vtkErrorMacro("Missing input or output.");
    return 0;
  }
  const auto empty = [outputVector]() { flowrecon::EmptyOutputs(outputVector); };
  if (input->GetNumberOfBlocks() == 0)
  {
    // Empty in, empty out: what the other ranks of a parallel run receive
    // (vtkFlowComplex computes on rank 0 only).
    empty();
    return 1;
  }

  this->SetProgressText("reading the flow complex");
  this->UpdateProgress(0.0);
  flowrecon::FlowComplex fc;
  std::string error;
  if (!flowrecon::FromMultiBlock(input, fc, error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  flowrecon::SimplificationResult simplified;
  if (flowrecon::SimplificationFromMultiBlock(
        input, static_cast<flowrecon::Id>(fc.Nodes.size()), simplified, error) ||
    !error.empty())
  {
    // The cancelled pairs are gone from a simplified Hasse diagram.
    vtkErrorMacro(<< (error.empty() ? std::string("the input is simplified; the persistence "
                                                  "diagram needs the flow complex itself")
                                    : error));
    return 0;
  }
  if (this->GetAbortExecute())
  {
    empty();
    return 1;
  }

  // The persistence is not interruptible: abort is checked around it.
  this->SetProgressText("persistence");
  this->UpdateProgress(0.2);
  std::vector<flowrecon::PersistencePair> pairs;
  const int ok = flowrecon::CallCore(
    this, "persistence",
    [&]() {
      // The diagram needs every arc: the deferred patches are walked here, on
      // the recomputed triangulation (what a complex without deferral costs).
      flowrecon::WalkEveryDeferredPatch(fc, flowrecon::Progress(),
        "set Defer Patches Above to 0 in Flow Complex, or use fewer points");
      pairs = flowrecon::DiagramPairs(fc);
    },
    empty);
  if (!ok)
  {
    return 0;
  }
  fc = flowrecon::FlowComplex();
  if (this->GetAbortExecute())
  {
    empty();
    return 1;
  }

  this->SetProgressText("diagram");
  this->UpdateProgress(0.8);
  flowrecon::DiagramToVTK(pairs, diagram);
  flowrecon::AddThresholdLine(this->PersistenceThreshold, diagram);
  flowrecon::DiagramChartToVTK(pairs, this->PersistenceThreshold, diagram);
  flowrecon::PersistenceCurveToVTK(pairs, this->PersistenceThreshold, curve);
  this->SetProgressText(nullptr);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkPersistenceDiagram::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PersistenceThreshold: " << this->PersistenceThreshold << "\n";
}
