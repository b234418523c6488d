// A t_p candidate's run held packed while the build serves the next one
// (HeldRun, as `flowrecon reconstruct` holds it for the compact output) must
// come back as the run a build of its own makes at that t_p: every insertion,
// the order and the carriers, on the same nodes. The oracle is that separate
// build and run (ReconstructBelow), not the packing. Pack itself must keep
// thresholds that are not the running maximum, and refuse carriers that do not
// match the run.
#include "CappedReconstruction.h"
#include "Check.h"
#include "Clouds.h"
#include "ReconFixtures.h"
#include "PackedRun.h"
#include "Reconstruction.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace flowrecon;

namespace
{

using fixtures::DiagramOnly;
constexpr double Cap = fixtures::CommandLineCap;

bool SameInsertions(const ReconstructionResult& a, const ReconstructionResult& b)
{
  if (a.Nodes.size() != b.Nodes.size() || a.Order != b.Order ||
    a.InitializationCount != b.InitializationCount)
  {
    return false;
  }
  for (std::size_t i = 0; i < a.Nodes.size(); ++i)
  {
    const Insertion& x = a.Nodes[i];
    const Insertion& y = b.Nodes[i];
    if (x.Step != y.Step || x.Priority != y.Priority || x.Threshold != y.Threshold ||
      x.Kind != y.Kind || x.Sponsor != y.Sponsor)
    {
      return false;
    }
  }
  return true;
}

bool SameNodes(const std::vector<Node>& a, const std::vector<Node>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    if (a[i].Value != b[i].Value || a[i].Index != b[i].Index || a[i].Simplex != b[i].Simplex)
    {
      return false;
    }
  }
  return true;
}

/// t_p 1.1 held while t_p 0 runs, then restored; against t_p 1.1 built alone.
/// The run at `heldTp` kept while the one at `otherTp` runs (the command line's
/// order is 1.1 then 0); a low `cap` makes the build defer patches. Returns
/// how many it deferred.
Id HeldAgainstAlone(const std::string& name, const std::vector<Point3>& cloud, double cap = Cap,
  double heldTp = 1.1, double otherTp = 0)
{
  CappedBuild build = BuildBelow(cloud, DiagramOnly(), 1.1, cap, true, Progress(), true);
  CappedReconstruction first = ReconstructBuilt(build, heldTp, false, Progress());
  ReturnNodes(first, build);
  HeldRun held = Hold(std::move(first));
  CHECK(first.Run.Nodes.empty() && first.Carriers.empty());
  CappedReconstruction second = ReconstructBuilt(build, otherTp, false, Progress());
  ReturnNodes(second, build);
  second = CappedReconstruction();
  const CappedReconstruction restored = Restore(std::move(held), build);

  const CappedReconstruction alone = ReconstructBelow(cloud, DiagramOnly(), heldTp, cap, true, Progress());
  std::cout << name << ": " << restored.Run.Order.size() << " of " << restored.Run.Nodes.size()
            << " nodes inserted below the cap, " << restored.DeferredPatches << " patches deferred, "
            << restored.WalkedLate << " walked late\n";
  CHECK(restored.Run.Order.size() > 10);
  CHECK(SameInsertions(restored.Run, alone.Run));
  CHECK(restored.Carriers == alone.Carriers);
  CHECK(SameNodes(restored.Complex.Nodes, alone.Complex.Nodes));
  CHECK(restored.Complex.InfinityNode == alone.Complex.InfinityNode);
  CHECK(restored.Simplified == (heldTp >= 1) && restored.WalkedLate == alone.WalkedLate);
  CHECK(restored.Triangulation != nullptr && restored.Lines == nullptr);
  CHECK(build.Complex.Nodes.empty()); // taken: the build is spent
  return restored.DeferredPatches;
}

/// A run whose thresholds are not the running maximum of its priorities
/// (Reconstruct never makes one): Pack must keep them as they are.
void OtherThresholds()
{
  const std::vector<Point3> cloud = clouds::Sphere(300, 11);
  const CappedReconstruction r = ReconstructBelow(cloud, DiagramOnly(), 0, Cap, true, Progress());
  ReconstructionResult run = r.Run;
  CHECK(run.Order.size() > 3);
  run.Nodes[run.Order[1]].Threshold = 7.5;
  ReconstructionResult back;
  std::vector<Id> carriers;
  const PackedRun p = Pack(run, r.Carriers);
  CHECK(!p.Threshold.empty());
  Unpack(p, back, carriers);
  CHECK(SameInsertions(back, run));
  CHECK(carriers == r.Carriers);
  // As Reconstruct made it, the thresholds are not stored.
  CHECK(Pack(r.Run, r.Carriers).Threshold.empty());

  CHECK_THROWS(Pack(run, std::vector<Id>(r.Carriers.size() + 1, -1)), InputError);
  std::vector<Id> outside = r.Carriers;
  outside.back() = static_cast<Id>(outside.size());
  CHECK_THROWS(Pack(r.Run, outside), InputError);
  ReconstructionResult misordered = r.Run;
  std::swap(misordered.Order[0], misordered.Order[1]);
  CHECK_THROWS(Pack(misordered, r.Carriers), InputError);
}

} // namespace

int main()
{
  HeldAgainstAlone("sphere", clouds::Sphere(1500, 3));
  HeldAgainstAlone("torus", clouds::Torus(2000, 6));
  HeldAgainstAlone("icosahedron", clouds::Icosahedron(1500, 7));
  HeldAgainstAlone("cube", clouds::Cube(1000, 8));
  HeldAgainstAlone("sparse sphere", clouds::Sphere(60, 9));
  // Below a cap of 1.5 a chart-uniform torus's far patches are deferred by the
  // build the two runs share (none is walked late here: the queues below the
  // cap do not need them), with either candidate held.
  Id deferred = HeldAgainstAlone("torus 4000, cap 1.5", clouds::Torus(4000, 8), 1.5);
  deferred += HeldAgainstAlone("torus 4000, t_p 0 held, cap 1.5", clouds::Torus(4000, 8), 1.5, 0, 1.1);
  CHECK(deferred > 0);
  OtherThresholds();
  return check::Finish("TestHeldRun");
}
