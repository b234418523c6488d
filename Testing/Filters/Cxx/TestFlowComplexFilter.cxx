// vtkFlowComplex as a VTK user meets it: block and array names of
// docs/data-contract.md, agreement between blocks, point-set and table input,
// progress events, abort, a clear error on coplanar input, and a .vtm round trip.
#include "Check.h"

#include "vtkFlowComplex.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLMultiBlockDataReader.h"
#include "vtkXMLMultiBlockDataWriter.h"

#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace
{

vtkSmartPointer<vtkPolyData> RandomCloud(int n, unsigned seed)
{
  std::mt19937_64 g(seed);
  vtkNew<vtkPoints> pts;
  for (int i = 0; i < n; ++i)
  {
    pts->InsertNextPoint(
      (g() >> 11) * 0x1.0p-53, (g() >> 11) * 0x1.0p-53, (g() >> 11) * 0x1.0p-53);
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(pts);
  return pd;
}

vtkDataObject* Block(vtkMultiBlockDataSet* mb, const char* name)
{
  for (unsigned int b = 0; b < mb->GetNumberOfBlocks(); ++b)
  {
    if (mb->HasMetaData(b) && std::string(mb->GetMetaData(b)->Get(vtkCompositeDataSet::NAME())) == name)
    {
      return mb->GetBlock(b);
    }
  }
  return nullptr;
}

void CheckOutput(vtkMultiBlockDataSet* mb)
{
  auto* cp = vtkPolyData::SafeDownCast(Block(mb, "CriticalPoints"));
  auto* hd = vtkPolyData::SafeDownCast(Block(mb, "HasseDiagram"));
  auto* sm = vtkUnstructuredGrid::SafeDownCast(Block(mb, "StableManifolds"));
  auto* um = vtkPolyData::SafeDownCast(Block(mb, "UnstableManifolds"));
  CHECK(cp && hd && sm && um);
  if (!(cp && hd && sm && um))
  {
    return;
  }
  for (const char* a : { "NodeId", "Index", "CriticalValue" })
  {
    CHECK(cp->GetPointData()->GetArray(a) != nullptr);
    CHECK(sm->GetCellData()->GetArray(a) != nullptr);
  }
  CHECK(hd->GetCellData()->GetArray("Multiplicity") && hd->GetCellData()->GetArray("Ratio"));
  CHECK(sm->GetPointData()->GetArray("vtkOriginalPointIds") != nullptr);
  CHECK(um->GetCellData()->GetArray("NodeId") != nullptr);

  // Counts by index from the points agree with the report and Euler's relation.
  auto* index = vtkIntArray::SafeDownCast(cp->GetPointData()->GetArray("Index"));
  auto* value = vtkDoubleArray::SafeDownCast(cp->GetPointData()->GetArray("CriticalValue"));
  vtkIdType n[4] = { 0, 0, 0, 0 }, infinite = 0;
  for (vtkIdType i = 0; index && value && i < index->GetNumberOfTuples(); ++i)
  {
    if (std::isinf(value->GetValue(i)))
      ++infinite;
    else
      ++n[index->GetValue(i)];
  }
  CHECK(infinite == 1);
  CHECK(n[0] - n[1] + n[2] - n[3] == 1);
  CHECK(cp->GetNumberOfVerts() == cp->GetNumberOfPoints() - 1); // infinity is not drawn
  // Index on the vertex cells too (the default display colours by the cell array).
  auto* vertexIndex = vtkIntArray::SafeDownCast(cp->GetCellData()->GetArray("Index"));
  CHECK(vertexIndex && vertexIndex->GetNumberOfTuples() == cp->GetNumberOfVerts());
  // GabrielEdges: one line per index-1 node, with its NodeId and Index 1.
  auto* ge = vtkPolyData::SafeDownCast(Block(mb, "GabrielEdges"));
  CHECK(ge && ge->GetNumberOfLines() == n[1] && ge->GetNumberOfCells() == n[1]);
  auto* edgeIndex = ge ? vtkIntArray::SafeDownCast(ge->GetCellData()->GetArray("Index")) : nullptr;
  CHECK(edgeIndex && edgeIndex->GetNumberOfTuples() == n[1]);
  for (vtkIdType c = 0; edgeIndex && c < edgeIndex->GetNumberOfTuples(); ++c)
    CHECK(edgeIndex->GetValue(c) == 1);
  auto* counts = vtkIdTypeArray::SafeDownCast(mb->GetFieldData()->GetArray("NodeCountByIndex"));
  CHECK(counts && counts->GetNumberOfComponents() == 4);
  for (int k = 0; counts && k < 4; ++k)
    CHECK(counts->GetTypedComponent(0, k) == n[k]);
  // One stable-manifold cell per index-0/1 node, patches and cones after them.
  auto* cellIndex = vtkIntArray::SafeDownCast(sm->GetCellData()->GetArray("Index"));
  vtkIdType low = 0, patches = 0;
  for (vtkIdType c = 0; cellIndex && c < sm->GetNumberOfCells(); ++c)
  {
    low += cellIndex->GetValue(c) <= 1 ? 1 : 0;
    patches += cellIndex->GetValue(c) == 2 ? 1 : 0;
  }
  CHECK(low == n[0] + n[1]);
  CHECK(patches >= 3 * n[2]);
  // Every index-2 point has two unstable flow lines.
  CHECK(um->GetNumberOfCells() == 2 * n[2]);

  // Node and point ids in 32 bits (what ParaView holds for as long as the
  // filter is), and the same lines as before: line k of HasseDiagram runs from
  // its LowerNodeId to its UpperNodeId (point k is node k; an arc to infinity
  // ends on a stub whose NodeId is infinity's), vertex k of CriticalPoints is
  // point k.
  for (vtkCellArray* cells : { cp->GetVerts(), hd->GetLines(), sm->GetCells(), um->GetLines(),
         ge ? ge->GetLines() : nullptr })
  {
    CHECK(cells && !cells->IsStorage64Bit());
  }
  vtkDataArray* lower = hd->GetCellData()->GetArray("LowerNodeId");
  vtkDataArray* upper = hd->GetCellData()->GetArray("UpperNodeId");
  vtkDataArray* pointNode = hd->GetPointData()->GetArray("NodeId");
  CHECK(lower && upper && pointNode);
  for (vtkDataArray* a : { lower, upper, pointNode, cp->GetPointData()->GetArray("NodeId"),
         cp->GetPointData()->GetArray("Simplex"), sm->GetCellData()->GetArray("NodeId") })
  {
    CHECK(a && a->GetDataTypeSize() == 4);
  }
  const vtkIdType infinity = static_cast<vtkIdType>(
    mb->GetFieldData()->GetArray("InfinityNodeId")->GetTuple1(0));
  bool same = lower && upper && pointNode;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; same && c < hd->GetNumberOfCells(); ++c)
  {
    hd->GetCellPoints(c, ids);
    const vtkIdType up = static_cast<vtkIdType>(upper->GetTuple1(c));
    same = ids->GetNumberOfIds() == 2 && ids->GetId(0) == static_cast<vtkIdType>(lower->GetTuple1(c)) &&
      (ids->GetId(1) == up ||
        (up == infinity && static_cast<vtkIdType>(pointNode->GetTuple1(ids->GetId(1))) == infinity));
  }
  CHECK(same);
  same = true;
  for (vtkIdType c = 0; c < cp->GetNumberOfVerts(); ++c)
  {
    cp->GetCellPoints(c, ids);
    same = same && ids->GetNumberOfIds() == 1 && ids->GetId(0) == c;
  }
  CHECK(same);
}

} // namespace

