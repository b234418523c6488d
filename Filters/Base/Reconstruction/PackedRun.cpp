#include "PackedRun.h"

#include <algorithm>
#include <limits>

namespace flowrecon
{

namespace
{

bool Fits32(Id v)
{
  return v >= std::numeric_limits<std::int32_t>::min() && v <= std::numeric_limits<std::int32_t>::max();
}

} // namespace

PackedRun Pack(const ReconstructionResult& run, const std::vector<Id>& carriers)
{
  const Id nodes = static_cast<Id>(run.Nodes.size());
  if (carriers.size() != run.Nodes.size() || !Fits32(nodes) ||
    run.InitializationCount < 0 || run.InitializationCount > static_cast<Id>(run.Order.size()))
  {
    throw InputError("packing a run: its carriers, nodes or steps do not match");
  }
  PackedRun p;
  p.NodeCount = nodes;
  p.InitializationCount = run.InitializationCount;
  const std::size_t steps = run.Order.size();
  p.Order.resize(steps);
  p.Priority.resize(steps);
  p.Sponsor.resize(steps);
  p.Kind.resize(steps);
  double running = 1;
  bool runningMaximum = true;
  for (std::size_t k = 0; k < steps; ++k)
  {
    const Id node = run.Order[k];
    if (node < 0 || node >= nodes || run.Nodes[node].Step != static_cast<Id>(k))
    {
      throw InputError("packing a run: step " + std::to_string(k) + " names no node inserted there");
    }
    const Insertion& in = run.Nodes[node];
    p.Order[k] = static_cast<std::int32_t>(node);
    p.Priority[k] = in.Priority;
    p.Sponsor[k] = in.Sponsor;
    p.Kind[k] = static_cast<std::uint8_t>(in.Kind);
    running = std::max(running, in.Priority);
    runningMaximum = runningMaximum && in.Threshold == running;
  }
  if (!runningMaximum)
  {
    p.Threshold.resize(steps);
    for (std::size_t k = 0; k < steps; ++k)
    {
      p.Threshold[k] = run.Nodes[run.Order[k]].Threshold;
    }
  }
  if (std::any_of(carriers.begin(), carriers.end(), [nodes](Id c) { return c < -1 || c >= nodes; }))
  {
    throw InputError("packing a run: a carrier names no node");
  }
  p.Carriers.assign(carriers.begin(), carriers.end()); // node ids: 32 bits (checked above)
  return p;
}

void Unpack(const PackedRun& p, ReconstructionResult& run, std::vector<Id>& carriers)
{
  run.Nodes.assign(static_cast<std::size_t>(p.NodeCount), Insertion());
  run.Order.assign(p.Order.begin(), p.Order.end());
  run.InitializationCount = p.InitializationCount;
  double running = 1;
  for (std::size_t k = 0; k < p.Order.size(); ++k)
  {
    Insertion& in = run.Nodes[static_cast<std::size_t>(p.Order[k])];
    running = std::max(running, p.Priority[k]);
    in.Step = static_cast<Id>(k);
    in.Priority = p.Priority[k];
    in.Threshold = p.Threshold.empty() ? running : p.Threshold[k];
    in.Kind = static_cast<Extension>(p.Kind[k]);
    in.Sponsor = p.Sponsor[k];
  }
  carriers.assign(p.Carriers.begin(), p.Carriers.end());
}

} // namespace flowrecon
