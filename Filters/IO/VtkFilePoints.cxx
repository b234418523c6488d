// The points of legacy and XML VTK files (see VtkFilePoints.h): VTK's reader
// in a child process, then the points and shared point data of every leaf.
#include "VtkFilePoints.h"

#include "IsolatedRead.h"
#include "PackedPoints.h"
#include "PointCloudParsing.h"
#include "VtkMessageCapture.h"

#include "MemoryGuard.h" // core: bounds allocations the file cannot
#include "Progress.h"    // core: InputError

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLGenericDataObjectReader.h"

#include <cmath>

namespace flowrecon
{
namespace reader
{
namespace
{

// Appends the points of a data set or of every leaf of a composite data set;
// the point data arrays all leaves share go to `pointData`.
void ExtractPoints(
  const std::string& file, vtkDataObject* data, std::vector<double>& xyz, vtkPointData* pointData)
{
  std::vector<vtkDataSet*> leaves;
  if (auto* dataSet = vtkDataSet::SafeDownCast(data))
  {
    leaves.push_back(dataSet);
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
      if (leaf && leaf->GetNumberOfPoints() > 0)
      {
        leaves.push_back(leaf);
      }
    }
  }
  else
  {
    Fail(file, 0, std::string("holds a ") + data->GetClassName() + ", not a data set with points");
  }
  vtkIdType total = 0;
  vtkDataSetAttributes::FieldList arrays(static_cast<int>(leaves.size()));
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    total += leaves[i]->GetNumberOfPoints();
    if (i == 0)
    {
      arrays.InitializeFieldList(leaves[i]->GetPointData());
    }
    else
    {
      arrays.IntersectFieldList(leaves[i]->GetPointData());
    }
  }
  // Image and rectilinear grids have implicit points: bound them before allocating.
  constexpr vtkIdType maximumPoints = vtkIdType(1) << 30;
  if (total > maximumPoints)
  {
    Fail(file, 0, "too many points (" + std::to_string(total) + ")");
  }
  // Below that bound an image of 10^9 implicit points still asks for 24 GB
  // that no file size bounds: ask the memory guard (3 doubles a point and as
  // much again for the point data, a generous guess).
  try
  {
    flowrecon::RequireMemory(48.0 * static_cast<double>(total),
      "reading " + std::to_string(total) + " points", "use a smaller or subsampled file");
  }
  catch (const flowrecon::InputError& e)
  {
    Fail(file, 0, e.what());
  }
  xyz.reserve(3 * static_cast<std::size_t>(total));
  pointData->CopyAllocate(arrays, total);
  vtkIdType next = 0;
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    vtkDataSet* leaf = leaves[i];
    const vtkIdType n = leaf->GetNumberOfPoints();
    for (vtkIdType id = 0; id < n; ++id)
    {
      double p[3];
      leaf->GetPoint(id, p);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        Fail(file, 0, "point " + std::to_string(next + id) + " has a non-finite coordinate");
      }
      xyz.insert(xyz.end(), p, p + 3);
    }
    pointData->CopyData(arrays, leaf->GetPointData(), static_cast<int>(i), next, n, 0);
    next += n;
  }
}

// Reads `file` with `reader` in a child process (IsolatedRead.h), which hands
// back the points and shared point data.
void ReadPoints(const std::string& file, vtkAlgorithm* reader, const char* kind,
  std::vector<double>& xyz, vtkPointData* pointData)
{
  const std::string packed = ReadIsolated(file, kind, [&]() {
    UpdateCaptured(file, reader, kind);
    std::vector<double> points;
    vtkNew<vtkPointData> data;
    ExtractPoints(file, reader->GetOutputDataObject(0), points, data);
    return PackPoints(points, data);
  });
  UnpackPoints(file, packed, xyz, pointData);
}

} // namespace

void ReadLegacyVtk(const std::string& file, std::vector<double>& xyz, vtkPointData* pointData)
{
  auto reader = vtkSmartPointer<vtkGenericDataObjectReader>::New();
  reader->SetFileName(file.c_str());
  // Every array, not only the first scalars/vectors.
  reader->ReadAllScalarsOn();
  reader->ReadAllVectorsOn();
  reader->ReadAllNormalsOn();
  reader->ReadAllTensorsOn();
  reader->ReadAllColorScalarsOn();
  reader->ReadAllTCoordsOn();
  reader->ReadAllFieldsOn();
  ReadPoints(file, reader, "legacy VTK", xyz, pointData);
}

void ReadXmlVtk(const std::string& file, std::vector<double>& xyz, vtkPointData* pointData)
{
  auto reader = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
  reader->SetFileName(file.c_str());
  ReadPoints(file, reader, "VTK XML", xyz, pointData);
}

} // namespace reader
} // namespace flowrecon
