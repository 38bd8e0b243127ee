#include "vtkStylizeFigureOverlays.h"

#include "vtkActor2D.h"
#include "vtkCellArray.h"
#include "vtkContext2D.h"
#include "vtkContextActor.h"
#include "vtkCoordinate.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkProp3D.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkScalarBarActor.h"
#include "vtkScalarBarActorInternal.h"
#include "vtkStylizeCairoContextDevice2D.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtkViewport.h"
#include "vtkWindow.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace vtkStylizeFigure
{
namespace
{
/**
 * Accesses a scalar bar's laid-out swatches and labels (protected in VTK) through pointers to
 * the members, which apply to any vtkScalarBarActor (casting the bar to this class would not:
 * it is not one).
 */
class ScalarBarPeek : public vtkScalarBarActor
{
public:
  static vtkScalarBarActorInternal* Layout(vtkScalarBarActor* bar)
  {
    vtkScalarBarActorInternal* vtkScalarBarActor::*member = &ScalarBarPeek::P;
    return bar->*member;
  }
  static vtkTextActor* Title(vtkScalarBarActor* bar)
  {
    vtkTextActor* vtkScalarBarActor::*member = &ScalarBarPeek::TitleActor;
    return bar->*member;
  }
};

/** A text actor as vector text, fitted to the box VTK laid it out in. */
void DrawText(Canvas& c, vtkTextActor* text, vtkViewport* viewport, int magnification)
{
  const char* input = text->GetInput();
  vtkTextProperty* tp = text->GetTextProperty();
  if (!input || !*input || !tp)
  {
    return;
  }
  double box[4];
  text->GetBoundingBox(viewport, box); // relative to the actor's position
  if (!(box[1] > box[0]) || !(box[3] > box[2]))
  {
    return;
  }
  const int* origin = text->GetActualPositionCoordinate()->GetComputedViewportValue(viewport);
  box[0] += origin[0];
  box[1] += origin[0];
  box[2] += origin[1];
  box[3] += origin[1];
  // 2D text keeps its pixel size in a magnified image; its place scales with the image.
  const int hj = tp->GetJustification(), vj = tp->GetVerticalJustification();
  const double anchorX =
    hj == VTK_TEXT_LEFT ? box[0] : (hj == VTK_TEXT_RIGHT ? box[1] : 0.5 * (box[0] + box[1]));
  const double anchorY =
    vj == VTK_TEXT_BOTTOM ? box[2] : (vj == VTK_TEXT_TOP ? box[3] : 0.5 * (box[2] + box[3]));
  const double shiftX = anchorX * (magnification - 1), shiftY = anchorY * (magnification - 1);
  const double x0 = box[0] + shiftX, x1 = box[1] + shiftX, y0 = box[2] + shiftY,
               y1 = box[3] + shiftY;

  const std::string family = tp->GetFontFamily() == VTK_COURIER
    ? "Liberation Mono"
    : (tp->GetFontFamily() == VTK_TIMES ? "Liberation Serif" : "Liberation Sans");
  cairo_select_font_face(c.Cr, family.c_str(),
    tp->GetItalic() ? CAIRO_FONT_SLANT_ITALIC : CAIRO_FONT_SLANT_NORMAL,
    tp->GetBold() ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  std::vector<std::string> lines;
  std::string s = input;
  for (size_t start = 0;;)
  {
    const size_t end = s.find('\n', start);
    lines.push_back(s.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos)
    {
      break;
    }
    start = end + 1;
  }
  // VTK's size: the text property's font size in points at the window's DPI; the lines stacked
  // from the top of VTK's box, which spans the lines' ascent to descent
  vtkWindow* window = viewport->GetVTKWindow();
  const double dpi = window ? window->GetDPI() : 72.0;
  const double spacing = tp->GetLineSpacing() > 0 ? tp->GetLineSpacing() : 1.0;
  cairo_set_font_size(c.Cr, tp->GetFontSize() * dpi / 72.0);
  cairo_font_extents_t fe;
  cairo_font_extents(c.Cr, &fe);
  const double height = (fe.ascent + fe.descent) * (1.0 + (lines.size() - 1) * spacing);
  // VTK's box starts at the top of the first line's ink (its top row is y1, whose upper edge
  // is y1 + 1): the baseline goes where that ink top meets the box's (centred in the box when
  // the first line has no ink)
  cairo_text_extents_t first;
  cairo_text_extents(c.Cr, lines[0].c_str(), &first);
  double baseline = first.height > 0.0 ? c.H - (y1 + 1.0) - first.y_bearing
                                       : c.H - 0.5 * (y0 + y1) - 0.5 * height + fe.ascent;
  // FreeType's hinted advances make VTK's lines a little wider or narrower than cairo's
  // unhinted ones: the lines are stretched to VTK's box width (by at most 10%)
  double widest = 0.0;
  for (const std::string& line : lines)
  {
    cairo_text_extents_t te;
    cairo_text_extents(c.Cr, line.c_str(), &te);
    widest = std::max(widest, te.x_advance);
  }
  const double stretch = widest > 0.0 ? std::max(0.9, std::min(1.1, (x1 - x0) / widest)) : 1.0;
  double* rgb = tp->GetColor();
  cairo_set_source_rgba(c.Cr, rgb[0], rgb[1], rgb[2], tp->GetOpacity());
  for (const std::string& line : lines)
  {
    cairo_text_extents_t te;
    cairo_text_extents(c.Cr, line.c_str(), &te);
    const double w = te.x_advance * stretch;
    double x = x0;
    if (hj == VTK_TEXT_CENTERED)
    {
      x = 0.5 * (x0 + x1 - w);
    }
    else if (hj == VTK_TEXT_RIGHT)
    {
      x = x1 - w;
    }
    cairo_save(c.Cr);
    cairo_translate(c.Cr, x, baseline);
    cairo_scale(c.Cr, stretch, 1.0);
    cairo_move_to(c.Cr, 0.0, 0.0);
    cairo_show_text(c.Cr, line.c_str());
    cairo_restore(c.Cr);
    baseline += (fe.ascent + fe.descent) * spacing;
  }
  cairo_new_path(c.Cr);
  ++c.Texts;
}

/** A scalar bar: its colour swatches as filled shapes, its title and labels as vector text. */
void DrawScalarBar(Canvas& c, vtkScalarBarActor* bar, vtkViewport* viewport, int magnification)
{
  vtkScalarBarActorInternal* layout = ScalarBarPeek::Layout(bar);
  if (layout && layout->SwatchPts && layout->Polys && layout->SwatchColors)
  {
    int* origin = bar->GetPositionCoordinate()->GetComputedViewportValue(viewport);
    const double ox = origin[0] * magnification, oy = origin[1] * magnification;
    vtkCellArray* polys = layout->Polys;
    vtkIdType npts;
    const vtkIdType* ids;
    vtkIdType cell = 0;
    for (polys->InitTraversal(); polys->GetNextCell(npts, ids); ++cell)
    {
      if (npts < 3 || cell >= layout->SwatchColors->GetNumberOfTuples())
      {
        continue;
      }
      cairo_new_path(c.Cr);
      for (vtkIdType k = 0; k < npts; ++k)
      {
        double q[3];
        layout->SwatchPts->GetPoint(ids[k], q);
        const double x = ox + q[0] * magnification, y = c.H - (oy + q[1] * magnification);
        k == 0 ? cairo_move_to(c.Cr, x, y) : cairo_line_to(c.Cr, x, y);
      }
      cairo_close_path(c.Cr);
      double color[4] = { 0, 0, 0, 255 };
      layout->SwatchColors->GetTuple(cell, color);
      const int n = layout->SwatchColors->GetNumberOfComponents();
      cairo_set_source_rgba(
        c.Cr, color[0] / 255.0, color[1] / 255.0, color[2] / 255.0, n > 3 ? color[3] / 255.0 : 1.0);
      // a hairline of the swatch's own colour closes the anti-aliased seams between swatches
      cairo_fill_preserve(c.Cr);
      cairo_set_line_width(c.Cr, 0.5);
      cairo_stroke(c.Cr);
      ++c.Rectangles;
    }
  }
  if (vtkTextActor* title = ScalarBarPeek::Title(bar))
  {
    if (title->GetVisibility())
    {
      DrawText(c, title, viewport, magnification);
    }
  }
  if (layout)
  {
    for (auto& label : layout->TextActors)
    {
      if (label && label->GetVisibility())
      {
        DrawText(c, label, viewport, magnification);
      }
    }
  }
}
}

//------------------------------------------------------------------------------
std::vector<vtkRenderer*> SceneOverlayRenderers(vtkRenderWindow* window, vtkRenderer* styleRenderer)
{
  std::vector<vtkRenderer*> out;
  vtkRendererCollection* renderers = window->GetRenderers();
  renderers->InitTraversal();
  while (vtkRenderer* ren = renderers->GetNextItem())
  {
    if (ren == styleRenderer || !ren->GetDraw())
    {
      continue;
    }
    vtkPropCollection* props = ren->GetViewProps();
    props->InitTraversal();
    while (vtkProp* prop = props->GetNextProp())
    {
      if (prop->GetVisibility() && vtkProp3D::SafeDownCast(prop))
      {
        out.push_back(ren);
        break;
      }
    }
  }
  return out;
}

//------------------------------------------------------------------------------
void DrawOverlayPixels(Canvas& c, const Image& with, const Image& without)
{
  if (with.W != without.W || with.H != without.H || with.W <= 0 || with.H <= 0)
  {
    return;
  }
  int x0 = with.W, y0 = with.H, x1 = -1, y1 = -1;
  for (int y = 0; y < with.H; ++y)
  {
    for (int x = 0; x < with.W; ++x)
    {
      if (with.Key(x, y) != without.Key(x, y))
      {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
    }
  }
  if (x1 < 0)
  {
    return;
  }
  // (rows top to bottom in cairo; the images' row 0 is the bottom)
  const int w = x1 - x0 + 1, h = y1 - y0 + 1;
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
  cairo_surface_flush(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = y0; y <= y1; ++y)
  {
    auto* row = reinterpret_cast<uint32_t*>(data + static_cast<size_t>(y1 - y) * stride);
    for (int x = x0; x <= x1; ++x)
    {
      const unsigned key = with.Key(x, y);
      row[x - x0] = key != without.Key(x, y) ? (0xff000000u | key) : 0u;
    }
  }
  cairo_surface_mark_dirty(surface);
  cairo_save(c.Cr);
  cairo_set_source_surface(c.Cr, surface, x0, c.H - 1 - y1);
  cairo_pattern_set_filter(cairo_get_source(c.Cr), CAIRO_FILTER_NEAREST);
  cairo_paint(c.Cr);
  cairo_restore(c.Cr);
  cairo_surface_destroy(surface);
  ++c.Images;
}

//------------------------------------------------------------------------------
std::vector<Overlay> HideOverlays(
  vtkRenderWindow* window, std::vector<std::pair<vtkProp*, int>>& hidden)
{
  std::vector<Overlay> overlays;
  vtkRendererCollection* renderers = window->GetRenderers();
  renderers->InitTraversal();
  while (vtkRenderer* ren = renderers->GetNextItem())
  {
    // the 2D actors of the visible props (a hidden widget's representation keeps its text
    // actor's own visibility on: ParaView's annotation)
    vtkNew<vtkPropCollection> actors;
    vtkPropCollection* props = ren->GetViewProps();
    props->InitTraversal();
    while (vtkProp* prop = props->GetNextProp())
    {
      if (prop->GetVisibility())
      {
        prop->GetActors2D(actors);
        // a vtkContextActor is a 2D overlay but not a vtkActor2D
        if (vtkContextActor::SafeDownCast(prop))
        {
          actors->AddItem(prop);
        }
      }
    }
    actors->InitTraversal();
    while (vtkProp* actor = actors->GetNextProp())
    {
      if (!(vtkActor2D::SafeDownCast(actor) || vtkContextActor::SafeDownCast(actor)) ||
        !actor->GetVisibility())
      {
        continue;
      }
      // drawn after the layers: as text, through vtkContext2D, or as a scalar bar; what none
      // of them draws is named in the warning
      overlays.push_back({ actor, ren });
      hidden.emplace_back(actor, actor->GetVisibility());
      actor->VisibilityOff();
    }
  }
  return overlays;
}

//------------------------------------------------------------------------------
void DrawOverlays(Canvas& c, const std::vector<Overlay>& overlays, const PaintFunction& paint)
{
  std::vector<std::string> leftOut;
  vtkNew<vtkStylizeCairoContextDevice2D> device;
  for (const Overlay& o : overlays)
  {
    o.Actor->SetVisibility(1);
    if (auto* text = vtkTextActor::SafeDownCast(o.Actor))
    {
      DrawText(c, text, o.Renderer, c.Magnification);
    }
    else
    {
      // what paints itself through vtkContext2D (a vtkContextActor's scene, ParaView's scalar
      // bars), as vectors; 2D actors magnified with the page
      device->SetTarget(c.Cr, c.H, c.Magnification);
      device->Begin(o.Renderer);
      vtkNew<vtkContext2D> painter;
      painter->Begin(device);
      const bool painted = paint(o.Actor, o.Renderer, painter);
      painter->End();
      device->End();
      c.Paths += device->GetNumberOfShapes();
      c.Texts += device->GetNumberOfTexts();
      c.Images += device->GetNumberOfImages();
      auto* bar = vtkScalarBarActor::SafeDownCast(o.Actor);
      if (!painted && bar)
      {
        DrawScalarBar(c, bar, o.Renderer, c.Magnification);
      }
      else if (!painted)
      {
        leftOut.emplace_back(o.Actor->GetClassName());
      }
    }
    o.Actor->SetVisibility(0);
  }
  if (!leftOut.empty())
  {
    c.Warning += "left out the 2D actors that are neither text, scalar bars nor painted "
                 "through vtkContext2D (";
    for (size_t i = 0; i < leftOut.size(); ++i)
    {
      c.Warning += (i ? ", " : "") + leftOut[i];
    }
    c.Warning += "); ";
  }
}
}
