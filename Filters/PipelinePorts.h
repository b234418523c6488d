// What the filters share about their ports: the inputs a cloud filter accepts,
// the whole input it asks for, the pieces it leaves empty, each output's type,
// and the empty outputs of an early return.
#ifndef PipelinePorts_h
#define PipelinePorts_h

#include "vtkAlgorithm.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

namespace flowrecon
{

/// A point cloud: the points of any vtkDataSet, or a vtkTable's x, y, z columns.
inline void AcceptPointCloud(vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkTable");
}

/// The distance function depends on every sample: the whole input, in one piece.
inline void RequestWholeInput(vtkInformationVector** inputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
}

/// Whether a parallel run asks for a piece after the first: piece 0 holds the
/// whole (global) result, the others stay empty.
inline bool IsLaterPiece(vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  return outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0;
}

/// The number of output ports of a filter whose port types are `types`, so
/// that the count and the types come from one list.
template <int N>
constexpr int PortCount(const char* const (&)[N])
{
  return N;
}

/// Sets output port `port`'s data type from `types`, one per port; false for a
/// port past them.
template <int N>
bool SetOutputType(vtkInformation* info, int port, const char* const (&types)[N])
{
  if (port < 0 || port >= N)
  {
    return false;
  }
  info->Set(vtkDataObject::DATA_TYPE_NAME(), types[port]);
  return true;
}

/// Whether every output port holds a data object of its type in `types`, so
/// that RequestData can use them unchecked.
template <int N>
bool HasOutputs(vtkInformationVector* outputVector, const char* const (&types)[N])
{
  for (int port = 0; port < N; ++port)
  {
    vtkDataObject* output = vtkDataObject::GetData(outputVector, port);
    if (!output || !output->IsA(types[port]))
    {
      return false;
    }
  }
  return true;
}

/// What every early return leaves: every output empty.
inline void EmptyOutputs(vtkInformationVector* outputVector)
{
  for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
  {
    if (vtkDataObject* output = vtkDataObject::GetData(outputVector, port))
    {
      output->Initialize();
    }
  }
}

} // namespace flowrecon

#endif
