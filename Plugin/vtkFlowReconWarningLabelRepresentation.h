// The labels of the under-sampling warnings in a render view.
#ifndef vtkFlowReconWarningLabelRepresentation_h
#define vtkFlowReconWarningLabelRepresentation_h

#include "vtkDataLabelRepresentation.h"

class vtkDataSet;
class vtkStringArray;

/**
 * @class vtkFlowReconWarningLabelRepresentation
 * @brief ParaView's point labels of a data set, each saying what changes there.
 *
 * The Under Sampling output of Flow Reconstruction (and of Reconstruct Point
 * Cloud) has one point per change of the Betti numbers just above t_r, with
 * the point data Threshold, Dimension, Change, Spacing and NodeId. This
 * representation labels each place "t_r 2.31: b1 -1" (the t_r above which the
 * k-th Betti number changes, and by how much) and draws nothing else. The
 * points within the sphere (radius Spacing) of an earlier one share its
 * label, on that point, a line per t_r: their texts would be drawn over
 * each other. It is ParaView's
 * vtkDataLabelRepresentation (properties, delivery, rendering) with the label
 * text made from those arrays, which no label format of one array can say.
 *
 * FlowReconUnderSamplingRepresentation (FlowReconstruction.xml) uses it as the
 * label part of its selection representation, so that the labels follow the
 * spheres' visibility. Not wrapped: FlowReconDisplayDefaults() registers it
 * with the ClientServer interpreter, its commands being
 * vtkDataLabelRepresentation's.
 */
class vtkFlowReconWarningLabelRepresentation : public vtkDataLabelRepresentation
{
public:
  static vtkFlowReconWarningLabelRepresentation* New();
  vtkTypeMacro(vtkFlowReconWarningLabelRepresentation, vtkDataLabelRepresentation);

  /// The label of each point of `warnings` ("" for a point whose change is
  /// told on an earlier point's label), in a string array named Label;
  /// nullptr when the arrays are missing.
  static vtkStringArray* NewLabels(vtkDataSet* warnings);

protected:
  vtkFlowReconWarningLabelRepresentation();
  ~vtkFlowReconWarningLabelRepresentation() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkFlowReconWarningLabelRepresentation(const vtkFlowReconWarningLabelRepresentation&) = delete;
  void operator=(const vtkFlowReconWarningLabelRepresentation&) = delete;
};

#endif
