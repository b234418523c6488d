#include "FlowReconDisplayDefaults.h"

#include "vtkClientServerInterpreter.h"
#include "vtkClientServerInterpreterInitializer.h"
#include "vtkClientServerStream.h"
#include "vtkFlowReconDisplayInitializationHelper.h"
#include "vtkFlowReconWarningLabelRepresentation.h"
#include "vtkSMSettings.h"

namespace
{
vtkObjectBase* NewHelper(void*)
{
  return vtkFlowReconDisplayInitializationHelper::New();
}

vtkObjectBase* NewWarningLabels(void*)
{
  return vtkFlowReconWarningLabelRepresentation::New();
}

// The label representation adds no method to vtkDataLabelRepresentation: its
// commands are that class's (what a wrapped subclass would forward to).
int WarningLabelsCommand(vtkClientServerInterpreter* interpreter, vtkObjectBase* object,
  const char* method, const vtkClientServerStream& message, vtkClientServerStream& result, void*)
{
  return interpreter->CallCommandFunction(
    "vtkDataLabelRepresentation", object, method, message, result);
}

void RegisterHelper(vtkClientServerInterpreter* interpreter)
{
  interpreter->AddNewInstanceFunction("vtkFlowReconDisplayInitializationHelper", NewHelper);
  interpreter->AddNewInstanceFunction("vtkFlowReconWarningLabelRepresentation", NewWarningLabels);
  interpreter->AddCommandFunction("vtkFlowReconWarningLabelRepresentation", WarningLabelsCommand);
}

// Settings ".array_lookup_tables.<array>": vtkSMTransferFunctionManager applies
// them when it creates the colour map of an array of that name. Index: the
// index of a critical point (Flow Complex) or of the node a reconstructed cell
// belongs to (Flow Reconstruction); Extension: how a node entered the
// reconstruction. Colours: those of Apps/demo/render.py (blue, orange, red),
// with a light grey for 0, which stays visible on the default background.
// Their values are fixed, so they are never rescaled ("Never"): a rescale on
// Apply gathers the array's prominent values, about 3 % of a t_r change.
const char* const Settings = R"json({
  "array_lookup_tables": {
    "Index": { "PVLookupTable": {
      "IndexedLookup": 1, "AnnotationsInitialized": 1, "AutomaticRescaleRangeMode": -1,
      "Annotations": ["0", "minimum (sample)", "1", "index-1 saddle (Gabriel edge)",
                      "2", "index-2 saddle (Gabriel triangle)", "3", "maximum"],
      "IndexedColors": [0.85, 0.85, 0.85, 0.12, 0.47, 0.71, 0.85, 0.55, 0.2, 0.75, 0.2, 0.2] } },
    "Extension": { "PVLookupTable": {
      "IndexedLookup": 1, "AnnotationsInitialized": 1, "AutomaticRescaleRangeMode": -1,
      "Annotations": ["0", "initialization", "1", "regularization", "2", "upflow",
                      "3", "horizontal"],
      "IndexedColors": [0.85, 0.85, 0.85, 0.12, 0.47, 0.71, 0.85, 0.55, 0.2, 0.75, 0.2, 0.2] } }
  }
})json";

bool Done = false;
} // namespace

void FlowReconDisplayDefaults()
{
  if (Done)
  {
    return;
  }
  Done = true;
  vtkSMSettings::GetInstance()->AddCollectionFromString(Settings, 0.0);
  vtkClientServerInterpreterInitializer::GetInitializer()->RegisterCallback(RegisterHelper);
}
