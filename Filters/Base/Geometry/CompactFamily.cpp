#include "CompactFamily.h"

#include "Retriangulation.h"

#include <cmath>

namespace flowrecon
{

namespace
{

/// Every node whose cells are in the reconstruction at `t` (index 0 to 3).
std::vector<Id> NodesAt(const std::vector<Id>& carriers, const ReconstructionResult& run, double t)
{
  std::vector<Id> nodes;
  for (std::size_t i = 0; i < carriers.size(); ++i)
  {
    if (carriers[i] >= 0 && run.Contains(carriers[i], t))
    {
      nodes.push_back(static_cast<Id>(i));
    }
  }
  return nodes;
}

} // namespace

CompactFamily::CompactFamily(const FlowComplex& fc, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double tmax, std::unique_ptr<Retriangulation> re,
  const Progress& progress, const std::string& advice)
  : FC(fc)
  , Carriers(carriers)
  , Run(run)
  , Tmax(tmax)
{
  if (!re)
  {
    re = Retriangulation::OfStoredComplex(fc, progress.Range(0, 0.4), advice);
  }
  this->Pieces =
    PrepareCompact(*re, fc.Nodes, NodesAt(carriers, run, tmax), progress.Range(0.4, 1));
  this->Cells = CellsOf(*re);
}

CompactFamily::~CompactFamily() = default;

CompactComplex CompactFamily::At(double tr, std::vector<double>& nodeThreshold) const
{
  const std::vector<Id> selected = NodesAt(this->Carriers, this->Run, std::min(tr, this->Tmax));
  nodeThreshold.assign(this->FC.Nodes.size(), std::nan(""));
  for (const Id node : selected)
  {
    nodeThreshold[node] = this->Run.Nodes[this->Carriers[node]].Threshold;
  }
  return SelectCompact(this->Cells, this->FC.Nodes, this->Pieces, selected, false);
}

} // namespace flowrecon
