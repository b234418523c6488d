// The configurations of docs/algorithm.md §8.3 with their published
// answers (counts, critical values, incidences, stable-manifold areas and the
// exact exit point of configuration D), and the degenerate inputs of §8.3 F
// checked at persistence level after the builder's perturbation.
#include "Check.h"

#include "FlowComplexBuilder.h"
#include "FlowComplexQueries.h"
#include "Persistence.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

using namespace flowrecon;

namespace
{

using queries::Build;
using queries::CheckCounts;

std::vector<double> Values(const FlowComplex& fc, int index)
{
  std::vector<double> v;
  for (const Node& n : fc.Nodes)
  {
    if (n.Index == index && !n.IsInfinity())
    {
      v.push_back(n.Value);
    }
  }
  std::sort(v.begin(), v.end());
  return v;
}

void CheckValues(const FlowComplex& fc, int index, std::vector<double> expected, double tol)
{
  const std::vector<double> got = Values(fc, index);
  CHECK(got.size() == expected.size());
  std::sort(expected.begin(), expected.end());
  for (std::size_t i = 0; i < std::min(got.size(), expected.size()); ++i)
  {
    CHECK_NEAR(got[i], expected[i], tol);
  }
}

using queries::Multiplicity;
using queries::NodeOf;

double Area(const FlowComplex& fc, Id node)
{
  double area = 0;
  for (std::size_t t = 0; t < fc.Triangles.size(); ++t)
  {
    if (fc.TriangleNode[t] != node)
    {
      continue;
    }
    const Point3& a = fc.Points[fc.Triangles[t][0]];
    const Point3& b = fc.Points[fc.Triangles[t][1]];
    const Point3& c = fc.Points[fc.Triangles[t][2]];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2],
                 z = u[0] * v[1] - u[1] * v[0];
    area += 0.5 * std::sqrt(x * x + y * y + z * z);
  }
  return area;
}

/// Finite-length pairs (death - birth > 1e-4) and essential classes, per dimension.
std::map<int, std::vector<std::array<double, 2>>> Diagram(const FlowComplex& fc)
{
  std::map<int, std::vector<std::array<double, 2>>> d;
  for (const PersistencePair& p : ComputePersistence(fc.Nodes, fc.Arcs))
  {
    if (p.DeathValue - p.BirthValue > 1e-4)
    {
      d[p.Dimension].push_back({ { p.BirthValue, p.DeathValue } });
    }
  }
  return d;
}

/// Compares diagrams as multisets: each expected pair is matched to an unused
/// computed pair within 1e-5 (births may tie, so no sort order is assumed).
void CheckDiagram(const FlowComplex& fc, int dim, std::vector<std::array<double, 2>> expected)
{
  auto d = Diagram(fc)[dim];
  CHECK(d.size() == expected.size());
  std::vector<bool> used(d.size(), false);
  for (const auto& e : expected)
  {
    bool matched = false;
    for (std::size_t i = 0; i < d.size() && !matched; ++i)
    {
      const bool death = std::isinf(e[1]) ? std::isinf(d[i][1]) : std::fabs(d[i][1] - e[1]) < 1e-5;
      if (!used[i] && std::fabs(d[i][0] - e[0]) < 1e-5 && death)
      {
        used[i] = matched = true;
      }
    }
    if (!matched)
    {
      std::cout << "dimension " << dim << ": no computed pair matches (" << e[0] << ", " << e[1]
                << ")\n";
    }
    CHECK(matched);
  }
}

void ConfigurationA()
{
  const FlowComplex fc = Build({ { { 1, 1, 1 } }, { { 1, -1, -1 } }, { { -1, 1, -1 } },
    { { -1, -1, 1 } } });
  CheckCounts(fc, { { 4, 6, 4, 1 } });
  CheckValues(fc, 1, std::vector<double>(6, std::sqrt(2.0)), 1e-12);
  CheckValues(fc, 2, std::vector<double>(4, std::sqrt(8.0 / 3)), 1e-12);
  CheckValues(fc, 3, { std::sqrt(3.0) }, 1e-12);
  const Id max = NodeOf(fc, { 0, 1, 2, 3 });
  for (const std::vector<Id>& face :
    std::vector<std::vector<Id>>{ { 0, 1, 2 }, { 0, 1, 3 }, { 0, 2, 3 }, { 1, 2, 3 } })
  {
    const Id f = NodeOf(fc, face);
    CHECK(f >= 0);
    CHECK_NEAR(Area(fc, f), 2 * std::sqrt(3.0), 1e-12);
    CHECK(Multiplicity(fc, f, max) == 1);
    CHECK(Multiplicity(fc, f, fc.InfinityNode) == 1);
    CHECK(Multiplicity(fc, NodeOf(fc, { face[0], face[1] }), f) == 1);
    CHECK(Multiplicity(fc, NodeOf(fc, { face[1], face[2] }), f) == 1);
    CHECK(Multiplicity(fc, NodeOf(fc, { face[0], face[2] }), f) == 1);
  }
  const double s2 = std::sqrt(2.0), s83 = std::sqrt(8.0 / 3);
  CheckDiagram(fc, 0, { { { 0, s2 } }, { { 0, s2 } }, { { 0, s2 } }, { { 0, HUGE_VAL } } });
  CheckDiagram(fc, 1, { { { s2, s83 } }, { { s2, s83 } }, { { s2, s83 } } });
  CheckDiagram(fc, 2, { { { s83, std::sqrt(3.0) } } });
}

