// Flow Reconstruction's Compute Topology and Maximum Topology Cells act at the
// next update although the drawing is cached: turned on after a run without
// them, or the cell limit changed, the Betti numbers (port 0's field data) and
// the topology profile (port 3) are a fresh filter's, and the queue does not
// run again. The fresh filter reads them off the Hasse diagram with its queue;
// turned on later, they come from the drawn cells (and their cell limit): the
// two ways agree.
#include "Check.h"

#include "vtkFlowComplex.h"
#include "vtkFlowReconstruction.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVariant.h"

#include <cmath>
#include <random>
#include <vector>

namespace
{

/// b0, b1, b2 of BettiNumbers, then the topology profile row by row; empty
/// when the Betti numbers were skipped.
std::vector<double> Topology(vtkFlowReconstruction* r)
{
  std::vector<double> t;
  if (vtkDataArray* betti = r->GetOutput()->GetFieldData()->GetArray("BettiNumbers"))
  {
    const int m = betti->GetNumberOfComponents();
    for (vtkIdType k = 0; k < m * betti->GetNumberOfTuples(); ++k)
    {
      t.push_back(betti->GetComponent(k / m, static_cast<int>(k % m)));
    }
  }
  auto* table = vtkTable::SafeDownCast(r->GetOutputDataObject(vtkFlowReconstruction::TOPOLOGY_PROFILE));
  for (vtkIdType row = 0; table && row < table->GetNumberOfRows(); ++row)
  {
    for (vtkIdType col = 0; col < table->GetNumberOfColumns(); ++col)
    {
      t.push_back(table->GetValue(row, col).ToDouble());
    }
  }
  return t;
}

} // namespace

int main()
{
  // 400 points on the unit sphere (Gaussian directions).
  std::mt19937_64 g(3);
  std::normal_distribution<double> n;
  vtkNew<vtkPoints> pts;
  for (int i = 0; i < 400; ++i)
  {
    const double x = n(g), y = n(g), z = n(g), r = std::sqrt(x * x + y * y + z * z);
    pts->InsertNextPoint(x / r, y / r, z / r);
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(pts);
  vtkNew<vtkFlowComplex> fc;
  fc->SetInputData(cloud);

  vtkNew<vtkFlowReconstruction> fresh;
  fresh->SetInputConnection(fc->GetOutputPort());
  fresh->AutomaticReconstructionThresholdOff(); // needs the topology
  fresh->Update();
  const std::vector<double> expected = Topology(fresh);
  CHECK(expected.size() > 3); // the Betti numbers and a profile

  vtkNew<vtkFlowReconstruction> r;
  r->SetInputConnection(fc->GetOutputPort());
  r->AutomaticReconstructionThresholdOff();
  r->SetComputeTopology(false);
  r->Update();
  CHECK(Topology(r).empty());
  r->SetComputeTopology(true);
  r->Update();
  CHECK(Topology(r) == expected);
  r->SetMaximumTopologyCells(0); // more cells than that: skipped, with a warning
  r->Update();
  CHECK(Topology(r).empty());
  r->SetMaximumTopologyCells(-1);
  r->Update();
  CHECK(Topology(r) == expected);
  CHECK(r->GetNumberOfQueueRuns() == 1);
  return check::Finish("TestTopologyAskedLater");
}
