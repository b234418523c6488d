#include "vtkFlowReconstruction.h"

#include "CoreCall.h"
#include "FlowComplexConversion.h"
#include "Reconstruction.h"
#include "Simplification.h"
#include "StableManifoldGeometry.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

using flowrecon::Id;

/// The t_r = infinity run of one input and what the outputs need from it.
struct vtkFlowReconstruction::Cache
{
  vtkMTimeType InputTime = 0;
  flowrecon::FlowComplex FC;
  flowrecon::ReconstructionResult Run;
  /// Node whose insertion brings each node's cells: itself, the earliest
  /// reconstructed owner of a cancelled node, or -1.
  std::vector<Id> Carrier;
  /// The T_max whose geometry FC holds (-1: none yet).
  double GeometryThreshold = -1;
  /// Triangles and tetrahedra of each node (compressed rows of cell positions).
  std::vector<Id> TriangleOffsets, TriangleList, TetraOffsets, TetraList;
};

namespace
{

void GroupByNode(const std::vector<Id>& cellNode, std::size_t nodes, std::vector<Id>& offsets,
  std::vector<Id>& list)
{
  offsets.assign(nodes + 1, 0);
  for (Id node : cellNode)
  {
    ++offsets[node + 1];
  }
  for (std::size_t i = 0; i < nodes; ++i)
  {
    offsets[i + 1] += offsets[i];
  }
  list.resize(cellNode.size());
  std::vector<Id> next(offsets.begin(), offsets.end() - 1);
  for (std::size_t c = 0; c < cellNode.size(); ++c)
  {
    list[next[cellNode[c]]++] = static_cast<Id>(c);
  }
}

using flowrecon::NamedArray;

/// The arrays that describe an insertion, in all three outputs (cells of the
/// reconstruction, rows of the profile, sponsor arrows): Step, NodeId, Priority,
/// Extension, Sponsor.
struct InsertionArrays
{
  vtkSmartPointer<vtkIdTypeArray> Step = NamedArray<vtkIdTypeArray>("Step");
  vtkSmartPointer<vtkIdTypeArray> NodeId = NamedArray<vtkIdTypeArray>("NodeId");
  vtkSmartPointer<vtkDoubleArray> Priority = NamedArray<vtkDoubleArray>("Priority");
  vtkSmartPointer<vtkIntArray> Extension = NamedArray<vtkIntArray>("Extension");
  vtkSmartPointer<vtkIdTypeArray> Sponsor = NamedArray<vtkIdTypeArray>("Sponsor");

  void Append(Id step, Id node, const flowrecon::Insertion& in)
  {
    this->Step->InsertNextValue(step);
    this->NodeId->InsertNextValue(node);
    this->Priority->InsertNextValue(in.Priority);
    this->Extension->InsertNextValue(static_cast<int>(in.Kind));
    this->Sponsor->InsertNextValue(in.Sponsor);
  }
  std::array<vtkDataArray*, 5> All() const
  {
    return { { this->Step, this->NodeId, this->Priority, this->Extension, this->Sponsor } };
  }
};

} // namespace

vtkStandardNewMacro(vtkFlowReconstruction);

//------------------------------------------------------------------------------
vtkFlowReconstruction::vtkFlowReconstruction()
{
  this->SetNumberOfOutputPorts(3);
}

//------------------------------------------------------------------------------
vtkFlowReconstruction::~vtkFlowReconstruction() = default;

//------------------------------------------------------------------------------
int vtkFlowReconstruction::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

//------------------------------------------------------------------------------
int vtkFlowReconstruction::FillOutputPortInformation(int port, vtkInformation* info)
{
  const char* types[3] = { "vtkUnstructuredGrid", "vtkTable", "vtkPolyData" };
  if (port < 0 || port > 2)
  {
    return 0;
  }
  info->Set(vtkDataObject::DATA_TYPE_NAME(), types[port]);
  return 1;
}

