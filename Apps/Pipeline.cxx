#include "Pipeline.h"

#include "FlowComplexConversion.h"
#include "FlowReconNames.h"
#include "Interrupt.h"
#include "IsolatedRead.h"
#include "OutputFiles.h"
#include "PointCloudParsing.h" // reader::ReadError
#include "VtkMessageCapture.h"
#include "vtkFlowComplex.h"
#include "vtkPointCloudReader.h"

#include "vtkCommand.h"
#include "vtkCompositeDataIterator.h"
#include "vtkDataSet.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkXMLMultiBlockDataReader.h"

#include <cmath>
#include <filesystem>

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

// A stored complex's points must be finite, as a cloud's are: the core
// triangulates its samples again.
void RequireFinitePoints(const std::string& file, vtkMultiBlockDataSet* data)
{
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(data->NewIterator());
  vtkIdType next = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
    for (vtkIdType id = 0; leaf && id < leaf->GetNumberOfPoints(); ++id, ++next)
    {
      double p[3];
      leaf->GetPoint(id, p);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        throw Failure(file + ": point " + std::to_string(next) + " has a non-finite coordinate");
      }
    }
  }
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
  // A missing, special or empty file is the point cloud reader's to name.
  std::error_code error;
  if (ExtensionOf(file) != ".vtm" || !std::filesystem::is_regular_file(file, error) ||
    std::filesystem::file_size(file, error) == 0)
  {
    return nullptr;
  }
  vtkNew<vtkXMLMultiBlockDataReader> reader;
  reader->SetFileName(file.c_str());
  try
  {
    // VTK's reader crashes on some corrupt files: it reads in a child process
    // that then goes on with the command, watched by this one (IsolatedRead.h).
    reader::ReadThenGoOnInChild(
      file, "VTK XML", [&]() { reader::UpdateCaptured(file, reader, "VTK XML"); });
  }
  catch (const reader::ReadError& e)
  {
    throw Failure(e.what());
  }
  catch (const VtkAllocationFailure& e)
  {
    throw Failure(file + ": out of memory (" + reader::OneLine(e.what()) + ")");
  }
  catch (const std::bad_alloc&)
  {
    throw Failure(file + ": out of memory");
  }
  vtkSmartPointer<vtkMultiBlockDataSet> data =
    vtkMultiBlockDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (!CriticalPointsBlock(data))
  {
    return nullptr;
  }
  RequireFinitePoints(file, data);
  return data;
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
