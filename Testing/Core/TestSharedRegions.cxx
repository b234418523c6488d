// The Betti numbers of a build's t_p candidates, run one after the other as
// `flowrecon reconstruct` runs them (Filters/CloudReconstruction.cxx), sharing
// the regions of the complement and the ends of the lines walked there
// (SharedRegions, TopologyInput.h). Each candidate's profile must be the eager
// diagram's, where every flow line is followed to its maximum (the oracle).
// No candidate may fall back to following every line: the levels' premises
// hold by construction (docs/algorithm.md §12), so a fallback is a level
// given to nodes it does not serve. And the later candidate must end lines at
// the earlier one's r*, or the sharing is not tested.
#include "CappedReconstruction.h"
#include "Check.h"
#include "CellHomology.h"
#include "Clouds.h"
#include "ReconFixtures.h"
#include "HasseTopology.h"
#include "Reconstruction.h"
#include "Simplification.h"
#include "TopologyInput.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace flowrecon;

namespace
{

using fixtures::DiagramOnly;
constexpr double Cap = fixtures::CommandLineCap;

/// Every reconstruction below the cap from the whole diagram (every line
/// followed by the build), simplified at t_p.
std::vector<TopologyStep> Eager(const std::vector<Point3>& cloud, double tp)
{
  const FlowComplex fc = BuildFlowComplex(cloud, DiagramOnly(), Progress());
  const SimplificationResult s = Simplify(fc.Nodes, fc.Arcs, tp, Progress());
  const std::vector<Arc>& arcs = tp >= 1 ? s.Arcs : fc.Arcs;
  const std::vector<bool> survives =
    tp >= 1 ? s.Survives : std::vector<bool>(fc.Nodes.size(), true);
  const std::vector<Id> init =
    InitializationEdges(fc.Nodes, NearestNeighboursFromDiagram(fc.Nodes, arcs));
  const ReconstructionResult run = Reconstruct(fc.Nodes, arcs, survives, init, HUGE_VAL, Progress());
  const std::vector<Id> carriers = CellCarriers(run, tp >= 1 ? &s : nullptr);
  return TopologyProfile(
    HasseBarcode(fc.Nodes, fc.Arcs, PresenceTimes(fc.Nodes, fc.Arcs, carriers, run)), 1, Cap);
}

bool Same(const std::vector<TopologyStep>& a, const std::vector<TopologyStep>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (std::size_t k = 0; k < a.size(); ++k)
  {
    if (a[k].Threshold != b[k].Threshold || a[k].Betti != b[k].Betti)
    {
      return false;
    }
  }
  return true;
}

/// The candidates t_p 1.1 then 0 of one build; returns the lines the second
/// ended at the first one's r*.
Id Candidates(const std::string& name, const std::vector<Point3>& cloud)
{
  CappedBuild build = BuildBelow(cloud, DiagramOnly(), 1.1, Cap, true, Progress(), true);
  SharedRegions shared;
  Id sharedLines = 0;
  for (const double tp : { 1.1, 0.0 })
  {
    CappedReconstruction r = ReconstructBuilt(build, tp, false, Progress());
    const TopologyInput t = TopologyOfCappedRun(r, &shared);
    const std::vector<TopologyStep> lazy =
      TopologyProfile(HasseBarcode(r.Complex.Nodes, t.Arcs, t.Presence, t.Joined), 1, Cap);
    ReturnNodes(r, build);
    const std::vector<TopologyStep> eager = Eager(cloud, tp);
    std::cout << name << ", t_p " << tp << ": " << lazy.size() << " profile rows, "
              << t.LinesToRegions << " lines ended in regions (" << t.LinesToLowerLevels
              << " below r*, " << t.LinesToSharedLevel << " at the other candidate's r*)"
              << (t.FollowedEveryLine ? ", every line followed" : "") << "\n";
    CHECK(eager.size() > 3);
    CHECK(Same(lazy, eager));
    CHECK(!t.FollowedEveryLine);
    sharedLines += t.LinesToSharedLevel;
  }
  return sharedLines;
}

/// Points on the unit sphere moved along the normal by Gaussian noise.
std::vector<Point3> Noisy(std::vector<Point3> points, double sigma, std::uint64_t seed)
{
  clouds::Rng rng(seed);
  for (Point3& p : points)
  {
    const double scale = 1 + sigma * rng.N();
    for (double& x : p)
    {
      x *= scale;
    }
  }
  return points;
}

} // namespace

int main()
{
  Id shared = 0;
  shared += Candidates("sphere", clouds::Sphere(1500, 3));
  // Noise of about half the spacing (sqrt(4 pi / 1500) ~ 0.09).
  shared += Candidates("noisy sphere", Noisy(clouds::Sphere(1500, 4), 0.05, 5));
  shared += Candidates("torus", clouds::Torus(2000, 6));
  shared += Candidates("icosahedron", clouds::Icosahedron(1500, 7));
  shared += Candidates("cube", clouds::Cube(1000, 8));
  std::cout << shared << " lines ended at the other candidate's r*\n";
  CHECK(shared > 0);
  return check::Finish("TestSharedRegions");
}
