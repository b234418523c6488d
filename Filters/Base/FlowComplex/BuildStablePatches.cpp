// Build phase 3: the stable manifolds of the index-2 critical points (patches),
// walked in parallel chunks and merged in node order; their arrivals on Gabriel
// edges are the 1-2 arcs and multiplicities.
#include "BuildPhases.h"

#include "HugePages.h"
#include "MemoryGuard.h"
#include "StableManifold.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <string>

namespace flowrecon
{
namespace internal
{

/// A chunk of patches: walked in parallel (WalkPatches), then merged.
struct Builder::PatchBatch
{
  std::size_t Begin = 0, Last = 0;
  std::vector<Patch> Patches;
  std::vector<Id> Fallbacks;
  std::vector<std::vector<std::uint32_t>> Walked; ///< RecordedWalks codes, when recording
};

namespace
{

/// The RecordedWalks codes of a patch's Walked triangles (which it frees).
std::vector<std::uint32_t> WalkCodes(const Triangulation& tri, Patch& patch)
{
  std::vector<std::uint32_t> codes(patch.Walked.size());
  for (std::size_t j = 0; j < patch.Walked.size(); ++j)
  {
    CellHandle cell = patch.WalkedCells[j];
    int opposite = tri.OppositeOf(cell, patch.Walked[j]);
    if (tri.CellId(cell) < 0)
    {
      const CellHandle other = cell->neighbor(opposite);
      opposite = other->index(cell);
      cell = other;
    }
    codes[j] = RecordedWalks::Code(tri.CellId(cell), opposite);
  }
  patch.Walked = {};
  patch.WalkedCells = {};
  return codes;
}

} // namespace

void Builder::WalkStablePatches()
{
  FlowComplex& fc = this->FC;
  fc.Points.assign(this->Input.begin(), this->Input.end());
  fc.NumberOfInputPoints = static_cast<Id>(this->Input.size());
  fc.Triangles.clear();
  fc.TriangleNode.clear();
  // Where each patch's triangles start (for the index-3 cones); geometry only.
  this->TriangleBegin.assign(this->Options.StableManifolds ? this->Cs.Facets.size() + 1 : 0, 0);
  this->KeptWalks = RecordedWalks();
  this->RecordingWalks = this->Keep && this->Options.RecordWalks &&
    this->Tri->NumberOfCells() < RecordedWalks::CellLimit;
  if (this->RecordingWalks)
  {
    this->KeptWalks.Offsets.reserve(this->Cs.Facets.size() + 1);
    this->KeptWalks.Offsets.push_back(0);
    this->KeptWalks.Known.assign(this->Cs.Facets.size(), false);
  }
  const double nf = static_cast<double>(this->NFacets) + 1;
  // Patches are independent: compute them in parallel, chunk by chunk, and merge
  // them in node order on this thread (which also reports progress).
  const std::size_t chunk = PatchChunk;
  // A pipeline: the walks of the next chunk run on the workers while this thread
  // merges the current one (the merge is sequential: it appends to the arc list).
  PatchBatch current, next;
  tbb::task_group group;
  try
  {
    if (!this->Cs.Facets.empty())
    {
      this->WalkPatches(0, current);
    }
    for (std::size_t begin = 0; begin < this->Cs.Facets.size(); begin += chunk)
    {
      this->Report(0.35 + 0.35 * begin / nf, "stable manifolds");
      const bool more = begin + chunk < this->Cs.Facets.size();
      if (more)
      {
        group.run([this, begin, &next]() { this->WalkPatches(begin + chunk, next); });
      }
      try
      {
        this->MergePatches(current);
      }
      catch (...)
      {
        group.cancel();
        group.wait();
        throw;
      }
      group.wait(); // rethrows what the walks threw
      std::swap(current, next);
    }
  }
  catch (const Degenerate&)
  {
    if (this->First)
    {
      ++fc.Report.WalkTies;
    }
    throw;
  }
  current = PatchBatch();
  next = PatchBatch();
  if (this->Options.StableManifolds)
  {
    this->TriangleBegin[this->Cs.Facets.size()] = static_cast<Id>(fc.Triangles.size());
  }
  // The rows of the edges (FindEdge) served the walks only (unless the walks
  // go on later); the edges themselves stay, their positions are node ids.
  if (!this->Keep)
  {
    std::vector<Id>().swap(this->Cs.Edges.Offsets);
  }
}

void Builder::WalkPatches(std::size_t begin, PatchBatch& batch) const
{
  batch.Begin = begin;
  batch.Last = std::min(this->Cs.Facets.size(), begin + PatchChunk);
  batch.Patches.assign(batch.Last - begin, Patch());
  batch.Fallbacks.assign(batch.Last - begin, 0);
  batch.Walked.assign(this->RecordingWalks ? batch.Last - begin : 0, {});
  tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, batch.Last),
    [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i)
      {
        Patch& patch = batch.Patches[i - begin];
        if (!this->Deferred.empty() && this->Deferred[i])
        {
          continue;
        }
        patch = ComputeStableManifold(*this->Tri, this->Cs, i, this->Options.StableManifolds,
          batch.Fallbacks[i - begin], this->Options.ExactOnly, this->RecordingWalks);
        if (this->RecordingWalks)
        {
          batch.Walked[i - begin] = WalkCodes(*this->Tri, patch);
        }
        // Sorted here, in parallel: equal runs are the 1-2 multiplicities.
        std::sort(patch.Arrivals.begin(), patch.Arrivals.end());
      }
    });
}

