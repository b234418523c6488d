// Each node's critical point through a .vtm file and back (ToMultiBlock,
// FromMultiBlock): the CriticalPoints array StableManifoldPointId gives back
// exactly the point the build made for the node (FlowComplex::NodePoint), with
// all the geometry, a cell budget or none; a file without the array (written
// before it) gives the samples' points alone; a value that is not a point of
// StableManifolds is refused in one line.
#include "Check.h"

#include "FlowComplexBuilder.h"
#include "FlowComplexFromVTK.h"
#include "FlowComplexToVTK.h"
#include "FlowReconNames.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLMultiBlockDataReader.h"
#include "vtkXMLMultiBlockDataWriter.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using flowrecon::FlowComplex;
using flowrecon::Id;

namespace
{

std::vector<flowrecon::Point3> RandomCloud(int n, unsigned seed)
{
  std::mt19937_64 g(seed);
  std::vector<flowrecon::Point3> pts(static_cast<std::size_t>(n));
  for (auto& p : pts)
  {
    for (double& x : p)
    {
      x = static_cast<double>(g() >> 11) * 0x1.0p-53;
    }
  }
  return pts;
}

vtkPolyData* CriticalPoints(vtkMultiBlockDataSet* mb)
{
  for (unsigned int b = 0; b < mb->GetNumberOfBlocks(); ++b)
  {
    const char* name = mb->HasMetaData(b) ? mb->GetMetaData(b)->Get(vtkCompositeDataSet::NAME()) : nullptr;
    if (name && std::string(name) == flowrecon::names::CriticalPoints)
    {
      return vtkPolyData::SafeDownCast(mb->GetBlock(b));
    }
  }
  return nullptr;
}

/// `fc` written to `file` and read back as a multiblock.
vtkSmartPointer<vtkMultiBlockDataSet> ThroughFile(const FlowComplex& fc, const std::string& file)
{
  vtkNew<vtkMultiBlockDataSet> mb;
  flowrecon::ToMultiBlock(fc, mb);
  vtkNew<vtkXMLMultiBlockDataWriter> writer;
  writer->SetInputData(mb);
  writer->SetFileName(file.c_str());
  CHECK(writer->Write() == 1);
  vtkNew<vtkXMLMultiBlockDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
}

/// Node points of a file without StableManifoldPointId: the sample of each
/// index-0 node, nothing else.
std::vector<Id> SamplePointsOnly(const FlowComplex& fc)
{
  std::vector<Id> expected(fc.Nodes.size(), -1);
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    expected[i] = fc.Nodes[i].Index == 0 ? fc.Nodes[i].Simplex[0] : -1;
  }
  return expected;
}

/// What the build's NodePoint means, read off the geometry: a sample node's
/// point is its sample; an index-3 node's is at its location, a vertex of its
/// cones (their apex); an index-2 node's is a vertex of its patch at its
/// location up to rounding: the walk computes it anew, so finding it again by
/// its coordinates (as reading back did) misses most of them.
void CheckMeaning(const FlowComplex& fc, bool allDrawn)
{
  std::vector<int> inCells(fc.Nodes.size(), 0);
  for (std::size_t t = 0; t < fc.Triangles.size(); ++t)
  {
    const Id node = fc.TriangleNode[t];
    const auto& v = fc.Triangles[t];
    inCells[node] |= std::find(v.begin(), v.end(), fc.NodePoint[node]) != v.end() ? 1 : 0;
  }
  for (std::size_t t = 0; t < fc.Tetrahedra.size(); ++t)
  {
    const Id node = fc.TetrahedronNode[t];
    const auto& v = fc.Tetrahedra[t];
    inCells[node] |= std::find(v.begin(), v.end(), fc.NodePoint[node]) != v.end() ? 1 : 0;
  }
  int drawn2 = 0, drawn3 = 0, undrawn = 0, notBitwise = 0;
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const flowrecon::Node& n = fc.Nodes[i];
    const Id p = fc.NodePoint[i];
    if (n.Index == 1 || n.IsInfinity())
    {
      CHECK(p == -1);
      continue;
    }
    if (p < 0)
    {
      CHECK(!allDrawn && n.Index >= 2);
      ++undrawn;
      continue;
    }
    const flowrecon::Point3& x = fc.Points[p];
    if (n.Index == 0)
    {
      CHECK(p == n.Simplex[0] && x == n.Location);
      continue;
    }
    CHECK(p >= fc.NumberOfInputPoints && inCells[i] == 1);
    CHECK(n.Index == 2 || x == n.Location);
    for (int k = 0; k < 3; ++k)
    {
      CHECK(std::abs(x[k] - n.Location[k]) <= 1e-12); // the cloud is in the unit cube
    }
    notBitwise += x != n.Location ? 1 : 0;
    drawn2 += n.Index == 2 ? 1 : 0;
    drawn3 += n.Index == 3 ? 1 : 0;
  }
  std::cout << (allDrawn ? "all drawn: " : "budget: ") << drawn2 << " index-2 and " << drawn3
            << " index-3 points, " << undrawn << " not drawn, " << notBitwise
            << " not bitwise at their node's location\n";
  CHECK(drawn2 > 0 && (drawn3 > 0 || !allDrawn) && (undrawn > 0) != allDrawn);
}

} // namespace