//------------------------------------------------------------------------------
int vtkFlowReconstruction::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkMultiBlockDataSet* input = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  auto* grid = vtkUnstructuredGrid::GetData(outputVector, RECONSTRUCTION);
  auto* profile = vtkTable::GetData(outputVector, PROFILE);
  auto* arrows = vtkPolyData::GetData(outputVector, SPONSOR_ARROWS);
  if (!input || !grid || !profile || !arrows)
  {
    vtkErrorMacro("Missing input or output.");
    return 0;
  }

  if (input->GetNumberOfBlocks() == 0)
  {
    // Empty in, empty out: what the other ranks of a parallel run receive
    // (vtkFlowComplex computes on rank 0 only).
    grid->Initialize();
    profile->Initialize();
    arrows->Initialize();
    return 1;
  }
  // The queue runs only for a new input; a new threshold only re-selects.
  if (!this->Cached || this->Cached->InputTime != input->GetMTime())
  {
    this->Cached.reset();
    auto cache = std::unique_ptr<Cache>(new Cache);
    cache->InputTime = input->GetMTime();
    flowrecon::SimplificationResult s;
    std::string error;
    if (!flowrecon::FromMultiBlock(input, cache->FC, error) ||
      (!flowrecon::SimplificationFromMultiBlock(
         input, static_cast<Id>(cache->FC.Nodes.size()), s, error) &&
        !error.empty()))
    {
      vtkErrorMacro(<< error);
      return 0;
    }
    const auto& nodes = cache->FC.Nodes;
    // The queue is 30% of the work, drawing 60%, the selection the rest.
    const flowrecon::Progress progress = flowrecon::AlgorithmProgress(this, 0.3);
    bool finished = false;
    const int ok = flowrecon::CallCore(
      this, "reconstruction",
      [&]() {
        const std::vector<Id> init = flowrecon::InitializationEdges(
          nodes, flowrecon::NearestNeighboursFromDiagram(nodes, cache->FC.Arcs));
        ++this->NumberOfQueueRuns;
        cache->Run =
          flowrecon::Reconstruct(nodes, cache->FC.Arcs, s.Survives, init, HUGE_VAL, progress);
        finished = true;
      },
      [&]() {
        grid->Initialize();
        profile->Initialize();
        arrows->Initialize();
      });
    if (!finished)
    {
      return ok; // failed (0) or aborted (1, nothing cached)
    }
    const auto& steps = cache->Run.Nodes;
    cache->Carrier.assign(nodes.size(), -1);
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
      if (s.Survives[i])
      {
        cache->Carrier[i] = steps[i].Step >= 0 ? static_cast<Id>(i) : -1;
        continue;
      }
      for (const Id* o = s.OwnersBegin(i); o != s.OwnersEnd(i); ++o)
      {
        const Id c = cache->Carrier[i];
        if (steps[*o].Step >= 0 && (c < 0 || steps[*o].Step < steps[c].Step))
        {
          cache->Carrier[i] = *o;
        }
      }
    }
    this->Cached = std::move(cache);
  }
  const double tmax = this->MaximumThreshold >= VTK_DOUBLE_MAX ? HUGE_VAL : this->MaximumThreshold;
  if (this->Cached->GeometryThreshold != tmax && !this->DrawGeometry(tmax))
  {
    grid->Initialize();
    profile->Initialize();
    arrows->Initialize();
    return this->GetAbortExecute() ? 1 : 0;
  }

  const Cache& c = *this->Cached;
  const flowrecon::FlowComplex& fc = c.FC;
  const auto& steps = c.Run.Nodes;
  double t =
    this->ReconstructionThreshold >= VTK_DOUBLE_MAX ? HUGE_VAL : this->ReconstructionThreshold;
  if (t > tmax)
  {
    vtkWarningMacro(<< "ReconstructionThreshold " << t << " is above MaximumThreshold " << tmax
                    << ": showing the reconstruction at " << tmax);
    t = tmax;
  }
  this->SetProgressText("output");
  this->UpdateProgress(0.9);

  // Nodes whose cells are in the reconstruction at t, in insertion order.
  std::vector<std::pair<Id, Id>> selected; // (step of the carrier, node)
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const Id carrier = c.Carrier[i];
    if (carrier >= 0 && c.Run.Contains(carrier, t))
    {
      selected.emplace_back(steps[carrier].Step, static_cast<Id>(i));
    }
  }
  std::sort(selected.begin(), selected.end());
  const std::vector<int> multiplicity =
    flowrecon::EdgeMultiplicities(fc.Nodes, fc.Arcs, c.Run, t);

  // Port 0: the cells, over the points they use (samples keep their input id).
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  auto original = NamedArray<vtkIdTypeArray>("vtkOriginalPointIds");
  std::vector<vtkIdType> pointOf(fc.Points.size(), -1);
  auto point = [&](Id p) {
    if (pointOf[p] < 0)
    {
      pointOf[p] = points->InsertNextPoint(fc.Points[p].data());
      original->InsertNextValue(p < fc.NumberOfInputPoints ? static_cast<vtkIdType>(p) : -1);
    }
    return pointOf[p];
  };
  grid->Initialize();
  InsertionArrays cellInsertion;
  auto index = NamedArray<vtkIntArray>("Index");
  auto value = NamedArray<vtkDoubleArray>("CriticalValue");
  auto threshold = NamedArray<vtkDoubleArray>("Threshold");
  auto owner = NamedArray<vtkIdTypeArray>("Owner");
  auto mult = NamedArray<vtkIntArray>("Multiplicity");
  grid->AllocateEstimate(static_cast<vtkIdType>(selected.size()), 3);
  auto add = [&](int type, int n, const vtkIdType* ids, Id node) {
    const Id carrier = c.Carrier[node];
    const flowrecon::Insertion& in = steps[carrier];
    vtkIdType local[4];
    for (int k = 0; k < n; ++k)
    {
      local[k] = point(ids[k]);
    }
    grid->InsertNextCell(type, n, local);
    cellInsertion.Append(in.Step, node, in);
    index->InsertNextValue(fc.Nodes[node].Index);
    value->InsertNextValue(fc.Nodes[node].Value);
    threshold->InsertNextValue(in.Threshold);
    owner->InsertNextValue(carrier);
    mult->InsertNextValue(fc.Nodes[node].Index == 1 ? multiplicity[node] : 0);
  };
  for (const auto& entry : selected)
  {
    const Id node = entry.second;
    const flowrecon::Node& n = fc.Nodes[node];
    if (n.Index == 0)
    {
      const vtkIdType v = n.Simplex[0];
      add(VTK_VERTEX, 1, &v, node);
    }
    else if (n.Index == 1)
    {
      const vtkIdType e[2] = { n.Simplex[0], n.Simplex[1] };
      add(VTK_LINE, 2, e, node);
    }
    for (Id k = c.TriangleOffsets[node]; k < c.TriangleOffsets[node + 1]; ++k)
    {
      const auto& tri = fc.Triangles[c.TriangleList[k]];
      const vtkIdType ids[3] = { tri[0], tri[1], tri[2] };
      add(VTK_TRIANGLE, 3, ids, node);
    }
    for (Id k = c.TetraOffsets[node]; k < c.TetraOffsets[node + 1]; ++k)
    {
      const auto& tet = fc.Tetrahedra[c.TetraList[k]];
      const vtkIdType ids[4] = { tet[0], tet[1], tet[2], tet[3] };
      add(VTK_TETRA, 4, ids, node);
    }
  }
  grid->SetPoints(points);
  grid->GetPointData()->AddArray(original);
  for (vtkDataArray* a : cellInsertion.All())
  {
    grid->GetCellData()->AddArray(a);
  }
  for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{ index, value, threshold, owner, mult })
  {
    grid->GetCellData()->AddArray(a);
  }
  grid->GetCellData()->SetActiveScalars("CriticalValue");

  // Port 1: the profile of the whole run.
  InsertionArrays rowInsertion;
  auto pIndex = NamedArray<vtkIntArray>("Index");
  auto pThreshold = NamedArray<vtkDoubleArray>("Threshold");
  for (std::size_t k = 0; k < c.Run.Order.size(); ++k)
  {
    const Id node = c.Run.Order[k];
    const flowrecon::Insertion& in = steps[node];
    rowInsertion.Append(static_cast<Id>(k), node, in);
    pIndex->InsertNextValue(fc.Nodes[node].Index);
    pThreshold->InsertNextValue(in.Threshold);
  }
  profile->Initialize();
  for (vtkDataArray* a : rowInsertion.All())
  {
    profile->AddColumn(a);
  }
  profile->AddColumn(pIndex);
  profile->AddColumn(pThreshold);

  // Port 2: sponsor -> node arrows of the current reconstruction.
  vtkNew<vtkPoints> arrowPoints;
  arrowPoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  InsertionArrays arrowInsertion;
  for (const Id node : c.Run.Order)
  {
    const flowrecon::Insertion& in = steps[node];
    if (!c.Run.Contains(node, t) || in.Sponsor < 0)
    {
      continue;
    }
    const vtkIdType ids[2] = { arrowPoints->InsertNextPoint(fc.Nodes[in.Sponsor].Location.data()),
      arrowPoints->InsertNextPoint(fc.Nodes[node].Location.data()) };
    lines->InsertNextCell(2, ids);
    arrowInsertion.Append(in.Step, node, in);
  }
  arrows->Initialize();
  arrows->SetPoints(arrowPoints);
  arrows->SetLines(lines);
  for (vtkDataArray* a : arrowInsertion.All())
  {
    arrows->GetCellData()->AddArray(a);
  }
  arrows->GetCellData()->SetActiveScalars("Priority");

  this->SetProgressText(nullptr);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkFlowReconstruction::DrawGeometry(double tmax)
{
  Cache& cache = *this->Cached;
  flowrecon::FlowComplex& fc = cache.FC;
  cache.GeometryThreshold = -1;
  // The nodes whose cells the output can show: carriers below T_max.
  std::vector<Id> draw;
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const Id carrier = cache.Carrier[i];
    if (fc.Nodes[i].Index >= 2 && carrier >= 0 && cache.Run.Contains(carrier, tmax))
    {
      draw.push_back(static_cast<Id>(i));
    }
  }
  // The input's own cells do when they cover every such node (a complex
  // computed with all its geometry); otherwise draw them from the samples.
  std::vector<char> drawn(fc.Nodes.size(), 0);
  for (const Id node : fc.TriangleNode)
  {
    drawn[node] = 1;
  }
  for (const Id node : fc.TetrahedronNode)
  {
    drawn[node] = 1;
  }
  const bool covered =
    std::all_of(draw.begin(), draw.end(), [&](Id node) { return drawn[node] != 0; });
  if (!covered)
  {
    const std::vector<flowrecon::Point3> samples(
      fc.Points.begin(), fc.Points.begin() + fc.NumberOfInputPoints);
    flowrecon::BuildOptions options;
    options.Seed = fc.Report.Seed;
    flowrecon::Progress progress = flowrecon::AlgorithmProgress(this);
    progress.Report = [this](double f, const char* phase) {
      this->SetProgressText(phase);
      this->UpdateProgress(0.3 + 0.6 * f);
    };
    bool finished = false;
    const int ok = flowrecon::CallCore(
      this, "drawing the stable manifolds",
      [&]() {
        flowrecon::DrawStableManifolds(samples, options, draw, fc, progress,
          "lower MaximumThreshold (flowrecon --tr-max), or the cloud's size");
        finished = true;
      },
      []() {});
    if (!finished)
    {
      (void)ok;
      return false;
    }
  }
  GroupByNode(fc.TriangleNode, fc.Nodes.size(), cache.TriangleOffsets, cache.TriangleList);
  GroupByNode(fc.TetrahedronNode, fc.Nodes.size(), cache.TetraOffsets, cache.TetraList);
  cache.GeometryThreshold = tmax;
  return true;
}

//------------------------------------------------------------------------------
void vtkFlowReconstruction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ReconstructionThreshold: " << this->ReconstructionThreshold << "\n";
  os << indent << "MaximumThreshold: " << this->MaximumThreshold << "\n";
  os << indent << "NumberOfQueueRuns: " << this->NumberOfQueueRuns << "\n";
}
