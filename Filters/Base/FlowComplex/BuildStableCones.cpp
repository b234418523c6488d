// Build phase 6: the stable manifolds of the index-3 critical points, each a cone
// from the maximum over the patches that bound it (geometry builds only).
#include "BuildPhases.h"

#include "CompressedRows.h"
#include "StableManifoldCone.h"

namespace flowrecon
{
namespace internal
{

void Builder::BuildStableCones()
{
  FlowComplex& fc = this->FC;
  // After scaling back: the cones' added points are then computed from the
  // same coordinates as DrawStableManifolds's.
  fc.Tetrahedra.clear();
  fc.TetrahedronNode.clear();
  if (this->Options.StableManifolds)
  {
    for (std::size_t i = 0; i < this->Cs.Cells.size(); ++i)
    {
      const Id node = this->Base3 + static_cast<Id>(i);
      fc.NodePoint[node] = static_cast<Id>(fc.Points.size());
      fc.Points.push_back(fc.Nodes[node].Location);
    }
    // The boundary patches of each maximum, in facet order (arcs are grouped by
    // lower node); fins (both flow lines here) too: see DrawStableManifolds.
    const auto boundary = CompressedRows<Id>::Group(this->Cs.Cells.size(), [&](const auto& emit) {
      for (const Arc& arc : fc.Arcs)
      {
        if (arc.Lower >= this->Base2 && arc.Lower < this->Base3 && arc.Upper != fc.InfinityNode)
        {
          emit(arc.Upper - this->Base3, arc.Lower - this->Base2);
        }
      }
    });
    ConeBoundary coneBoundary;
    for (std::size_t i = 0; i < this->Cs.Cells.size(); ++i)
    {
      const Id node = this->Base3 + static_cast<Id>(i);
      coneBoundary.Clear();
      for (const Id b : boundary.Row(static_cast<Id>(i)))
      {
        const std::size_t f = static_cast<std::size_t>(b);
        const bool fin = this->Ends[f][0] == this->Ends[f][1];
        coneBoundary.Add(fc.Triangles.data() + this->TriangleBegin[f],
          fc.Triangles.data() + this->TriangleBegin[f + 1], !fin && this->Ends[f][this->PatchFaces[f]] != node, fin);
      }
      fc.TetrahedronNode.insert(fc.TetrahedronNode.end(),
        static_cast<std::size_t>(AppendCone(fc.NodePoint[node], coneBoundary.Triangles, fc.Points,
          fc.Tetrahedra, &coneBoundary.TwoSided)),
        node);
    }
  }
}

} // namespace internal
} // namespace flowrecon