void Builder::ReserveArcsFor(const PatchBatch& batch)
{
  FlowComplex& fc = this->FC;
  // Surfaces have far more 1-2 arcs than the first guess: grow the arc list to
  // an estimate of its final size (from the rate so far) rather than by
  // doubling, which would copy it several times and overshoot memory.
  std::size_t chunkArcs = 0;
  for (const Patch& patch : batch.Patches)
  {
    for (std::size_t k = 0; k < patch.Arrivals.size(); ++k)
    {
      chunkArcs += (k == 0 || patch.Arrivals[k] != patch.Arrivals[k - 1]) ? 1 : 0;
    }
  }
  if (fc.Arcs.size() + chunkArcs <= fc.Arcs.capacity())
  {
    return;
  }
  const std::size_t arcs12 = fc.Arcs.size() + chunkArcs - 2 * static_cast<std::size_t>(this->NEdges);
  const double perFacet = static_cast<double>(arcs12) / static_cast<double>(batch.Last);
  const std::size_t estimate = 2 * static_cast<std::size_t>(this->NEdges) +
    static_cast<std::size_t>(1.05 * perFacet * static_cast<double>(this->NFacets)) + 2 * this->Cs.Facets.size();
  const std::size_t grown = std::max(estimate, fc.Arcs.capacity() + fc.Arcs.capacity() / 2);
  // Surface samples with tubes have ~n^1.5 arcs: say so before the kernel
  // kills the process (the copy holds the old and the new list at once).
  RequireMemory(static_cast<double>(sizeof(Arc)) * static_cast<double>(grown + fc.Arcs.size()),
    "the Hasse diagram of " + this->Cloud() + " (about " + std::to_string(estimate) + " arcs)",
    "use fewer points (a subsample) or a machine with more memory");
  ReserveHuge(fc.Arcs, grown);
}

void Builder::MergePatches(PatchBatch& batch)
{
  FlowComplex& fc = this->FC;
  this->ReserveArcsFor(batch);
  for (std::size_t i = batch.Begin; i < batch.Last; ++i)
  {
    const Id node = this->Base2 + static_cast<Id>(i);
    Patch& patch = batch.Patches[i - batch.Begin];
    fc.Report.ExactFallbacks += batch.Fallbacks[i - batch.Begin];
    // Arrival counts per Gabriel edge are the 1-2 multiplicities.
    for (std::size_t k = 0; k < patch.Arrivals.size();)
    {
      std::size_t l = k;
      while (l < patch.Arrivals.size() && patch.Arrivals[l] == patch.Arrivals[k])
      {
        ++l;
      }
      fc.Arcs.emplace_back(this->Base1 + patch.Arrivals[k], node, static_cast<Id>(l - k));
      k = l;
    }
    if (this->Options.StableManifolds)
    {
      this->AppendPatchGeometry(i, patch);
    }
    if (this->RecordingWalks)
    {
      this->RecordWalk(i, batch);
    }
    patch = Patch(); // release memory early
  }
}

void Builder::RecordWalk(std::size_t i, PatchBatch& batch)
{
  RecordedWalks& w = this->KeptWalks;
  if (w.Offsets.empty())
  {
    return; // given up: more codes than 32-bit offsets hold
  }
  std::vector<std::uint32_t>& codes = batch.Walked[i - batch.Begin];
  if (w.Codes.size() + codes.size() > UINT32_MAX)
  {
    w = RecordedWalks(); // the compact output walks the patches itself
    return;
  }
  const bool walked = this->Deferred.empty() || !this->Deferred[i];
  w.Known[i] = walked;
  w.Codes.insert(w.Codes.end(), codes.begin(), codes.end());
  w.Offsets.push_back(static_cast<std::uint32_t>(w.Codes.size()));
  if (walked && batch.Fallbacks[i - batch.Begin] > 0)
  {
    w.Fallbacks.emplace_back(
      static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(batch.Fallbacks[i - batch.Begin]));
  }
  std::vector<std::uint32_t>().swap(codes);
}

void Builder::AppendPatchGeometry(std::size_t i, const Patch& patch)
{
  FlowComplex& fc = this->FC;
  const Id node = this->Base2 + static_cast<Id>(i);
  if (fc.Triangles.size() == fc.Triangles.capacity() && !fc.Triangles.empty())
  {
    // All the geometry was asked for: refuse before it no longer fits.
    const double perFacet = static_cast<double>(fc.Triangles.size()) / static_cast<double>(i);
    RequireMemory(3 * 48 * perFacet * static_cast<double>(this->NFacets),
      "drawing every stable manifold of " + this->Cloud(),
      "draw fewer cells (MaximumStableManifoldCells, flowrecon --max-cells)");
  }
  this->TriangleBegin[i] = static_cast<Id>(fc.Triangles.size());
  const Id offset = static_cast<Id>(fc.Points.size());
  fc.Points.insert(fc.Points.end(), patch.Constructed.begin(), patch.Constructed.end());
  fc.NodePoint[node] = offset; // Constructed[0] is the critical point
  for (const auto& tr : patch.Triangles)
  {
    std::array<Id, 3> v;
    for (int k = 0; k < 3; ++k)
    {
      v[k] = tr[k] >= 0 ? this->In.InputId[tr[k]] : offset + (-1 - tr[k]);
    }
    fc.Triangles.push_back(v);
    fc.TriangleNode.push_back(node);
  }
}

} // namespace internal
} // namespace flowrecon
