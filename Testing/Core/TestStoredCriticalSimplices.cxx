// The critical simplices a later stage reads off a stored complex's nodes
// (StoredCriticalSimplices) against the classification of every Delaunay
// simplex (FindCriticalSimplices, kept by the builder): equal list for list on
// volume, surface, lattice (perturbed), cospherical and duplicated samples.
// And a stored complex that does not belong to its points is refused: nodes
// out of order, a node whose simplex is a Delaunay simplex but not critical
// (edge, facet and cell each, the lists sorted again so that only that test
// can see it), a node naming no Delaunay simplex, a node missing, and the triangulation of a lattice without the
// perturbation its complex was built with.
#include "Check.h"
#include "Clouds.h"
#include "ReconFixtures.h"

#include "CriticalSimplices.h"
#include "FlowComplexBuilder.h"
#include "InputPreparation.h"
#include "Progress.h"
#include "Retriangulation.h"
#include "StoredCriticalSimplices.h"

#include <algorithm>
#include <array>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace
{
using namespace flowrecon;

const char* const Refused = "refused";

using fixtures::Build;
using fixtures::Built;

bool Same(const CriticalSimplices& a, const CriticalSimplices& b)
{
  if (a.Edges.Offsets != b.Edges.Offsets || a.Edges.Values != b.Edges.Values ||
    a.Facets.size() != b.Facets.size() || a.Cells.size() != b.Cells.size())
  {
    return false;
  }
  for (std::size_t i = 0; i < a.Facets.size(); ++i)
  {
    if (a.Facets[i].Vertices != b.Facets[i].Vertices || a.Facets[i].Cell != b.Facets[i].Cell ||
      a.Facets[i].Opposite != b.Facets[i].Opposite)
    {
      return false;
    }
  }
  for (std::size_t i = 0; i < a.Cells.size(); ++i)
  {
    if (a.Cells[i].Vertices != b.Cells[i].Vertices || a.Cells[i].Cell != b.Cells[i].Cell)
    {
      return false;
    }
  }
  return true;
}

/// The nodes of index `index` (a block), with node `at` given the simplex `s`
/// (triangulation ids), then the block sorted again by triangulation ids, as
/// the builder orders it.
std::vector<Node> Replaced(const Built& b, int index, Id at, std::array<Id, 4> s)
{
  std::vector<Node> nodes = b.Complex.Nodes;
  const std::vector<Id>& inputId = b.Re->Prepared().InputId;
  Node& n = nodes[static_cast<std::size_t>(at)];
  n.Simplex = { { -1, -1, -1, -1 } };
  for (int k = 0; k <= index; ++k)
  {
    n.Simplex[k] = static_cast<std::int32_t>(inputId[static_cast<std::size_t>(s[k])]);
  }
  std::sort(n.Simplex.begin(), n.Simplex.begin() + index + 1);
  // The block's order by triangulation ids.
  std::vector<Id> vertexOf(static_cast<std::size_t>(*std::max_element(inputId.begin(), inputId.end())) + 1, -1);
  for (std::size_t k = 0; k < inputId.size(); ++k)
  {
    vertexOf[static_cast<std::size_t>(inputId[k])] = static_cast<Id>(k);
  }
  const auto key = [&](const Node& x) {
    std::array<Id, 4> t{ { -1, -1, -1, -1 } };
    for (int k = 0; k <= index; ++k)
    {
      t[k] = vertexOf[static_cast<std::size_t>(x.Simplex[k])];
    }
    std::sort(t.begin(), t.begin() + index + 1);
    return t;
  };
  auto first = std::find_if(nodes.begin(), nodes.end(), [&](const Node& x) { return x.Index == index; });
  auto last = std::find_if(first, nodes.end(), [&](const Node& x) { return x.Index != index || x.IsInfinity(); });
  std::sort(first, last, [&](const Node& x, const Node& y) { return key(x) < key(y); });
  return nodes;
}

void CheckCloud(const std::vector<Point3>& points, const std::string& name)
{
  const Built b = Build(points);
  const Triangulation& tri = b.Re->Tri();
  const std::vector<Id>& inputId = b.Re->Prepared().InputId;
  const CriticalSimplices& oracle = b.Re->Critical();
  CHECK(!oracle.Edges.Offsets.empty());
  const CriticalSimplices stored = StoredCriticalSimplices(tri, b.Complex.Nodes, inputId, Refused);
  std::cout << "-- " << name << ": " << oracle.Edges.ValueCount() << " edges, " << oracle.Facets.size()
            << " facets, " << oracle.Cells.size() << " cells, perturbed "
            << (b.Complex.Report.Attempts > 1 ? "yes" : "no") << "\n";
  CHECK(Same(stored, oracle));
  // Through the stored path: the samples' triangulation made again.
  const std::unique_ptr<Retriangulation> again = Retriangulation::OfStoredComplex(b.Complex, Progress(), "");
  CHECK(Same(again->Critical(), oracle));
  CHECK(again->Base2() == b.Re->Base2() && again->Base3() == b.Re->Base3());

  const Id base1 = tri.NumberOfVertices();
  const Id base2 = b.Re->Base2(), base3 = b.Re->Base3();
  // Two facets swapped: out of order.
  if (oracle.Facets.size() >= 2)
  {
    std::vector<Node> nodes = b.Complex.Nodes;
    std::swap(nodes[static_cast<std::size_t>(base2)], nodes[static_cast<std::size_t>(base2 + 1)]);
    CHECK_THROWS(StoredCriticalSimplices(tri, nodes, inputId, Refused), InputError);
  }
  // An edge dropped (the infinity node after it keeps its place): Morse's count.
  {
    std::vector<Node> nodes = b.Complex.Nodes;
    nodes.erase(nodes.begin() + base1);
    CHECK_THROWS(StoredCriticalSimplices(tri, nodes, inputId, Refused), InputError);
  }
  // A Delaunay simplex that is not critical in place of a critical one, of
  // each index: the first finite cell's edges, facets and the cell itself.
  std::set<std::array<Id, 2>> gabriel;
  for (const auto& e : oracle.Edges.Values)
  {
    gabriel.insert({ { e[0], e[1] } });
  }
  std::set<std::array<Id, 3>> critical;
  for (const CriticalFacet& f : oracle.Facets)
  {
    critical.insert({ { f.Vertices[0], f.Vertices[1], f.Vertices[2] } });
  }
  std::set<Id> selfCentred;
  for (const CriticalCell& c : oracle.Cells)
  {
    selfCentred.insert(c.Cell);
  }
  bool edgeDone = false, facetDone = false, cellDone = false;
  for (Id c = 0; c < tri.NumberOfCells() && !(edgeDone && facetDone && cellDone); ++c)
  {
    const std::array<Id, 4> v = tri.SortedVertices(tri.Cell(c));
    for (int i = 0; i < 4 && !edgeDone; ++i)
    {
      for (int j = i + 1; j < 4 && !edgeDone; ++j)
      {
        if (!gabriel.count({ { v[i], v[j] } }) && oracle.Edges.ValueCount() > 0)
        {
          CHECK_THROWS(StoredCriticalSimplices(tri, Replaced(b, 1, base1, { { v[i], v[j], -1, -1 } }),
                         inputId, Refused),
            InputError);
          edgeDone = true;
        }
      }
    }
    for (int skip = 0; skip < 4 && !facetDone; ++skip)
    {
      std::array<Id, 4> f{ { -1, -1, -1, -1 } };
      for (int k = 0, j = 0; k < 4; ++k)
      {
        if (k != skip)
        {
          f[j++] = v[k];
        }
      }
      if (!critical.count({ { f[0], f[1], f[2] } }) && !oracle.Facets.empty())
      {
        CHECK_THROWS(StoredCriticalSimplices(tri, Replaced(b, 2, base2, f), inputId, Refused), InputError);
        facetDone = true;
      }
    }
    if (!cellDone && !selfCentred.count(c) && !oracle.Cells.empty())
    {
      CHECK_THROWS(StoredCriticalSimplices(tri, Replaced(b, 3, base3, v), inputId, Refused), InputError);
      cellDone = true;
    }
  }
  CHECK(edgeDone && facetDone && cellDone);
  // No Delaunay simplex at all: vertex 0 with the vertices farthest from it.
  std::vector<Id> far(static_cast<std::size_t>(tri.NumberOfVertices()));
  for (Id k = 0; k < tri.NumberOfVertices(); ++k)
  {
    far[static_cast<std::size_t>(k)] = k;
  }
  const auto distance = [&](Id k) {
    double d = 0;
    for (int i = 0; i < 3; ++i)
    {
      d += (tri.Coord(k)[i] - tri.Coord(0)[i]) * (tri.Coord(k)[i] - tri.Coord(0)[i]);
    }
    return d;
  };
  std::sort(far.begin(), far.end(), [&](Id a, Id b) { return distance(a) > distance(b); });
  CHECK_THROWS(StoredCriticalSimplices(
                 tri, Replaced(b, 1, base1, { { 0, far[0], -1, -1 } }), inputId, Refused),
    InputError);
  if (!oracle.Facets.empty())
  {
    CHECK_THROWS(StoredCriticalSimplices(
                   tri, Replaced(b, 2, base2, { { 0, far[0], far[1], -1 } }), inputId, Refused),
      InputError);
  }
}

/// A lattice's complex is built on perturbed points; the triangulation of the
/// points as they are (a tie everywhere) is not the one its nodes name.
void CheckUnperturbed()
{
  const std::vector<Point3> points = clouds::Grid(5, 0, 3);
  const Built b = Build(points);
  CHECK(b.Complex.Report.Attempts > 1);
  const PreparedInput in = PrepareForTriangulation(points);
  const Triangulation plain(in.Unique);
  CHECK_THROWS(StoredCriticalSimplices(plain, b.Complex.Nodes, in.InputId, Refused), InputError);
}

} // namespace

int main()
{
  CheckCloud(clouds::Cube(2000, 1), "cube 2000");
  CheckCloud(clouds::Sphere(3000, 2), "sphere 3000");
  CheckCloud(clouds::Torus(3000, 3), "torus 3000");
  CheckCloud(clouds::Icosahedron(2000, 4), "icosahedron faces 2000");
  CheckCloud(clouds::Grid(6, 0, 5), "lattice 6^3 (perturbed)");
  CheckCloud(clouds::Cospherical(), "cospherical");
  CheckCloud(clouds::WithDuplicates(clouds::Sphere(1500, 6)), "sphere with duplicates");
  CheckUnperturbed();
  return check::Finish("TestStoredCriticalSimplices");
}