int main(int argc, char* argv[])
{
  const std::string dir = argc > 1 ? argv[1] : ".";

  // Point-set input, progress events.
  vtkNew<vtkFlowComplex> fc;
  fc->SetInputData(RandomCloud(500, 1));
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progressEvents);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* cd, void*) { ++*static_cast<int*>(cd); });
  fc->AddObserver(vtkCommand::ProgressEvent, onProgress);
  fc->Update();
  CheckOutput(fc->GetOutput());
  CHECK(progressEvents >= 3);

  // The .vtm round trip keeps block names and arrays.
  const std::string file = dir + "/TestFlowComplexFilter.vtm";
  vtkNew<vtkXMLMultiBlockDataWriter> writer;
  writer->SetInputConnection(fc->GetOutputPort());
  writer->SetFileName(file.c_str());
  CHECK(writer->Write() == 1);
  vtkNew<vtkXMLMultiBlockDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  auto* back = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
  CHECK(back != nullptr);
  if (back)
  {
    auto* cp = vtkPolyData::SafeDownCast(Block(back, "CriticalPoints"));
    CHECK(cp && cp->GetFieldData()->GetArray("NodeCountByIndex"));
    auto* sm = vtkUnstructuredGrid::SafeDownCast(Block(back, "StableManifolds"));
    auto* orig = vtkUnstructuredGrid::SafeDownCast(Block(fc->GetOutput(), "StableManifolds"));
    CHECK(sm && orig && sm->GetNumberOfCells() == orig->GetNumberOfCells());
  }

  // Table input with named columns gives the same complex.
  vtkNew<vtkTable> table;
  const char* names[3] = { "x", "y", "z" };
  auto cloud = RandomCloud(500, 1);
  for (int k = 0; k < 3; ++k)
  {
    vtkNew<vtkDoubleArray> col;
    col->SetName(names[k]);
    for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
      col->InsertNextValue(cloud->GetPoint(i)[k]);
    table->AddColumn(col);
  }
  vtkNew<vtkFlowComplex> fromTable;
  fromTable->SetInputData(table);
  fromTable->Update();
  auto* a = vtkIdTypeArray::SafeDownCast(fc->GetOutput()->GetFieldData()->GetArray("NodeCountByIndex"));
  auto* b = vtkIdTypeArray::SafeDownCast(fromTable->GetOutput()->GetFieldData()->GetArray("NodeCountByIndex"));
  CHECK(a && b);
  for (int k = 0; a && b && k < 4; ++k)
    CHECK(a->GetTypedComponent(0, k) == b->GetTypedComponent(0, k));

  // Coplanar input: a VTK error that says so, and no output blocks.
  vtkNew<vtkPoints> flat;
  for (int i = 0; i < 10; ++i)
    flat->InsertNextPoint(i % 3, i / 3, 0);
  vtkNew<vtkPolyData> flatPd;
  flatPd->SetPoints(flat);
  std::string message;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&message);
  onError->SetCallback([](vtkObject*, unsigned long, void* cd, void* data) {
    *static_cast<std::string*>(cd) = static_cast<const char*>(data);
  });
  vtkNew<vtkFlowComplex> bad;
  bad->AddObserver(vtkCommand::ErrorEvent, onError);
  bad->SetInputData(flatPd);
  bad->Update();
  CHECK(message.find("coplanar") != std::string::npos);
  CHECK(bad->GetOutput()->GetNumberOfBlocks() == 0);

  // Abort from a progress observer stops the run with an empty output.
  vtkNew<vtkFlowComplex> aborted;
  aborted->SetInputData(RandomCloud(20000, 2));
  vtkNew<vtkCallbackCommand> onAbort;
  onAbort->SetCallback([](vtkObject* caller, unsigned long, void*, void*) {
    static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
  });
  aborted->AddObserver(vtkCommand::ProgressEvent, onAbort);
  aborted->Update();
  CHECK(aborted->GetOutput()->GetNumberOfBlocks() == 0);

  // Progress from the first second: the Delaunay phase of a large cloud reports
  // as it goes, the copy into VTK data too, and 1 comes only at the end.
  struct Seen
  {
    std::vector<std::pair<double, std::string>> Reports;
    bool AbortInDelaunay = false;
  };
  auto record = [](vtkObject* caller, unsigned long, void* cd, void* data) {
    auto* seen = static_cast<Seen*>(cd);
    auto* algorithm = static_cast<vtkAlgorithm*>(caller);
    const char* text = algorithm->GetProgressText();
    const double f = *static_cast<double*>(data);
    seen->Reports.emplace_back(f, text ? text : "");
    if (seen->AbortInDelaunay && f > 0 && seen->Reports.back().second == "Delaunay triangulation")
    {
      algorithm->SetAbortExecute(1);
    }
  };
  // The filter on 70 000 points, its progress reports recorded; its blocks.
  auto run = [&record](Seen& seen) {
    vtkNew<vtkFlowComplex> large;
    large->SetInputData(RandomCloud(70000, 3));
    vtkNew<vtkCallbackCommand> observer;
    observer->SetClientData(&seen);
    observer->SetCallback(record);
    large->AddObserver(vtkCommand::ProgressEvent, observer);
    large->Update();
    return large->GetOutput()->GetNumberOfBlocks();
  };
  {
    Seen seen;
    const unsigned int blocks = run(seen);
    int delaunay = 0, vtkOutput = 0;
    bool monotone = true;
    for (std::size_t i = 0; i < seen.Reports.size(); ++i)
    {
      const auto& r = seen.Reports[i];
      delaunay += (r.second == "Delaunay triangulation" && r.first > 0 && r.first < 0.2) ? 1 : 0;
      vtkOutput += (r.second.rfind("VTK output", 0) == 0 && r.first > 0.8 && r.first < 1) ? 1 : 0;
      monotone = monotone && (i == 0 || r.first >= seen.Reports[i - 1].first);
      CHECK(r.first < 1 || i + 2 >= seen.Reports.size()); // 1 at the end only
    }
    std::cout << "progress: " << seen.Reports.size() << " reports, " << delaunay
              << " inside the Delaunay phase, " << vtkOutput << " in the VTK output\n";
    CHECK(delaunay >= 4);
    CHECK(vtkOutput >= 2);
    CHECK(monotone);
    CHECK(blocks == vtkFlowComplex::NUMBER_OF_BLOCKS && blocks == 5);
  }
  {
    // Abort inside the Delaunay phase: nothing after it runs.
    Seen seen;
    seen.AbortInDelaunay = true;
    const unsigned int blocks = run(seen);
    bool later = false;
    for (const auto& r : seen.Reports)
      later = later || r.second == "critical points";
    CHECK(!later);
    CHECK(blocks == 0);
  }

  return check::Finish("TestFlowComplexFilter");
}