int main(int argc, char* argv[])
{
  const std::string dir = argc > 1 ? argv[1] : ".";
  const std::vector<flowrecon::Point3> cloud = RandomCloud(400, 7);

  flowrecon::BuildOptions all, budget, none;
  budget.MaximumGeometryCells = 3000; // some nodes drawn, the rest not
  none.StableManifolds = false;
  int k = 0;
  for (const flowrecon::BuildOptions* options : { &all, &budget, &none })
  {
    const FlowComplex fc = flowrecon::BuildFlowComplex(cloud, *options, flowrecon::Progress());
    const std::string file = dir + "/TestNodePointRoundTrip" + std::to_string(k++) + ".vtm";
    vtkSmartPointer<vtkMultiBlockDataSet> back = ThroughFile(fc, file);
    FlowComplex read;
    std::string error;
    CHECK(back && flowrecon::FromMultiBlock(back, read, error));
    CHECK(error.empty());
    if (options->StableManifolds)
    {
      CheckMeaning(fc, options == &all);
      CHECK(read.NodePoint == fc.NodePoint);
    }
    else
    {
      // No geometry drawn: the samples are still points of StableManifolds.
      CHECK(fc.NodePoint.empty());
      CHECK(read.NodePoint == SamplePointsOnly(fc));
    }
    CHECK(read.Points == fc.Points);

    // Only the Hasse diagram: the array is checked, NodePoint is not filled.
    FlowComplex diagram;
    CHECK(flowrecon::FromMultiBlock(back, diagram, error, /*diagramOnly=*/true) && diagram.NodePoint.empty());

    vtkPolyData* cp = back ? CriticalPoints(back) : nullptr;
    vtkDataArray* point = cp ? cp->GetPointData()->GetArray(flowrecon::names::StableManifoldPointId) : nullptr;
    CHECK(point != nullptr);
    if (!point)
    {
      continue;
    }
    // A value past the last point of StableManifolds: one line naming the array.
    const Id node = fc.CountByIndex()[0] + fc.CountByIndex()[1]; // the first index-2 node
    CHECK(fc.Nodes[node].Index == 2);
    const double kept = point->GetComponent(node, 0);
    point->SetComponent(node, 0, static_cast<double>(fc.Points.size()));
    CHECK(!flowrecon::FromMultiBlock(back, read, error));
    CHECK(error.find("StableManifoldPointId") != std::string::npos && error.find('\n') == std::string::npos);
    point->SetComponent(node, 0, kept);

    // Critical values that are no distance (NaN, negative, +inf off infinity,
    // a finite one at infinity): one line naming them, no complex read.
    vtkDataArray* value = cp->GetPointData()->GetArray(flowrecon::names::CriticalValue);
    CHECK(value != nullptr && fc.InfinityNode >= 0);
    for (const auto& [at, bad] : { std::make_pair(node, std::nan("")), std::make_pair(node, -0.5),
           std::make_pair(node, HUGE_VAL), std::make_pair(fc.InfinityNode, 5.0) })
    {
      const double was = value->GetComponent(at, 0);
      value->SetComponent(at, 0, bad);
      CHECK(!flowrecon::FromMultiBlock(back, read, error));
      CHECK(error.find("critical value") != std::string::npos && error.find('\n') == std::string::npos);
      value->SetComponent(at, 0, was);
    }
    CHECK(flowrecon::FromMultiBlock(back, read, error));

    // A file written before the array: the samples' points alone.
    cp->GetPointData()->RemoveArray(flowrecon::names::StableManifoldPointId);
    CHECK(flowrecon::FromMultiBlock(back, read, error));
    CHECK(read.NodePoint == SamplePointsOnly(fc));
  }
  return check::Finish("TestNodePointRoundTrip");
}
