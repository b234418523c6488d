// The default look of a FlowRecon multiblock output in a render view.
#ifndef vtkFlowReconDisplayInitializationHelper_h
#define vtkFlowReconDisplayInitializationHelper_h

#include "vtkSMProxyInitializationHelper.h"

/**
 * @class vtkFlowReconDisplayInitializationHelper
 * @brief Chooses the colouring, the visible blocks or the arrow glyphs of a new display.
 *
 * Named by the hint of the representations FlowReconMultiBlockRepresentation
 * (FlowComplex.xml) and FlowReconSimplificationRepresentation
 * (FlowComplexSimplification.xml, the surviving blocks), which Flow Complex and
 * Flow Complex Simplification ask for in render views:
 *
 *   <InitializationHelper class="vtkFlowReconDisplayInitializationHelper"
 *     color_association="POINTS" color_array="Index" blocks="/Root/CriticalPoints"/>
 *
 * ParaView calls it when it sets up a display (vtkSMParaViewPipelineController::
 * PostInitializeProxy), before it picks defaults from the domains; it then sets
 * up the colour map of the array (vtkSMTransferFunctionManager, from settings).
 * A property is left alone when it was set since the display's creation or when
 * a setting (representations.<display>.<property>) gives it, and the colouring
 * only when the data has the array. `blocks` is a space-separated list of
 * selectors. `glyph_vectors="Direction"` (FlowReconArrowsRepresentation, the
 * sponsor arrows of Flow Reconstruction) shows the data as 3D Glyphs, arrows
 * oriented by that point vector and scaled by its magnitude times 1.
 * `sphere_radius_array="Spacing"` (FlowReconUnderSamplingRepresentation)
 * shows the points as Point Gaussian spheres of radius `sphere_radius_factor`
 * times that point array, with `opacity`; `solid_color="1 0 1"` colours the
 * display with that RGB (ambient and diffuse colours);
 * `text_justification="0"` (FlowReconTopologyTextRepresentation) left-justifies
 * a text display's lines (1 centred, 2 right).
 * `beside_render_view="0.65 2"` (the charts Apply opens) makes room for the
 * new view when the layout holds nothing but a render view showing port 0 of
 * the same source: the render view keeps 0.65 of the width and the right
 * part is cut into 2 empty cells, one above the other, which ParaView then
 * fills with the views it opens (instead of halving the render view each time).
 *
 * Not Python- or ClientServer-wrapped: FlowReconDisplayDefaults() registers the
 * class with the ClientServer interpreter, which is how ParaView creates it.
 */
class vtkFlowReconDisplayInitializationHelper : public vtkSMProxyInitializationHelper
{
public:
  static vtkFlowReconDisplayInitializationHelper* New();
  vtkTypeMacro(vtkFlowReconDisplayInitializationHelper, vtkSMProxyInitializationHelper);

  void PostInitializeProxy(vtkSMProxy* repr, vtkPVXMLElement* xml, vtkMTimeType ts) override;

protected:
  vtkFlowReconDisplayInitializationHelper() = default;
  ~vtkFlowReconDisplayInitializationHelper() override = default;

private:
  vtkFlowReconDisplayInitializationHelper(const vtkFlowReconDisplayInitializationHelper&) = delete;
  void operator=(const vtkFlowReconDisplayInitializationHelper&) = delete;
};

#endif
