#include "SurvivingBlocks.h"

#include "ContractArrays.h"
#include "FlowReconNames.h"

#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <vector>

namespace flowrecon
{

namespace
{

/// The part of `in` made of the points with `keepPoint` and the cells with
/// `keepCell` (all of whose points are kept), renumbered in order, with every
/// point and cell array. Cells keep their order: a block holds one cell type.
vtkSmartPointer<vtkPolyData> Part(
  vtkPolyData* in, const std::vector<bool>& keepPoint, const std::vector<bool>& keepCell)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  if (std::find(keepPoint.begin(), keepPoint.end(), false) == keepPoint.end() &&
    std::find(keepCell.begin(), keepCell.end(), false) == keepCell.end())
  {
    // Nothing cancelled (t_p 0): the same points, cells and arrays, shared.
    out->ShallowCopy(in);
    out->SetFieldData(vtkNew<vtkFieldData>());
    return out;
  }
  std::vector<vtkIdType> newId(keepPoint.size(), -1);
  vtkNew<vtkIdList> fromPoints, toPoints, fromCells, toCells, ids;
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(keepPoint.size()); ++p)
  {
    if (keepPoint[p])
    {
      newId[p] = fromPoints->GetNumberOfIds();
      toPoints->InsertNextId(newId[p]);
      fromPoints->InsertNextId(p);
    }
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(in->GetPoints()->GetDataType());
  points->SetNumberOfPoints(fromPoints->GetNumberOfIds());
  in->GetPoints()->GetPoints(fromPoints, points);
  out->SetPoints(points);
  out->GetPointData()->CopyAllocate(in->GetPointData(), fromPoints->GetNumberOfIds());
  out->GetPointData()->CopyData(in->GetPointData(), fromPoints, toPoints);
  out->AllocateCopy(in);
  for (vtkIdType c = 0; c < static_cast<vtkIdType>(keepCell.size()); ++c)
  {
    if (keepCell[c])
    {
      in->GetCellPoints(c, ids);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        ids->SetId(k, newId[ids->GetId(k)]);
      }
      toCells->InsertNextId(out->InsertNextCell(in->GetCellType(c), ids));
      fromCells->InsertNextId(c);
    }
  }
  out->GetCellData()->CopyAllocate(in->GetCellData(), fromCells->GetNumberOfIds());
  out->GetCellData()->CopyData(in->GetCellData(), fromCells, toCells);
  return out;
}

/// Whether each tuple of `cancelled` is 0.
std::vector<bool> Survives(vtkDataArray* cancelled)
{
  std::vector<bool> keep(static_cast<std::size_t>(cancelled->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < cancelled->GetNumberOfTuples(); ++i)
  {
    keep[i] = cancelled->GetComponent(i, 0) == 0;
  }
  return keep;
}

vtkSmartPointer<vtkPolyData> SurvivingCriticalPoints(vtkPolyData* cp)
{
  vtkDataArray* cancelled = cp->GetPointData()->GetArray(names::Cancelled);
  if (!cancelled || cancelled->GetNumberOfTuples() != cp->GetNumberOfPoints())
  {
    return nullptr;
  }
  const std::vector<bool> keepPoint = Survives(cancelled);
  std::vector<bool> keepCell(static_cast<std::size_t>(cp->GetNumberOfCells()), true);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < cp->GetNumberOfCells(); ++c)
  {
    cp->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      keepCell[c] = keepCell[c] && keepPoint[ids->GetId(k)];
    }
  }
  return Part(cp, keepPoint, keepCell);
}

vtkSmartPointer<vtkPolyData> SurvivingGabrielEdges(vtkPolyData* ge)
{
  vtkDataArray* cancelled = ge->GetCellData()->GetArray(names::Cancelled);
  if (!cancelled || cancelled->GetNumberOfTuples() != ge->GetNumberOfCells())
  {
    return nullptr;
  }
  return Part(ge, std::vector<bool>(static_cast<std::size_t>(ge->GetNumberOfPoints()), true),
    Survives(cancelled));
}

void Append(vtkMultiBlockDataSet* output, vtkPolyData* block, const char* name)
{
  if (block)
  {
    const unsigned int b = output->GetNumberOfBlocks();
    output->SetBlock(b, block);
    output->GetMetaData(b)->Set(vtkCompositeDataSet::NAME(), name);
  }
}

} // namespace

void AddSurvivingBlocks(vtkMultiBlockDataSet* output)
{
  auto* cp = vtkPolyData::SafeDownCast(NamedBlock(output, names::CriticalPoints));
  auto* ge = vtkPolyData::SafeDownCast(NamedBlock(output, names::GabrielEdges));
  Append(output, cp ? SurvivingCriticalPoints(cp) : nullptr, names::SurvivingCriticalPoints);
  Append(output, ge ? SurvivingGabrielEdges(ge) : nullptr, names::SurvivingGabrielEdges);
}

} // namespace flowrecon