void ConfigurationB()
{
  const FlowComplex fc = Build({ { { -0.1, -0.1, -0.1 } }, { { 1, 0, 0 } }, { { 0, 1, 0 } },
    { { 0, 0, 1 } } });
  CheckCounts(fc, { { 4, 6, 3, 0 } });
  const double a = std::sqrt(1.23) / 2, b = std::sqrt(0.5);
  CheckValues(fc, 1, { a, a, a, b, b, b }, 1e-12);
  CheckValues(fc, 2, { 0.719803, 0.719803, 0.719803 }, 1e-6);
  CHECK(NodeOf(fc, { 1, 2, 3 }) < 0); // acute, but the apex is inside its diametral ball
  for (const Arc& arc : fc.Arcs)
  {
    if (fc.Nodes[arc.Lower].Index == 2)
    {
      CHECK(arc.Upper == fc.InfinityNode && arc.Multiplicity == 2);
    }
  }
  CheckDiagram(fc, 0, { { { 0, a } }, { { 0, a } }, { { 0, a } }, { { 0, HUGE_VAL } } });
  CheckDiagram(fc, 1, { { { b, 0.719803 } }, { { b, 0.719803 } }, { { b, 0.719803 } } });
}

void ConfigurationC()
{
  const FlowComplex fc = Build({ { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 0.4, 0.8, 0 } },
    { { 0.5, 0.25, 3 } } });
  CheckCounts(fc, { { 4, 6, 4, 1 } });
  CheckValues(fc, 1, { 0.447214, 0.5, 0.5, 1.525819, 1.525819, 1.525819 }, 1e-6);
  CheckValues(fc, 2, { std::sqrt(0.3125), 1.542473, 1.546722, 1.546722 }, 1e-6);
  CheckValues(fc, 3, { 1.552083 }, 1e-6);
  CheckDiagram(fc, 0, { { { 0, 0.447214 } }, { { 0, 0.5 } }, { { 0, 1.525819 } }, { { 0, HUGE_VAL } } });
  CheckDiagram(fc, 1, { { { 0.5, 0.559017 } }, { { 1.525819, 1.542473 } }, { { 1.525819, 1.546722 } } });
  CheckDiagram(fc, 2, { { { 1.546722, 1.552083 } } });
}

