#include "vtkFlowReconWarningLabelRepresentation.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkLabeledDataMapper.h"
#include "vtkMaskPoints.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkFlowReconWarningLabelRepresentation);

namespace
{
const char* const LabelArray = "Label";
}

//------------------------------------------------------------------------------
vtkFlowReconWarningLabelRepresentation::vtkFlowReconWarningLabelRepresentation()
{
  // Every place up to the label limit, the nearest t_r first (the output's
  // order), rather than ParaView's random sample of selected points.
  this->PointMask->RandomModeOff();
  this->PointLabelMapper->SetLabelModeToLabelFieldData();
  this->PointLabelMapper->SetFieldDataName(LabelArray);
}

//------------------------------------------------------------------------------
vtkStringArray* vtkFlowReconWarningLabelRepresentation::NewLabels(vtkDataSet* warnings)
{
  vtkPointData* pd = warnings ? warnings->GetPointData() : nullptr;
  vtkDataArray* threshold = pd ? pd->GetArray("Threshold") : nullptr;
  vtkDataArray* dimension = pd ? pd->GetArray("Dimension") : nullptr;
  vtkDataArray* change = pd ? pd->GetArray("Change") : nullptr;
  vtkDataArray* node = pd ? pd->GetArray("NodeId") : nullptr;
  if (!threshold || !dimension || !change)
  {
    return nullptr;
  }
  const vtkIdType n = warnings->GetNumberOfPoints();
  // One label per place (node and t_r), on its first point: the sum of the
  // changes of each dimension there.
  using Place = std::pair<double, double>;
  std::map<Place, vtkIdType> first;
  std::map<vtkIdType, std::map<int, long long>> sums;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const Place place{ node ? node->GetComponent(i, 0) : static_cast<double>(i),
      threshold->GetComponent(i, 0) };
    const vtkIdType owner = first.emplace(place, i).first->second;
    sums[owner][static_cast<int>(dimension->GetComponent(i, 0))] +=
      static_cast<long long>(std::llround(change->GetComponent(i, 0)));
  }
  auto* labels = vtkStringArray::New();
  labels->SetName(LabelArray);
  labels->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    auto it = sums.find(i);
    if (it == sums.end())
    {
      labels->SetValue(i, "");
      continue;
    }
    std::ostringstream text;
    text.precision(3);
    text << "t_r " << threshold->GetComponent(i, 0) << ":";
    const char* separator = " ";
    for (const auto& dimensionSum : it->second)
    {
      text << separator << "b" << dimensionSum.first << " " << std::showpos << dimensionSum.second
           << std::noshowpos;
      separator = ", ";
    }
    labels->SetValue(i, text.str());
  }
  return labels;
}

//------------------------------------------------------------------------------
int vtkFlowReconWarningLabelRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  // The superclass's merged copy of the input, labelled (it is what the view
  // delivers and the label mapper draws).
  if (auto* merged = vtkDataSet::SafeDownCast(this->Dataset))
  {
    vtkSmartPointer<vtkStringArray> labels;
    labels.TakeReference(NewLabels(merged));
    if (labels)
    {
      vtkSmartPointer<vtkDataSet> labelled;
      labelled.TakeReference(merged->NewInstance());
      labelled->ShallowCopy(merged);
      labelled->GetPointData()->AddArray(labels);
      this->Dataset = labelled;
    }
  }
  // Whatever the (unexposed) array name property says.
  this->PointLabelMapper->SetFieldDataName(LabelArray);
  return 1;
}
