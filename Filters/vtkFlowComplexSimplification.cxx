#include "vtkFlowComplexSimplification.h"

#include "CoreCall.h"
#include "AutomaticThresholds.h"
#include "FlowComplexConversion.h"
#include "FlowReconNames.h"
#include "MemoryGuard.h"
#include "ReconstructionReport.h"
#include "Retriangulation.h"
#include "Simplification.h"
#include "StoredComplexTopology.h"
#include "SurvivingBlocks.h"
#include "TopologyConversion.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>

namespace
{

/// The topology of the reconstructions of one t_p, from the Hasse diagram.
flowrecon::StoredTopology TopologyAt(const flowrecon::FlowComplex& fc, double tp, double cap,
  const flowrecon::Retriangulation* re, const flowrecon::Progress& progress)
{
  try
  {
    return flowrecon::TopologyOfStoredComplex(fc, tp, cap, re, progress);
  }
  catch (const flowrecon::Degenerate&)
  {
    throw flowrecon::InputError("a deferred patch met a tie the flow complex did not see: "
                                "set Defer Patches Above to 0 in Flow Complex");
  }
}

/// The deferred patches drawn below the cap are walked on the samples'
/// triangulation, computed again (the input does not hold it).
std::unique_ptr<flowrecon::Retriangulation> TriangulationFor(
  const flowrecon::FlowComplex& fc, const flowrecon::Progress& progress)
{
  if (fc.DeferredPatches.empty())
  {
    return nullptr;
  }
  return flowrecon::Retriangulation::OfStoredComplex(
    fc, progress, "lower Defer Patches Above in Flow Complex, or the cloud's size");
}

/// The t_p (chosen or given) and the Betti numbers of its reconstructions.
struct PersistenceChoice
{
  std::vector<double> Candidates{ { 1.1, 0 } };
  double Chosen = 1.1;
  std::vector<std::string> Warnings;
  bool HasBars = false; ///< Bars hold every t_r below BarsBelow
  std::vector<flowrecon::Bar> Bars;
  double BarsBelow = HUGE_VAL;
};

/// The automatic t_p: the candidate whose reconstructions up to `cap` have
/// the most stable topology, and what the choice warns about.
PersistenceChoice ChoosePersistenceThreshold(const flowrecon::FlowComplex& fc,
  const std::vector<flowrecon::Point3>& samples, double cap, const flowrecon::Progress& progress)
{
  PersistenceChoice c;
  const std::unique_ptr<flowrecon::Retriangulation> re =
    TriangulationFor(fc, progress.Range(0, 0.3));
  std::vector<flowrecon::StoredTopology> topologies;
  std::vector<std::vector<flowrecon::TopologyStep>> profiles;
  const double share = 0.7 / static_cast<double>(c.Candidates.size());
  for (std::size_t k = 0; k < c.Candidates.size(); ++k)
  {
    const double from = 0.3 + share * static_cast<double>(k);
    topologies.push_back(
      TopologyAt(fc, c.Candidates[k], cap, re.get(), progress.Range(from, from + share)));
    const flowrecon::StoredTopology& t = topologies.back();
    if (!t.Error.empty())
    {
      std::ostringstream line;
      line << "t_p " << c.Candidates[k] << ": no Betti numbers: " << t.Error;
      c.Warnings.push_back(line.str());
    }
    profiles.push_back(t.Profile);
  }
  flowrecon::ThresholdChoice choice = flowrecon::ChooseThresholds(profiles, cap);
  // As on a cloud: a surface filled in, and then a window with a void
  // (samples: empty when the input lacks them, which leaves the choice).
  const std::vector<double>& maxima = topologies[choice.Candidate].MaximumThresholds;
  flowrecon::CheckFilled(choice, samples,
    static_cast<flowrecon::Id>(std::lower_bound(maxima.begin(), maxima.end(), choice.ReconstructionThreshold) -
      maxima.begin()));
  flowrecon::PreferSurface(choice, profiles, cap);
  c.Chosen = c.Candidates[choice.Candidate];
  flowrecon::StoredTopology& chosen = topologies[choice.Candidate];
  c.HasBars = chosen.Error.empty();
  c.Bars = std::move(chosen.Bars);
  c.BarsBelow = fc.DeferredPatches.empty() ? HUGE_VAL : cap;
  for (const std::string& line :
    flowrecon::PersistenceChoiceWarnings(choice, c.Candidates, /*trChosen=*/true))
  {
    c.Warnings.push_back(line);
  }
  return c;
}

/// The choice in the output's field data, for Flow Reconstruction to carry on.
void AddChoice(const PersistenceChoice& c, vtkMultiBlockDataSet* output)
{
  vtkFieldData* fd = output->GetFieldData();
  vtkNew<vtkIntArray> chosen;
  chosen->SetName(flowrecon::names::ThresholdsChosen);
  chosen->InsertNextValue(0); // t_r: Flow Reconstruction's choice
  chosen->InsertNextValue(1);
  fd->AddArray(chosen);
  vtkNew<vtkDoubleArray> candidates;
  candidates->SetName(flowrecon::names::PersistenceCandidates);
  for (const double tp : c.Candidates)
  {
    candidates->InsertNextValue(tp);
  }
  fd->AddArray(candidates);
  vtkNew<vtkStringArray> warnings;
  warnings->SetName(flowrecon::names::ThresholdWarnings);
  for (const std::string& line : c.Warnings)
  {
    warnings->InsertNextValue(line);
  }
  fd->AddArray(warnings);
}

} // namespace

