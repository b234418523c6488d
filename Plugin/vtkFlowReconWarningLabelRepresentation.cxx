#include "vtkFlowReconWarningLabelRepresentation.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkLabeledDataMapper.h"
#include "vtkMath.h"
#include "vtkMaskPoints.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <cmath>
#include <map>
#include <sstream>
#include <string>
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
  vtkDataArray* spacing = pd ? pd->GetArray("Spacing") : nullptr;
  if (!threshold || !dimension || !change)
  {
    return nullptr;
  }
  const vtkIdType n = warnings->GetNumberOfPoints();
  // One label per place, on its first point: a point within the sphere of an
  // earlier one (radius Spacing, as drawn) joins its label, whose text would
  // otherwise be drawn over (a handful of places; past a few thousand, one per point).
  const bool cluster = spacing && n <= 2000;
  std::vector<vtkIdType> owners;
  std::map<vtkIdType, std::map<double, std::map<int, long long>>> sums;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    warnings->GetPoint(i, x);
    vtkIdType owner = i;
    for (const vtkIdType j : owners)
    {
      if (!cluster)
      {
        break;
      }
      double y[3];
      warnings->GetPoint(j, y);
      const double d2 = vtkMath::Distance2BetweenPoints(x, y);
      const double r = spacing->GetComponent(j, 0);
      if (d2 <= r * r)
      {
        owner = j;
        break;
      }
    }
    if (owner == i)
    {
      owners.push_back(i);
    }
    sums[owner][threshold->GetComponent(i, 0)][static_cast<int>(dimension->GetComponent(i, 0))] +=
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
    // "t_r 2.54: b1 -1, b2 -1", a line per t_r, the nearest first.
    std::ostringstream text;
    text.precision(3);
    const char* line = "";
    for (const auto& atThreshold : it->second)
    {
      text << line << "t_r " << atThreshold.first << ":";
      const char* separator = " ";
      for (const auto& dimensionSum : atThreshold.second)
      {
        text << separator << "b" << dimensionSum.first << " " << std::showpos
             << dimensionSum.second << std::noshowpos;
        separator = ", ";
      }
      line = "\n";
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
