#include "SimplificationConversion.h"

#include "ContractArrays.h"
#include "FlowReconNames.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <string>
#include <vector>

namespace flowrecon
{

namespace
{

/// A field array named `name` holding `values` (one half of compressed rows).
vtkSmartPointer<vtkIdTypeArray> IdArray(const char* name, const std::vector<Id>& values)
{
  auto a = NamedArray<vtkIdTypeArray>(name);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    a->SetValue(static_cast<vtkIdType>(k), values[k]);
  }
  return a;
}

vtkSmartPointer<vtkPolyData> PersistencePairsBlock(const FlowComplex& fc, const SimplificationResult& s)
{
  std::vector<Point3> pts;
  vtkNew<vtkCellArray> lines;
  for (const CancelledPair& p : s.Pairs)
  {
    const vtkIdType ids[2] = { static_cast<vtkIdType>(pts.size()),
      static_cast<vtkIdType>(pts.size() + 1) };
    pts.push_back(fc.Nodes[p.Lower].Location);
    pts.push_back(fc.Nodes[p.Upper].Location);
    lines->InsertNextCell(2, ids);
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(MakePoints(pts));
  pd->SetLines(lines);
  vtkCellData* cd = pd->GetCellData();
  cd->AddArray(Column<vtkDoubleArray>(flowrecon::names::Ratio, s.Pairs, &CancelledPair::Ratio));
  cd->AddArray(Column<vtkDoubleArray>(flowrecon::names::Birth, s.Pairs, &CancelledPair::Birth));
  cd->AddArray(Column<vtkDoubleArray>(flowrecon::names::Death, s.Pairs, &CancelledPair::Death));
  cd->AddArray(Column<vtkIntArray>(flowrecon::names::PairType, s.Pairs, &CancelledPair::PairType));
  cd->AddArray(Column<vtkIdTypeArray>(flowrecon::names::LowerNodeId, s.Pairs, &CancelledPair::Lower));
  cd->AddArray(Column<vtkIdTypeArray>(flowrecon::names::UpperNodeId, s.Pairs, &CancelledPair::Upper));
  pd->GetCellData()->SetActiveScalars(flowrecon::names::Ratio);
  return pd;
}

} // namespace

void AddSimplification(const FlowComplex& fc, const SimplificationResult& s, double threshold,
  vtkMultiBlockDataSet* output)
{
  auto* cp = vtkPolyData::SafeDownCast(NamedBlock(output, flowrecon::names::CriticalPoints));
  auto* sm = vtkUnstructuredGrid::SafeDownCast(NamedBlock(output, flowrecon::names::StableManifolds));
  if (cp)
  {
    vtkDataArray* nodeId = cp->GetPointData()->GetArray(flowrecon::names::NodeId);
    auto cancelled = NamedArray<vtkUnsignedCharArray>(flowrecon::names::Cancelled);
    cancelled->SetNumberOfTuples(cp->GetNumberOfPoints());
    for (vtkIdType i = 0; i < cp->GetNumberOfPoints(); ++i)
    {
      cancelled->SetValue(i, s.Survives[IdValue(nodeId, i)] ? 0 : 1);
    }
    cp->GetPointData()->AddArray(cancelled);
  }
  auto* ge = vtkPolyData::SafeDownCast(NamedBlock(output, flowrecon::names::GabrielEdges));
  vtkDataArray* edgeNode = ge ? ge->GetCellData()->GetArray(flowrecon::names::NodeId) : nullptr;
  if (edgeNode && edgeNode->GetNumberOfTuples() == ge->GetNumberOfCells())
  {
    auto cancelled = NamedArray<vtkUnsignedCharArray>(flowrecon::names::Cancelled);
    cancelled->SetNumberOfTuples(ge->GetNumberOfCells());
    for (vtkIdType c = 0; c < ge->GetNumberOfCells(); ++c)
    {
      const Id node = IdValue(edgeNode, c);
      const bool known = node >= 0 && node < static_cast<Id>(s.Survives.size());
      cancelled->SetValue(c, known && !s.Survives[node] ? 1 : 0);
    }
    ge->GetCellData()->AddArray(cancelled);
  }
  if (sm)
  {
    vtkDataArray* nodeId = sm->GetCellData()->GetArray(flowrecon::names::NodeId);
    auto owner = NamedArray<vtkIdTypeArray>(flowrecon::names::Owner);
    owner->SetNumberOfTuples(sm->GetNumberOfCells());
    for (vtkIdType c = 0; c < sm->GetNumberOfCells(); ++c)
    {
      const Id node = IdValue(nodeId, c);
      const RowRange<Id> owners = s.OwnerRow(node);
      owner->SetValue(c, s.Survives[node] ? node : (owners.empty() ? -1 : owners[0]));
    }
    sm->GetCellData()->AddArray(owner);
  }
  auto offsets = IdArray("OwnerOffsets", s.Owners.Offsets);
  auto owners = IdArray("Owners", s.Owners.Values);
  auto tp = NamedArray<vtkDoubleArray>("PersistenceThreshold");
  tp->InsertNextValue(threshold);
  auto pairs = NamedArray<vtkIdTypeArray>("CancelledPairCount");
  pairs->InsertNextValue(static_cast<vtkIdType>(s.Pairs.size()));
  // What a replay of the cancellations on deferred patches needs (recorded when
  // the complex has some): per pair, its odd lowers and its direct owners.
  std::vector<vtkSmartPointer<vtkIdTypeArray>> replay;
  if (s.HasLowers)
  {
    replay = { IdArray(flowrecon::names::PairLowerOffsets, s.Lowers.Offsets),
      IdArray(flowrecon::names::PairLowers, s.Lowers.Values),
      IdArray(flowrecon::names::PairOwnerOffsets, s.DirectOwners.Offsets),
      IdArray(flowrecon::names::PairOwners, s.DirectOwners.Values) };
  }
  for (vtkFieldData* fd : { cp ? cp->GetFieldData() : nullptr, output->GetFieldData() })
  {
    if (fd)
    {
      for (const auto& a : replay)
      {
        fd->AddArray(a);
      }
      fd->AddArray(offsets);
      fd->AddArray(owners);
      fd->AddArray(tp);
      fd->AddArray(pairs);
    }
  }
  const unsigned int b = output->GetNumberOfBlocks();
  output->SetNumberOfBlocks(b + 1);
  output->SetBlock(b, PersistencePairsBlock(fc, s));
  output->GetMetaData(b)->Set(vtkCompositeDataSet::NAME(), flowrecon::names::PersistencePairs);
}

namespace
{

/// Compressed rows of `fd` named `offsetsName` (`rows` + 1 increasing values
/// from 0) and `valuesName` (node ids), into `out`.
bool ReadRows(vtkFieldData* fd, const char* offsetsName, const char* valuesName, Id rows,
  Id nodeCount, CompressedRows<Id>& out, std::string& error)
{
  vtkDataArray* o = fd->GetArray(offsetsName);
  vtkDataArray* v = fd->GetArray(valuesName);
  const std::string where = std::string("block CriticalPoints: ") + offsetsName + "/" + valuesName;
  if (!o || !v || o->GetNumberOfComponents() != 1 || v->GetNumberOfComponents() != 1 ||
    o->GetNumberOfTuples() != rows + 1)
  {
    error = where + " missing or not " + std::to_string(rows) + " rows";
    return false;
  }
  std::vector<Id>& offsets = out.Offsets;
  offsets.resize(static_cast<std::size_t>(rows + 1));
  for (vtkIdType k = 0; k <= rows; ++k)
  {
    offsets[k] = IdValue(o, k);
    if ((k == 0 && offsets[k] != 0) || (k > 0 && offsets[k] < offsets[k - 1]))
    {
      error = where + " offsets do not increase from 0";
      return false;
    }
  }
  if (offsets.back() != v->GetNumberOfTuples())
  {
    error = where + " offsets do not match the values";
    return false;
  }
  std::vector<Id>& values = out.Values;
  values.resize(static_cast<std::size_t>(v->GetNumberOfTuples()));
  for (vtkIdType k = 0; k < v->GetNumberOfTuples(); ++k)
  {
    values[k] = IdValue(v, k);
    if (values[k] < 0 || values[k] >= nodeCount)
    {
      error = where + " names a node that does not exist";
      return false;
    }
  }
  return true;
}

bool ReadReplay(vtkMultiBlockDataSet* input, vtkFieldData* fd, Id nodeCount,
  SimplificationResult& s, std::string& error)
{
  if (!fd->GetArray(flowrecon::names::PairLowerOffsets))
  {
    return true; // a simplification of a complete complex: nothing to replay
  }
  auto* pp = vtkPolyData::SafeDownCast(NamedBlock(input, flowrecon::names::PersistencePairs));
  vtkDataArray* count = fd->GetArray("CancelledPairCount");
  if (!pp || !count || count->GetNumberOfTuples() < 1)
  {
    error = "block PersistencePairs: missing, but the replay arrays need its pairs";
    return false;
  }
  const Id pairs = static_cast<Id>(count->GetComponent(0, 0));
  const char* block = flowrecon::names::PersistencePairs;
  vtkCellData* cd = pp->GetCellData();
  vtkDataArray* lower = RequiredArray(cd, block, flowrecon::names::LowerNodeId, 1, pairs, error);
  vtkDataArray* upper = lower ? RequiredArray(cd, block, flowrecon::names::UpperNodeId, 1, pairs, error) : nullptr;
  vtkDataArray* type = upper ? RequiredArray(cd, block, flowrecon::names::PairType, 1, pairs, error) : nullptr;
  vtkDataArray* ratio = type ? RequiredArray(cd, block, flowrecon::names::Ratio, 1, pairs, error) : nullptr;
  if (!ratio || pp->GetNumberOfCells() != pairs)
  {
    error = error.empty() ? std::string(block) + ": not one line per cancelled pair" : error;
    return false;
  }
  s.Pairs.resize(static_cast<std::size_t>(pairs));
  for (vtkIdType p = 0; p < pairs; ++p)
  {
    CancelledPair& c = s.Pairs[p];
    c.Lower = IdValue(lower, p);
    c.Upper = IdValue(upper, p);
    c.PairType = static_cast<int>(IdValue(type, p));
    c.Ratio = ratio->GetComponent(p, 0);
    if (c.Lower < 0 || c.Lower >= nodeCount || c.Upper < 0 || c.Upper >= nodeCount ||
      s.Survives[c.Lower] || s.Survives[c.Upper] || c.PairType < 1 || c.PairType > 2)
    {
      error = std::string("block ") + block + ": a pair whose nodes are not cancelled ones";
      return false;
    }
  }
  if (!ReadRows(fd, flowrecon::names::PairLowerOffsets, flowrecon::names::PairLowers, pairs,
        nodeCount, s.Lowers, error) ||
    !ReadRows(fd, flowrecon::names::PairOwnerOffsets, flowrecon::names::PairOwners, pairs,
      nodeCount, s.DirectOwners, error))
  {
    return false;
  }
  s.HasLowers = true;
  return true;
}

} // namespace

bool SimplificationFromMultiBlock(vtkMultiBlockDataSet* input, Id nodeCount,
  SimplificationResult& s, std::string& error)
{
  s = SimplificationResult();
  s.Survives.assign(static_cast<std::size_t>(nodeCount), true);
  s.Owners.Offsets.assign(static_cast<std::size_t>(nodeCount + 1), 0);
  error.clear();
  auto* cp = vtkPolyData::SafeDownCast(NamedBlock(input, flowrecon::names::CriticalPoints));
  vtkDataArray* cancelled = cp ? cp->GetPointData()->GetArray(flowrecon::names::Cancelled) : nullptr;
  if (!cancelled)
  {
    return false;
  }
  const char* block = flowrecon::names::CriticalPoints;
  vtkDataArray* nodeId = RequiredArray(cp->GetPointData(), block, flowrecon::names::NodeId, 1, nodeCount, error);
  if (!nodeId || cancelled->GetNumberOfTuples() != nodeCount)
  {
    error = error.empty() ? "block CriticalPoints: the simplification arrays are incomplete" : error;
    return false;
  }
  for (vtkIdType i = 0; i < nodeCount; ++i)
  {
    s.Survives[IdValue(nodeId, i)] = cancelled->GetComponent(i, 0) == 0;
  }
  if (!ReadRows(cp->GetFieldData(), "OwnerOffsets", "Owners", nodeCount, nodeCount, s.Owners, error))
  {
    return false;
  }
  return ReadReplay(input, cp->GetFieldData(), nodeCount, s, error);
}

} // namespace flowrecon