void ConfigurationD()
{
  const FlowComplex fc = Build({ { { -0.9, -0.8, -0.2 } }, { { -0.8, 0.8, -0.9 } },
    { { 0.1, -0.3, 0.7 } }, { { -0.7, -0.3, -0.3 } }, { { -0.5, -1.0, -0.1 } } });
  CheckCounts(fc, { { 5, 5, 1, 0 } });
  CheckValues(fc, 1, { 0.273861, 0.229129, 0.628490, 0.640312, 0.610328 }, 1e-6);
  CHECK(NodeOf(fc, { 3, 4 }) < 0); // P0 is inside its diametral ball
  const Id c = NodeOf(fc, { 2, 3, 4 });
  CHECK(c >= 0);
  if (c < 0)
  {
    return;
  }
  CHECK_NEAR(fc.Nodes[c].Value, 0.657613, 1e-6);
  CHECK_NEAR(fc.Nodes[c].Location[0], -0.294784, 1e-6);
  CHECK_NEAR(fc.Nodes[c].Location[1], -0.449702, 1e-6);
  CHECK_NEAR(fc.Nodes[c].Location[2], 0.195827, 1e-6);
  CHECK_NEAR(Area(fc, c), 0.567435, 1e-6);
  // The walk toward m_34 exits at y = (-239/425, -1063/1700, -257/1700).
  const Point3 y{ { -239.0 / 425, -1063.0 / 1700, -257.0 / 1700 } };
  int found = 0, triangles = 0;
  for (std::size_t t = 0; t < fc.Triangles.size(); ++t)
  {
    triangles += fc.TriangleNode[t] == c ? 1 : 0;
    for (const Id v : fc.Triangles[t])
    {
      const Point3& p = fc.Points[v];
      if (fc.TriangleNode[t] == c && std::fabs(p[0] - y[0]) < 1e-15 &&
        std::fabs(p[1] - y[1]) < 1e-15 && std::fabs(p[2] - y[2]) < 1e-15)
      {
        ++found;
      }
    }
  }
  CHECK(triangles == 6);
  CHECK(found == 4); // y is a vertex of (c,y,P3), (c,y,P4), (P0,y,P3), (P0,y,P4)
  for (const std::vector<Id>& e : std::vector<std::vector<Id>>{ { 0, 3 }, { 0, 4 }, { 2, 3 }, { 2, 4 } })
  {
    CHECK(Multiplicity(fc, NodeOf(fc, e), c) == 1);
  }
  CHECK(Multiplicity(fc, NodeOf(fc, { 1, 3 }), c) == 0);
  CheckDiagram(fc, 1, { { { 0.640312, 0.657613 } } });
}

void DegenerateF()
{
  std::vector<Point3> cube;
  for (int i = 0; i < 8; ++i)
  {
    cube.push_back({ { double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1) } });
  }
  const FlowComplex fc = Build(cube);
  CHECK(fc.Report.Perturbed());
  const double h = 0.5, f = std::sqrt(0.5), m = std::sqrt(0.75);
  CheckDiagram(fc, 0, { { { 0, h } }, { { 0, h } }, { { 0, h } }, { { 0, h } }, { { 0, h } },
                        { { 0, h } }, { { 0, h } }, { { 0, HUGE_VAL } } });
  CheckDiagram(fc, 1, std::vector<std::array<double, 2>>(5, { { h, f } }));
  CheckDiagram(fc, 2, { { { f, m } } });

  const FlowComplex oct = Build({ { { 1, 0, 0 } }, { { -1, 0, 0 } }, { { 0, 1, 0 } },
    { { 0, -1, 0 } }, { { 0, 0, 1 } }, { { 0, 0, -1 } } });
  CHECK(oct.Report.Perturbed());
  const double e = std::sqrt(0.5), t = std::sqrt(2.0 / 3);
  CheckDiagram(oct, 0, { { { 0, e } }, { { 0, e } }, { { 0, e } }, { { 0, e } }, { { 0, e } },
                         { { 0, HUGE_VAL } } });
  CheckDiagram(oct, 1, std::vector<std::array<double, 2>>(7, { { e, t } }));
  CheckDiagram(oct, 2, { { { t, 1.0 } } });

  // Regular polygons of radius 1 in z = 0: coplanar, so refused with a clear
  // error; jittered out of the plane by 1e-7 they have one H1 class
  // (sin(pi/n), 1) and n - 1 finite H0 classes dying at sin(pi/n).
  std::vector<Point3> hexagon;
  for (int i = 0; i < 6; ++i)
  {
    hexagon.push_back({ { std::cos(i * M_PI / 3), std::sin(i * M_PI / 3), 0 } });
  }
  for (int n : { 5, 6 })
  {
    std::vector<Point3> polygon;
    for (int i = 0; i < n; ++i)
    {
      polygon.push_back({ { std::cos(2 * i * M_PI / n), std::sin(2 * i * M_PI / n),
        (i % 2 ? 1e-7 : -1e-7) * (1 + 0.1 * i) } });
    }
    const FlowComplex pc = Build(polygon);
    const double r = std::sin(M_PI / n);
    std::vector<std::array<double, 2>> h0(n - 1, { { 0, r } });
    h0.push_back({ { 0, HUGE_VAL } });
    CheckDiagram(pc, 0, h0);
    CheckDiagram(pc, 1, { { { r, 1.0 } } });
    CheckDiagram(pc, 2, {});
  }
  bool refused = false;
  try
  {
    Build(hexagon);
  }
  catch (const InputError& err)
  {
    refused = std::string(err.what()).find("coplanar") != std::string::npos;
  }
  CHECK(refused);
}

} // namespace

int main()
{
  ConfigurationA();
  ConfigurationB();
  ConfigurationC();
  ConfigurationD();
  DegenerateF();
  return check::Finish("TestKnownConfigurations");
}
