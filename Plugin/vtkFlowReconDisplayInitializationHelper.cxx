#include "vtkFlowReconDisplayInitializationHelper.h"

#include "vtkDataObject.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVDataInformation.h"
#include "vtkPVXMLElement.h"
#include "vtkSMOutputPort.h"
#include "vtkSMProperty.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"
#include "vtkSMProxyIterator.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSettings.h"
#include "vtkSMSourceProxy.h"
#include "vtkSMViewLayoutProxy.h"
#include "vtkSMViewProxy.h"

#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkFlowReconDisplayInitializationHelper);

namespace
{
// The property is still at its initial value and no setting chose it.
bool IsFree(vtkSMProxy* repr, vtkSMProperty* property, const char* name, vtkMTimeType ts)
{
  if (!property || property->GetMTime() > ts)
  {
    return false;
  }
  const std::string setting = std::string(repr->GetXMLGroup()) + "." + repr->GetXMLName() + "." +
    name;
  return !vtkSMSettings::GetInstance()->HasSetting(
    setting.c_str(), std::numeric_limits<double>::max());
}

// The layout holding nothing but a render view that shows port 0 of `source`.
vtkSMViewLayoutProxy* LayoutOfItsRenderView(vtkSMProxy* source)
{
  vtkSMSessionProxyManager* pxm = source ? source->GetSessionProxyManager() : nullptr;
  if (!pxm)
  {
    return nullptr;
  }
  vtkNew<vtkSMProxyIterator> layouts;
  layouts->SetSessionProxyManager(pxm);
  layouts->SetModeToOneGroup();
  for (layouts->Begin("layouts"); !layouts->IsAtEnd(); layouts->Next())
  {
    auto* layout = vtkSMViewLayoutProxy::SafeDownCast(layouts->GetProxy());
    if (!layout || layout->IsSplitCell(0) || layout->GetViews().size() != 1)
    {
      continue;
    }
    vtkSMViewProxy* view = layout->GetView(0);
    auto* producer = vtkSMSourceProxy::SafeDownCast(source);
    if (view && std::strcmp(view->GetXMLName(), "RenderView") == 0 && producer &&
      view->FindRepresentation(producer, 0))
    {
      return layout;
    }
  }
  return nullptr;
}

// Empty cells beside the render view of `repr`'s source, before ParaView puts
// the new view in the layout: it takes the first empty cell, and would
// otherwise halve the render view for each view it opens.
void MakeRoomBesideRenderView(vtkSMProxy* repr, const char* spec)
{
  double fraction = 0.65;
  int cells = 1;
  std::istringstream words(spec);
  words >> fraction >> cells;
  vtkSMProxy* source =
    repr->GetProperty("Input") ? vtkSMPropertyHelper(repr, "Input").GetAsProxy() : nullptr;
  vtkSMViewLayoutProxy* layout = LayoutOfItsRenderView(source);
  if (!layout || !(fraction > 0 && fraction < 1) || cells < 1)
  {
    return;
  }
  int right = layout->SplitHorizontal(0, fraction) + 1;
  for (int k = cells; k > 1; --k)
  {
    right = layout->SplitVertical(right, 1.0 / k) + 1;
  }
}

// Integer properties of `repr` set, those it has.
void SetInts(vtkSMProxy* repr, std::initializer_list<std::pair<const char*, int>> values)
{
  for (const auto& value : values)
  {
    if (vtkSMProperty* p = repr->GetProperty(value.first))
    {
      vtkSMPropertyHelper(p).Set(value.second);
    }
  }
}

// blocks="...": the blocks shown.
bool BlockSelectorsHint(vtkSMProxy* repr, vtkPVXMLElement* xml, vtkMTimeType ts)
{
  vtkSMProperty* blocks = repr->GetProperty("BlockSelectors");
  const char* selectors = xml->GetAttribute("blocks");
  if (selectors && IsFree(repr, blocks, "BlockSelectors", ts))
  {
    std::istringstream words(selectors);
    const std::vector<std::string> list{ std::istream_iterator<std::string>(words),
      std::istream_iterator<std::string>() };
    vtkSMPropertyHelper helper(blocks);
    helper.SetNumberOfElements(static_cast<unsigned int>(list.size()));
    for (unsigned int i = 0; i < list.size(); ++i)
    {
      helper.Set(i, list[i].c_str());
    }
    return true;
  }
  return false;
}

// color_array, color_association: the array coloured by, where the input has it.
bool ColorArrayHint(vtkSMProxy* repr, vtkPVXMLElement* xml, vtkMTimeType ts)
{
  vtkSMProperty* color = repr->GetProperty("ColorArrayName");
  const char* array = xml->GetAttribute("color_array");
  const char* association = xml->GetAttribute("color_association");
  if (array && IsFree(repr, color, "ColorArrayName", ts))
  {
    const int field = (association && std::strcmp(association, "CELLS") == 0)
      ? vtkDataObject::FIELD_ASSOCIATION_CELLS
      : vtkDataObject::FIELD_ASSOCIATION_POINTS;
    vtkSMOutputPort* port = repr->GetProperty("Input")
      ? vtkSMPropertyHelper(repr, "Input").GetAsOutputPort()
      : nullptr;
    vtkPVDataInformation* info = port ? port->GetDataInformation() : nullptr;
    if (info && info->GetArrayInformation(array, field))
    {
      vtkSMPropertyHelper(color).SetInputArrayToProcess(field, array);
      return true;
    }
  }
  return false;
}

// The value of hint `attribute` when it applies: given, with the representation
// still the user's to choose; the representation is then set to `representation`.
const char* RepresentationHint(vtkSMProxy* repr, vtkPVXMLElement* xml, vtkMTimeType ts,
  const char* attribute, const char* representation)
{
  const char* value = xml->GetAttribute(attribute);
  vtkSMProperty* p = repr->GetProperty("Representation");
  if (!value || !IsFree(repr, p, "Representation", ts))
  {
    return nullptr;
  }
  vtkSMPropertyHelper(p).Set(representation);
  return value;
}

// A size property of `repr` set to `value`, if it has it. Marked modified, so
// that its bounds domain (a tenth of the data) does not replace it when `value`
// equals the XML default.
void SetSize(vtkSMProxy* repr, const char* name, double value)
{
  if (vtkSMProperty* p = repr->GetProperty(name))
  {
    vtkSMPropertyHelper(p).Set(value);
    p->Modified();
  }
}

// glyph_vectors: lines drawn as arrows, one glyph per point, oriented and scaled
// by a point vector that is the line itself at its start and zero at its end.
bool ArrowGlyphsHint(vtkSMProxy* repr, vtkPVXMLElement* xml, vtkMTimeType ts)
{
  const char* glyphs = RepresentationHint(repr, xml, ts, "glyph_vectors", "3D Glyphs");
  if (!glyphs)
  {
    return false;
  }
  SetInts(repr, { { "Orient", 1 }, { "Scaling", 1 }, { "ScaleMode", 1 /* magnitude */ } });
  for (const char* name : { "SelectOrientationVectors", "SelectScaleArray" })
  {
    if (vtkSMProperty* p = repr->GetProperty(name))
    {
      vtkSMPropertyHelper(p).Set(glyphs);
    }
  }
  SetSize(repr, "ScaleFactor", 1.0);
  return true;
}

// sphere_radius_array, sphere_radius_factor, opacity: spheres sized by a point
// array (Point Gaussian, radius = factor x value).
bool SpheresHint(vtkSMProxy* repr, vtkPVXMLElement* xml, vtkMTimeType ts)
{
  const char* scaleArray = RepresentationHint(repr, xml, ts, "sphere_radius_array", "Point Gaussian");
  if (!scaleArray)
  {
    return false;
  }
  SetInts(repr, { { "ShaderPreset", 1 /* Sphere */ }, { "ScaleByArray", 1 },
                  { "UseScaleFunction", 0 } });
  if (vtkSMProperty* p = repr->GetProperty("SetScaleArray"))
  {
    vtkSMPropertyHelper(p).SetInputArrayToProcess(vtkDataObject::FIELD_ASSOCIATION_POINTS, scaleArray);
  }
  double factor = 1;
  xml->GetScalarAttribute("sphere_radius_factor", &factor);
  SetSize(repr, "GaussianRadius", factor);
  double opacity = 1;
  vtkSMProperty* p = repr->GetProperty("Opacity");
  if (xml->GetScalarAttribute("opacity", &opacity) && p)
  {
    vtkSMPropertyHelper(p).Set(opacity);
  }
  return true;
}

// text_justification: text lines justified (0 left, 1 centred, 2 right).
bool JustificationHint(vtkSMProxy* repr, vtkPVXMLElement* xml, vtkMTimeType ts)
{
  int justification = 0;
  vtkSMProperty* justify = repr->GetProperty("Justification");
  if (xml->GetScalarAttribute("text_justification", &justification) &&
    IsFree(repr, justify, "Justification", ts))
  {
    vtkSMPropertyHelper(justify).Set(justification);
    return true;
  }
  return false;
}

// point_size: vertices drawn as shaded spheres of that many pixels. One display
// draws every block of a multiblock alike in ParaView 5.11, so the critical points
// cannot be world-size glyphs beside the Gabriel edges' lines.
bool PointSpheresHint(vtkSMProxy* repr, vtkPVXMLElement* xml, vtkMTimeType ts)
{
  double size = 0;
  vtkSMProperty* pointSize = repr->GetProperty("PointSize");
  vtkSMProperty* spheres = repr->GetProperty("RenderPointsAsSpheres");
  if (!xml->GetScalarAttribute("point_size", &size) || !spheres ||
    !IsFree(repr, pointSize, "PointSize", ts) || !IsFree(repr, spheres, "RenderPointsAsSpheres", ts))
  {
    return false;
  }
  vtkSMPropertyHelper(pointSize).Set(size);
  vtkSMPropertyHelper(spheres).Set(1);
  return true;
}

// solid_color: one colour (no array, no legend), replacing the palette's.
bool SolidColorHint(vtkSMProxy* repr, vtkPVXMLElement* xml, vtkMTimeType ts)
{
  bool changed = false;
  const char* rgb = xml->GetAttribute("solid_color");
  if (rgb)
  {
    std::istringstream words(rgb);
    double c[3] = { 1, 1, 1 };
    words >> c[0] >> c[1] >> c[2];
    for (const char* name : { "AmbientColor", "DiffuseColor" })
    {
      vtkSMProperty* p = repr->GetProperty(name);
      if (p && IsFree(repr, p, name, ts))
      {
        vtkSMPropertyHelper(p).Set(c, 3);
        changed = true;
      }
    }
  }
  return changed;
}
} // namespace

//------------------------------------------------------------------------------
void vtkFlowReconDisplayInitializationHelper::PostInitializeProxy(
  vtkSMProxy* repr, vtkPVXMLElement* xml, vtkMTimeType ts)
{
  bool changed = false;
  for (auto hint : { BlockSelectorsHint, ColorArrayHint, ArrowGlyphsHint, SpheresHint,
         JustificationHint, PointSpheresHint, SolidColorHint })
  {
    changed = hint(repr, xml, ts) || changed;
  }

  // A chart opened beside the render view (Apply): the render view keeps a
  // fraction of the width, the charts share the rest, one above the other.
  if (const char* beside = xml->GetAttribute("beside_render_view"))
  {
    MakeRoomBesideRenderView(repr, beside);
  }

  if (changed)
  {
    repr->UpdateVTKObjects();
  }
}
