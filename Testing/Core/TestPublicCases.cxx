// The public small cases of docs/algorithm.md §8.3 E: the point sets of
// UmbReTHY/flow-complex tests/test_cases/d3_*.dat, checked against the published
// counts, critical values and incidences.
//
// The .dat files hold one point per line, three coordinates, no header; input ids
// below are 0-based line numbers. All four sets are full-dimensional (every
// 4-subset has non-zero volume), so none of them is rejected as coplanar or
// collinear: the 4/4/1/0 and 4/3/0/0 counts of two 4-point cases come from edges
// that are not Gabriel and faces that are obtuse or not Gabriel, not from a
// lower-dimensional input. (8.3 E assumes this too: 4 - 4 + 1 - 0 = 4 - 3 + 0 - 0 = 1.)
//
// Beyond the published numbers, the tests check the full sets of critical
// simplices and their values. These come from a brute-force check of the
// definition (the circumcentre of the simplex within its affine hull is in the
// simplex's interior and no other point is inside or on its circumsphere), not
// from the source repository.
#include "Check.h"

#include "FlowComplexBuilder.h"
#include "FlowComplexQueries.h"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

using namespace flowrecon;

namespace
{

using queries::Build;
using queries::CheckCounts;

using queries::Multiplicity;
using queries::NodeOf;

/// Each listed simplex is a node of the right index with the given value, and
/// there is no other finite node of that index.
void CheckCritical(const FlowComplex& fc, int index,
  const std::vector<std::pair<std::vector<Id>, double>>& expected, double tol)
{
  Id count = 0;
  for (const Node& n : fc.Nodes)
  {
    count += (n.Index == index && !n.IsInfinity()) ? 1 : 0;
  }
  CHECK(count == static_cast<Id>(expected.size()));
  for (const auto& e : expected)
  {
    const Id id = NodeOf(fc, e.first);
    CHECK(id >= 0);
    if (id >= 0)
    {
      CHECK_NEAR(fc.Nodes[id].Value, e.second, tol);
    }
  }
}

/// The index-1 nodes with an arc into `upper` are exactly `edges`, each with
/// multiplicity 1.
void CheckEdgesOf(const FlowComplex& fc, Id upper, const std::vector<std::vector<Id>>& edges)
{
  int arcs = 0;
  for (const Arc& a : fc.Arcs)
  {
    arcs += (a.Upper == upper && fc.Nodes[a.Lower].Index == 1) ? 1 : 0;
  }
  CHECK(arcs == static_cast<int>(edges.size()));
  for (const std::vector<Id>& e : edges)
  {
    const Id edge = NodeOf(fc, e);
    CHECK(edge >= 0);
    CHECK(Multiplicity(fc, edge, upper) == 1);
  }
}

// UmbReTHY/flow-complex, tests/test_cases/d3_finite_max.dat (data only).
// Published: 4/6/4/1, maximum value 0.489060.
void FiniteMax()
{
  const FlowComplex fc = Build({
    { { 0.3285548080024819, 0.02065161338136678, 0.09166202609582064 } },
    { { -0.4363320380787664, -0.4325644880836499, -0.1113517494977934 } },
    { { -0.4888568511128955, -0.2170967415134392, 0.2550631698733784 } },
    { { -0.1533098473710099, 0.3213925224928116, -0.3558808917700135 } },
  });
  CHECK(!fc.Report.Perturbed());
  CheckCounts(fc, { { 4, 6, 4, 1 } });
  CheckCritical(fc, 3, { { { 0, 1, 2, 3 }, 0.489060 } }, 1e-6);
  CheckCritical(fc, 1,
    { { { 0, 1 }, 0.455980 }, { { 0, 2 }, 0.433413 }, { { 0, 3 }, 0.361571 },
      { { 1, 2 }, 0.214152 }, { { 1, 3 }, 0.420817 }, { { 2, 3 }, 0.440402 } },
    1e-6);
  CheckCritical(fc, 2,
    { { { 0, 1, 2 }, 0.460445 }, { { 0, 1, 3 }, 0.482735 }, { { 0, 2, 3 }, 0.479979 },
      { { 1, 2, 3 }, 0.446213 } },
    1e-6);
}

// UmbReTHY/flow-complex, tests/test_cases/d3_4_no_finite_max.dat (data only).
// Published: 4/4/1/0, the index-2 value 0.317327. A genuine tetrahedron (volume
// about 0.0062) whose circumcentre lies outside it.
void NoFiniteMax()
{
  const FlowComplex fc = Build({
    { { -0.165052540754017, -0.03805507397098007, 0.4083681548092217 } },
    { { 0.4435707698050614, 0.09392072921052641, -0.4743088069132611 } },
    { { 0.2918820081203077, -0.3390957194744569, -0.1817584663459644 } },
    { { 0.1854536330191918, -0.08079521086141023, 0.07488777169481642 } },
  });
  CHECK(!fc.Report.Perturbed());
  CheckCounts(fc, { { 4, 4, 1, 0 } });
  CheckCritical(fc, 2, { { { 1, 2, 3 }, 0.317327 } }, 1e-6);
  CheckCritical(fc, 1,
    { { { 0, 3 }, 0.242843 }, { { 1, 2 }, 0.272075 }, { { 1, 3 }, 0.315740 },
      { { 2, 3 }, 0.189680 } },
    1e-6);
  // No finite maximum: both unstable flow lines of the index-2 point go to infinity.
  const Id face = NodeOf(fc, { 1, 2, 3 });
  CHECK(Multiplicity(fc, face, fc.InfinityNode) == 2);
}

// UmbReTHY/flow-complex, tests/test_cases/d3_drop_two_at_once.dat (data only).
// Published: 4/3/0/0. A genuine tetrahedron (volume about 0.0012) with three
// Gabriel edges and no critical face.
void DropTwoAtOnce()
{
  const FlowComplex fc = Build({
    { { -0.3505463747778408, 0.3670779395541902, 0.4789233016585217 } },
    { { 0.2639233137144924, -0.2408723791510541, -0.3420784197208271 } },
    { { -0.312001483805479, 0.191060210290421, 0.1489489429154889 } },
    { { 0.3848785021201507, -0.3470217919415066, -0.3952583581165023 } },
  });
  CHECK(!fc.Report.Perturbed());
  CheckCounts(fc, { { 4, 3, 0, 0 } });
  CheckCritical(fc, 1, { { { 0, 2 }, 0.187983 }, { { 1, 2 }, 0.435707 }, { { 1, 3 }, 0.084744 } },
    1e-6);
}

// UmbReTHY/flow-complex, tests/test_cases/d3_sliver.dat (data only).
// Published: 6/9/4/0; the index-2 point of (2,3,5) has value 0.279256 and a
// two-level stable manifold reaching the edges (1,3), (1,5), (2,3), (2,5).
void Sliver()
{
  const FlowComplex fc = Build({
    { { 0.3756763999123838, -0.006753525702984542, 0.4934896500720546 } },
    { { 0.3593285170936291, 0.234380067544412, 0.225789471739707 } },
    { { 0.4773760330652594, 0.2589800788638927, -0.3218204745294717 } },
    { { 0.346015760997325, 0.486888461268403, 0.1343608145922057 } },
    { { 0.3183980428785067, 0.3159002543575132, 0.3355686015780722 } },
    { { 0.400311222207091, 0.03070458865790127, 0.05201742011310295 } },
  });
  CHECK(!fc.Report.Perturbed());
  CheckCounts(fc, { { 6, 9, 4, 0 } });
  CheckCritical(fc, 1,
    { { { 0, 1 }, 0.180330 }, { { 0, 4 }, 0.181883 }, { { 0, 5 }, 0.221871 },
      { { 1, 3 }, 0.134440 }, { { 1, 4 }, 0.071366 }, { { 1, 5 }, 0.135425 },
      { { 2, 3 }, 0.263296 }, { { 2, 5 }, 0.222376 }, { { 3, 4 }, 0.132744 } },
    1e-6);
  CheckCritical(fc, 2,
    { { { 0, 1, 4 }, 0.184768 }, { { 0, 1, 5 }, 0.221995 }, { { 1, 3, 4 }, 0.138663 },
      { { 2, 3, 5 }, 0.279256 } },
    1e-6);
  const Id c = NodeOf(fc, { 2, 3, 5 });
  CHECK(c >= 0);
  if (c < 0)
  {
    return;
  }
  // (3,5) is not Gabriel, so the walk toward its midpoint goes one level down
  // and reaches (1,3) and (1,5); (2,3) and (2,5) are reached directly.
  CHECK(NodeOf(fc, { 3, 5 }) < 0);
  CheckEdgesOf(fc, c, { { 1, 3 }, { 1, 5 }, { 2, 3 }, { 2, 5 } });
}

} // namespace

int main()
{
  FiniteMax();
  NoFiniteMax();
  DropTwoAtOnce();
  Sliver();
  return check::Finish("TestPublicCases");
}
