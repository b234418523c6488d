#include "ContractArrays.h"

#include "vtkCompositeDataSet.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPoints.h"

#include <cstring>

namespace flowrecon
{

vtkDataObject* NamedBlock(vtkMultiBlockDataSet* input, const char* name)
{
  if (!input)
  {
    return nullptr;
  }
  for (unsigned int b = 0; b < input->GetNumberOfBlocks(); ++b)
  {
    vtkInformation* meta = input->HasMetaData(b) ? input->GetMetaData(b) : nullptr;
    const char* blockName = meta ? meta->Get(vtkCompositeDataSet::NAME()) : nullptr;
    if (blockName && std::strcmp(blockName, name) == 0)
    {
      return input->GetBlock(b);
    }
  }
  return nullptr;
}

vtkDataArray* RequiredArray(vtkFieldData* data, const char* block, const char* name,
  int components, vtkIdType n, std::string& error)
{
  vtkDataArray* a = data ? data->GetArray(name) : nullptr;
  if (!a)
  {
    error = std::string("not a flow complex: block ") + block + " has no array " + name;
    return nullptr;
  }
  if (a->GetNumberOfComponents() != components || a->GetNumberOfTuples() != n)
  {
    error = std::string("block ") + block + ": array " + name + " has the wrong size";
    return nullptr;
  }
  return a;
}

vtkSmartPointer<vtkPoints> MakePoints(const std::vector<Point3>& pts)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), pts[i].data());
  }
  return points;
}

} // namespace flowrecon
