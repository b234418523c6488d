#include "Pipeline.h"

#include "FlowComplexConversion.h"
#include "FlowReconNames.h"
#include "Interrupt.h"
#include "VtkMessageCapture.h"
#include "OutputFiles.h"
#include "vtkFlowComplex.h"
#include "vtkPointCloudReader.h"

#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkXMLMultiBlockDataReader.h"

namespace flowrecon::cli
{

namespace
{

// The output of `reader` run on `file`, whose own error message is the failure.
vtkDataObject* Read(vtkPointCloudReader* reader, const std::string& file)
{
  reader->SetFileName(file.c_str());
  if (!reader->GetExecutive()->Update())
  {
    throw Failure(reader->GetErrorMessage());
  }
  ThrowIfInterrupted();
  return reader->GetOutputDataObject(0);
}

} // namespace

std::vector<Point3> ReadSamples(const std::string& file)
{
  vtkNew<vtkPointCloudReader> reader;
  std::vector<Point3> samples;
  std::string error;
  if (!ExtractSamples(Read(reader, file), samples, error))
  {
    throw Failure(file + ": " + error);
  }
  return samples;
}

vtkSmartPointer<vtkMultiBlockDataSet> LoadStoredFlowComplex(const std::string& file)
{
  if (ExtensionOf(file) != ".vtm")
  {
    return nullptr;
  }
  {
    vtkNew<vtkPointCloudReader> check;
    Read(check, file);
  }
  vtkNew<vtkXMLMultiBlockDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkSmartPointer<vtkMultiBlockDataSet> data =
    vtkMultiBlockDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  return CriticalPointsBlock(data) ? data : nullptr;
}

vtkDataObject* CriticalPointsBlock(vtkDataObject* data)
{
  vtkDataObject* block = NamedBlock(vtkMultiBlockDataSet::SafeDownCast(data),
    vtkFlowComplex::BlockName(vtkFlowComplex::CRITICAL_POINTS));
  return block && block->GetFieldData()->GetArray(names::NodeCountByIndex) ? block : nullptr;
}

bool IsSimplified(vtkMultiBlockDataSet* complex)
{
  auto* points = vtkPolyData::SafeDownCast(NamedBlock(complex, names::CriticalPoints));
  return points && points->GetPointData()->GetArray(names::Cancelled);
}

void RunFilter(vtkAlgorithm* filter, const std::string& input, const FlowComplexOptions& options,
  const char* what)
{
  vtkSmartPointer<ProgressLine> progress = ProgressLine::Make(options.Label, options.Quiet);
  filter->AddObserver(vtkCommand::ProgressEvent, progress);
  RunMessages().Clear();
  const int ok = filter->GetExecutive()->Update();
  progress->Finish();
  ThrowIfInterrupted();
  if (!ok)
  {
    const std::string error = RunMessages().FirstError();
    throw Failure(input + ": " + (error.empty() ? std::string(what) + " failed" : error));
  }
}

vtkSmartPointer<vtkMultiBlockDataSet> ComputeFlowComplex(
  const std::string& file, const FlowComplexOptions& options)
{
  vtkNew<vtkPointCloudReader> reader;
  Read(reader, file);
  vtkNew<vtkFlowComplex> filter;
  filter->SetInputConnection(reader->GetOutputPort());
  filter->SetComputeStableManifolds(options.Stable);
  filter->SetMaximumStableManifoldCells(options.MaxCells);
  filter->SetComputeUnstableManifolds(options.Unstable);
  // complex, diagram and info give the whole Hasse diagram; reconstruct of a
  // cloud defers patches by itself (CloudReconstruction).
  filter->SetDeferPatchesAbove(0);
  RunFilter(filter, file, options, "flow complex computation");
  auto* output = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  if (!output || output->GetNumberOfBlocks() == 0)
  {
    throw Failure(file + ": flow complex computation failed");
  }
  return output;
}

} // namespace flowrecon::cli