vtkStandardNewMacro(vtkFlowComplexSimplification);

//------------------------------------------------------------------------------
vtkFlowComplexSimplification::vtkFlowComplexSimplification() = default;
vtkFlowComplexSimplification::~vtkFlowComplexSimplification() = default;

//------------------------------------------------------------------------------
int vtkFlowComplexSimplification::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

//------------------------------------------------------------------------------
int vtkFlowComplexSimplification::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkMultiBlockDataSet* input = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output.");
    return 0;
  }
  if (input->GetNumberOfBlocks() == 0)
  {
    // Empty in, empty out: what the other ranks of a parallel run receive
    // (vtkFlowComplex computes on rank 0 only).
    output->Initialize();
    return 1;
  }
  flowrecon::FlowComplex fc;
  flowrecon::SimplificationResult previous;
  std::string error;
  // The simplification changes the arcs only: the drawn geometry is neither
  // read nor copied (ReplaceHasseDiagram shares it with the input).
  if (!flowrecon::FromMultiBlock(input, fc, error, /*diagramOnly=*/true))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (flowrecon::SimplificationFromMultiBlock(
        input, static_cast<flowrecon::Id>(fc.Nodes.size()), previous, error) ||
    !error.empty())
  {
    vtkErrorMacro(<< (error.empty() ? std::string("the input is already simplified; simplify the "
                                                  "flow complex itself instead")
                                    : error));
    return 0;
  }

  const bool deferred = !fc.DeferredPatches.empty();
  const bool automatic = this->AutomaticPersistenceThreshold;
  // The topology of a given t_p needs one more queue (the choice has it).
  const bool topology = automatic || this->ComputeTopology;
  if (topology && deferred && !flowrecon::ReadSamples(input, fc, error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (automatic && !deferred && !flowrecon::ReadSamples(input, fc, error))
  {
    // Only CheckFilled's flatness reads them: without, no solid is taken for
    // a surface filled in (and none is warned of).
    fc.Points.clear();
    error.clear();
  }
  if (automatic && deferred && !(this->MaximumThreshold <= fc.DeferralRatio))
  {
    vtkErrorMacro(<< "Maximum Threshold (T_max) " << this->MaximumThreshold
                  << " is above the input's Defer Patches Above (" << fc.DeferralRatio
                  << "): lower T_max, or raise Defer Patches Above in Flow Complex");
    return 0;
  }
  if (!automatic && deferred && !(this->PersistenceThreshold < fc.DeferralRatio))
  {
    // Cancellations at t_p could then use the arcs the complex does not have.
    vtkErrorMacro(<< "Persistence Threshold (t_p) " << this->PersistenceThreshold
                  << " must be below the input's Defer Patches Above (" << fc.DeferralRatio
                  << "): lower t_p, or raise Defer Patches Above in Flow Complex");
    return 0;
  }
  const flowrecon::Progress progress = flowrecon::AlgorithmProgress(this);
  const int ok = flowrecon::CallCore(
    this, "simplification",
    [&]() {
      PersistenceChoice choice;
      choice.Chosen = this->PersistenceThreshold;
      if (automatic)
      {
        this->SetProgressText("choosing t_p");
        const std::size_t n = std::min(fc.Points.size(), static_cast<std::size_t>(fc.NumberOfInputPoints));
        choice = ChoosePersistenceThreshold(fc,
          std::vector<flowrecon::Point3>(fc.Points.begin(), fc.Points.begin() + static_cast<std::ptrdiff_t>(n)),
          this->MaximumThreshold, progress.Range(0, 0.7));
      }
      else if (topology)
      {
        // Exact below the deferral ratio: a larger T_max downstream falls back
        // to the Betti numbers of the drawn cells.
        this->SetProgressText("Betti numbers");
        const double cap = deferred ? std::min(this->MaximumThreshold, fc.DeferralRatio) : HUGE_VAL;
        const auto re = TriangulationFor(fc, progress.Range(0, 0.3));
        flowrecon::StoredTopology t =
          TopologyAt(fc, choice.Chosen, cap, re.get(), progress.Range(0.3, 0.7));
        choice.HasBars = t.Error.empty();
        choice.Bars = std::move(t.Bars);
        choice.BarsBelow = cap;
        if (!t.Error.empty())
        {
          vtkWarningMacro(<< "no Betti numbers from the Hasse diagram: " << t.Error);
        }
      }
      const flowrecon::Progress rest = progress.Range(topology ? 0.7 : 0, 1);
      // With deferred patches, what a replay on them needs is recorded too.
      const flowrecon::SimplificationResult s = flowrecon::Simplify(fc.Nodes,
        std::vector<flowrecon::Arc>(fc.Arcs), choice.Chosen, rest.Range(0, 0.6), deferred);
      fc.Arcs = s.Arcs; // the HasseDiagram block shows the simplified diagram
      flowrecon::ReplaceHasseDiagram(input, fc, output);
      flowrecon::AddSimplification(fc, s, choice.Chosen, output);
      flowrecon::AddSurvivingBlocks(output); // what the display shows
      if (automatic)
      {
        AddChoice(choice, output);
      }
      if (choice.HasBars)
      {
        flowrecon::ReconstructionBarsToVTK(choice.Bars, choice.BarsBelow, output->GetFieldData());
      }
      flowrecon::SetDefaultScalars(output);
      this->SetProgressText(nullptr);
      fc = flowrecon::FlowComplex();
    },
    [&]() { output->Initialize(); });
  // The candidates' runs, their triangulation and the diagram's copy, freed
  // by now: handed back before Flow Reconstruction allocates its own.
  flowrecon::ReleaseFreedMemory();
  return ok;
}

//------------------------------------------------------------------------------
void vtkFlowComplexSimplification::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PersistenceThreshold: " << this->PersistenceThreshold << "\n";
  os << indent << "AutomaticPersistenceThreshold: " << (this->AutomaticPersistenceThreshold ? "on" : "off") << "\n";
  os << indent << "MaximumThreshold: " << this->MaximumThreshold << "\n";
  os << indent << "ComputeTopology: " << (this->ComputeTopology ? "on" : "off") << "\n";
}
