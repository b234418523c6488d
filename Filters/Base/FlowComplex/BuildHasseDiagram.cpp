// Build phase 5: the nodes (critical points and values) and the 2-3 arcs, made
// monotone and checked, then scaled back to the input's coordinates.
#include "BuildPhases.h"

#include "Arithmetic.h"
#include "DrawingBox.h"
#include "HugePages.h"
#include "MemoryGuard.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace flowrecon
{
namespace internal
{

void Builder::AssembleHasseDiagram()
{
  FlowComplex& fc = this->FC;
  // Everything below needs only the critical simplices: free the triangulation.
  this->Report(0.9, "Hasse diagram");
  if (!this->Keep)
  {
    this->Tri.reset();
    // The triangulation's blocks came from tbbmalloc and the heap; the nodes below
    // are one large mapping that cannot reuse them.
    ReleaseFreedMemory();
  }

  // Nodes are independent constructions: fill them in parallel.
  fc.Nodes.clear();
  ReserveHugePopulated(fc.Nodes, static_cast<std::size_t>(fc.InfinityNode + 1));
  fc.Nodes.resize(static_cast<std::size_t>(fc.InfinityNode + 1));
  tbb::parallel_for(tbb::blocked_range<Id>(0, fc.InfinityNode), [&](const tbb::blocked_range<Id>& r) {
    for (Id n = r.begin(); n != r.end(); ++n)
    {
      if (n < this->Base1)
      {
        fc.Nodes[n] = this->MakeNode(0, &n, this->Coords());
      }
      else if (n < this->Base2)
      {
        fc.Nodes[n] = this->MakeNode(1, this->Cs.Edges.Values[n - this->Base1].data(), this->Coords());
      }
      else if (n < this->Base3)
      {
        fc.Nodes[n] = this->MakeNode(2, Widen(this->Cs.Facets[n - this->Base2].Vertices).data(), this->Coords());
      }
      else
      {
        fc.Nodes[n] = this->MakeNode(3, Widen(this->Cs.Cells[n - this->Base3].Vertices).data(), this->Coords());
      }
    }
  });
  {
    Node& inf = fc.Nodes.back();
    inf.Index = 3;
    inf.Value = HUGE_VAL;
    inf.Location = this->In.Centre;
  }

  for (std::size_t i = 0; i < this->Ends.size(); ++i)
  {
    const Id node = this->Base2 + static_cast<Id>(i);
    // A pending flow line (SuccessorForest::Pending) has no arc yet.
    if (this->Ends[i][0] < 0 || this->Ends[i][1] < 0)
    {
      for (const std::int32_t end : this->Ends[i])
      {
        if (end >= 0)
        {
          fc.Arcs.emplace_back(node, end, 1);
        }
      }
    }
    else if (this->Ends[i][0] == this->Ends[i][1])
    {
      fc.Arcs.emplace_back(node, this->Ends[i][0], 2);
    }
    else
    {
      fc.Arcs.emplace_back(node, this->Ends[i][0], 1);
      fc.Arcs.emplace_back(node, this->Ends[i][1], 1);
    }
  }
  // Values increase strictly along arcs in exact arithmetic, but a perturbed
  // degeneracy can leave a gap below double precision. The arcs come grouped by
  // index: one pass makes the doubles non-decreasing along every arc (a change
  // of at most an ulp or two), which the filtration relies on.
  for (const Arc& a : fc.Arcs)
  {
    fc.Nodes[a.Upper].Value = std::max(fc.Nodes[a.Upper].Value, fc.Nodes[a.Lower].Value);
  }
  // The critical points are double constructions (exact combinatorics, rounded
  // geometry): a cloud whose spacing is some 1e-20 of its extent makes them
  // underflow or cancel (values 0 or NaN). Refuse rather than answer wrongly.
  for (Id n = this->Base1; n < fc.InfinityNode; ++n)
  {
    const Node& node = fc.Nodes[n];
    if (!(node.Value > 0 && std::isfinite(node.Value) && std::isfinite(node.Location[0]) &&
          std::isfinite(node.Location[1]) && std::isfinite(node.Location[2])))
    {
      throw InputError(TooClose);
    }
  }

  this->ScaleBack();
  if (!fc.DeferredPatches.empty())
  {
    // The promise of DeferredPatches on the final values (scaling back by a
    // power of two keeps every ratio; a value raised by the pass above would not).
    double largest = 0;
    for (Id n = this->Base1; n < this->Base2; ++n)
    {
      largest = std::max(largest, fc.Nodes[n].Value);
    }
    for (const Id n : fc.DeferredPatches)
    {
      if (!(fc.Nodes[n].Value / largest >= fc.DeferralRatio))
      {
        throw Degenerate("deferred patch below its ratio");
      }
    }
  }
  const DrawingBox box = BoxAround(fc.Points, fc.NumberOfInputPoints, RayStub);
  for (FlowLine& line : fc.FlowLines)
  {
    if (line.Target == fc.InfinityNode)
    {
      ClipPolyline(line.Points, box);
    }
  }
}

} // namespace internal
} // namespace flowrecon
