#include "vtkStylizeFeatureStrokes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkStylizeFeatureLines.h"
#include "vtkStylizeLineVisibility.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace
{
/** A surface of the scene: its lines and their visibility, kept between frames. */
struct Surface
{
  vtkWeakPointer<vtkPolyData> Data;
  vtkNew<vtkStylizeFeatureLines> Lines;
  vtkNew<vtkStylizeLineVisibility> Visibility;
  bool Seen = false;
  /** The mean edge length of the surface's polygons, and the surface's time when measured. */
  double MeanEdge = 0.0;
  vtkMTimeType EdgeTime = 0;
};

/** The mean edge length of (up to 10000 of) the surface's polygons. */
double MeanEdgeLength(vtkPolyData* pd)
{
  vtkCellArray* polys = pd->GetPolys();
  const vtkIdType cells = polys->GetNumberOfCells();
  const vtkIdType stride = std::max<vtkIdType>(1, cells / 10000);
  double sum = 0.0;
  vtkIdType count = 0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < cells; c += stride)
  {
    polys->GetCellAtId(c, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    for (vtkIdType k = 0; k < n; ++k)
    {
      double a[3], b[3];
      pd->GetPoint(ids->GetId(k), a);
      pd->GetPoint(ids->GetId((k + 1) % n), b);
      const double d = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
      if (std::isfinite(d))
      {
        sum += d;
        ++count;
      }
    }
  }
  return count > 0 ? sum / count : 0.0;
}

/** How much a matrix scales lengths (the cube root of its 3 x 3 part's determinant). */
double ScaleOf(vtkMatrix4x4* m)
{
  if (!m)
  {
    return 1.0;
  }
  const double det = vtkMatrix4x4::Determinant(m->GetData()) / std::max(1e-300, std::fabs(m->GetElement(3, 3)));
  const double s = std::cbrt(std::fabs(det));
  return std::isfinite(s) ? s : 1.0;
}

/** A surface to draw this frame and the matrix from its coordinates to the world. */
struct Item
{
  vtkPolyData* Data;
  vtkMatrix4x4* Matrix;
};

void AddSurface(vtkDataObject* data, vtkMatrix4x4* matrix, std::vector<Item>& out)
{
  if (auto* pd = vtkPolyData::SafeDownCast(data))
  {
    if (pd->GetNumberOfPolys() + pd->GetNumberOfStrips() > 0)
    {
      out.push_back({ pd, matrix });
    }
  }
  else if (auto* cd = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(cd->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      AddSurface(it->GetCurrentDataObject(), matrix, out);
    }
  }
}

/** The visible opaque actors' surfaces. */
std::vector<Item> SurfacesOf(vtkRenderer* ren)
{
  std::vector<Item> items;
  vtkPropCollection* props = ren->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    auto* actor = vtkActor::SafeDownCast(prop);
    if (!actor || !actor->GetVisibility() || !actor->GetMapper() ||
      actor->GetProperty()->GetOpacity() < 1.0)
    {
      continue;
    }
    AddSurface(actor->GetMapper()->GetInputDataObject(0, 0), actor->GetMatrix(), items);
  }
  return items;
}

/** Coverage of a pixel centre at distance d from a stroke's axis of half width r. */
inline float Coverage(double d, double r)
{
  const double c = std::min(1.0, std::max(0.0, r + 0.5 - d));
  // Below a pixel's width a stroke keeps its ink (the profile's area, 2r) by fading.
  return static_cast<float>(r >= 0.5 ? c : c * 2.0 * r / ((r + 0.5) * (r + 0.5)));
}
}

struct vtkStylizeFeatureStrokes::Internals
{
  std::map<vtkPolyData*, std::unique_ptr<Surface>> Cache;
  vtkNew<vtkPolyData> Strokes;
  vtkNew<vtkImageData> Depth;
  int Size[2] = { 0, 0 };
  vtkTextureObject* Texture = nullptr;
  std::vector<float> Coverage;
};

vtkStandardNewMacro(vtkStylizeFeatureStrokes);

//------------------------------------------------------------------------------
vtkStylizeFeatureStrokes::vtkStylizeFeatureStrokes()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkStylizeFeatureStrokes::~vtkStylizeFeatureStrokes()
{
  if (this->Internal->Texture)
  {
    this->Internal->Texture->Delete();
  }
}

//------------------------------------------------------------------------------
double vtkStylizeFeatureStrokes::Reach(const Settings& settings, double pointSize)
{
  double widest = 0.0;
  for (double w : settings.Widths)
  {
    widest = std::max(widest, w);
  }
  return 0.5 * widest * pointSize + 1.0;
}

//------------------------------------------------------------------------------
void vtkStylizeFeatureStrokes::ClearCache()
{
  this->Internal->Cache.clear();
}

//------------------------------------------------------------------------------
vtkPolyData* vtkStylizeFeatureStrokes::GetStrokes()
{
  return this->Internal->Strokes;
}

//------------------------------------------------------------------------------
namespace
{
/** The strokes of one frame: the visible runs projected into the drawn pixels, with widths. */
class StrokeSink
{
public:
  using View = vtkStylizeFeatureStrokes::View;
  using Settings = vtkStylizeFeatureStrokes::Settings;

  StrokeSink(const View& view, const Settings& settings, vtkCamera* camera)
    : V(view)
    , S(settings)
  {
    this->Points->SetDataTypeToFloat();
    this->Widths->SetName("StrokeWidth");
    this->Kinds->SetName("FeatureKind");
    if (!camera)
    {
      return;
    }
    // The projection of the whole image, and the scene's depth range for the taper.
    this->Projection->DeepCopy(camera->GetCompositeProjectionTransformMatrix(
      view.FullSize[0] / std::max(1.0, view.FullSize[1]), -1.0, 1.0));
    this->ModelView->DeepCopy(camera->GetViewTransformMatrix());
    double b[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
    view.Renderer->ComputeVisiblePropBounds(b);
    if (vtkMath::AreBoundsInitialized(b))
    {
      const double center[4] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]),
        1.0 };
      double eye[4];
      this->ModelView->MultiplyPoint(center, eye);
      const double radius = 0.5 *
        std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
          (b[5] - b[4]) * (b[5] - b[4]));
      this->Nearest = -eye[2] - radius;
      this->Range = 2.0 * radius;
    }
  }

  /** Appends the runs (vtkStylizeLineVisibility's output) of a surface seen through `matrix`. */
  void Append(vtkPolyData* runs, vtkMatrix4x4* matrix)
  {
    vtkDataArray* strength = runs->GetPointData()->GetArray("FeatureStrength");
    vtkDataArray* cellKind = runs->GetCellData()->GetArray("FeatureKind");
    vtkNew<vtkMatrix4x4> toClip, toEye;
    vtkMatrix4x4::Multiply4x4(this->Projection, matrix, toClip);
    vtkMatrix4x4::Multiply4x4(this->ModelView, matrix, toEye);
    vtkCellArray* cells = runs->GetLines();
    vtkIdType cell = 0, n;
    const vtkIdType* ids;
    for (cells->InitTraversal(); cells->GetNextCell(n, ids); ++cell)
    {
      const int kind = cellKind ? static_cast<int>(cellKind->GetTuple1(cell)) : 0;
      if (kind < 0 || kind >= vtkStylizeFeatureStrokes::Kinds || n < 2)
      {
        continue;
      }
      this->Lines->InsertNextCell(static_cast<int>(n));
      this->Kinds->InsertNextValue(static_cast<unsigned char>(kind));
      for (vtkIdType i = 0; i < n; ++i)
      {
        double p[4] = { 0.0, 0.0, 0.0, 1.0 };
        runs->GetPoint(ids[i], p);
        double c[4], e[4];
        toClip->MultiplyPoint(p, c);
        toEye->MultiplyPoint(p, e);
        const double w = c[3] > 0.0 ? c[3] : 1.0;
        double x = (c[0] / w + 1.0) * 0.5 * this->V.FullSize[0] - this->V.FullOffset[0];
        double y = (c[1] / w + 1.0) * 0.5 * this->V.FullSize[1] - this->V.FullOffset[1];
        if (!std::isfinite(x) || !std::isfinite(y))
        {
          x = y = -1.0e6;
        }
        const double f = strength ? strength->GetTuple1(ids[i]) : 1.0;
        this->Lines->InsertCellPoint(this->Points->InsertNextPoint(x, y, 0.0));
        this->Widths->InsertNextValue(static_cast<float>(this->Width(kind, -e[2], f)));
      }
    }
  }

  /** The strokes into `out`; returns their number. */
  vtkIdType Finish(vtkPolyData* out)
  {
    out->Initialize();
    out->SetPoints(this->Points);
    out->SetLines(this->Lines);
    out->GetPointData()->AddArray(this->Widths);
    out->GetCellData()->AddArray(this->Kinds);
    return this->Lines->GetNumberOfCells();
  }

private:
  /** A stroke's width in pixels at eye depth z and strength f. */
  double Width(int kind, double z, double f) const
  {
    const double depth = this->Range > 0.0 ? (z - this->Nearest) / this->Range : 0.0;
    const double taper = 1.0 - this->S.DepthTaper * std::min(1.0, std::max(0.0, depth));
    const double strength = std::isfinite(f) ? std::min(1.0, std::max(0.0, f)) : 1.0;
    const double fade = 1.0 - this->S.StrengthTaper * (1.0 - strength);
    return this->S.Widths[kind] * this->V.PointSize * taper * fade;
  }

  const View& V;
  const Settings& S;
  vtkNew<vtkMatrix4x4> Projection, ModelView;
  double Nearest = 0.0, Range = 0.0;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Lines;
  vtkNew<vtkFloatArray> Widths;
  vtkNew<vtkUnsignedCharArray> Kinds;
};

/** The kinds a frame computes: those with a width; the interactive variant, the cheap ones. */
int KindMask(const vtkStylizeFeatureStrokes::Settings& settings, bool interactive)
{
  int mask = 0;
  for (int k = 0; k < vtkStylizeFeatureStrokes::Kinds; ++k)
  {
    mask |= settings.Widths[k] > 0.0 ? (1 << k) : 0;
  }
  if (interactive)
  {
    mask &= (1 << vtkStylizeFeatureLines::CONTOUR) | (1 << vtkStylizeFeatureLines::BOUNDARY) |
      (1 << vtkStylizeFeatureLines::CREASE);
  }
  return mask;
}
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizeFeatureStrokes::Build(
  const View& view, const Settings& settings, vtkFloatArray* linearDepth)
{
  Internals& in = *this->Internal;
  in.Size[0] = std::max(1, view.Size[0]);
  in.Size[1] = std::max(1, view.Size[1]);
  const int mask = KindMask(settings, view.Interactive);
  vtkCamera* camera = view.Renderer ? view.Renderer->GetActiveCamera() : nullptr;
  const std::vector<Item> items =
    camera && mask ? SurfacesOf(view.Renderer) : std::vector<Item>();
  if (linearDepth)
  {
    in.Depth->SetDimensions(in.Size[0], in.Size[1], 1);
    in.Depth->GetPointData()->SetScalars(linearDepth);
    in.Depth->Modified();
  }
  StrokeSink sink(view, settings, camera);
  for (auto& entry : in.Cache)
  {
    entry.second->Seen = false;
  }
  for (const Item& item : items)
  {
    std::unique_ptr<Surface>& s = in.Cache[item.Data];
    if (!s || s->Data.GetPointer() != item.Data)
    {
      s.reset(new Surface);
      s->Data = item.Data;
      s->Lines->SetInputData(item.Data);
      s->Visibility->SetInputConnection(s->Lines->GetOutputPort());
      s->Visibility->VisibleOnlyOn();
      s->Visibility->SetDepthKind(vtkStylizeLineVisibility::VIEW_DEPTH);
    }
    s->Seen = true;
    vtkStylizeFeatureLines* fl = s->Lines;
    fl->SetKindMask(mask);
    fl->SetCreaseAngle(settings.CreaseAngle);
    fl->SetRidgeThreshold(settings.RidgeThreshold);
    fl->SetSuggestiveThreshold(settings.SuggestiveThreshold);
    fl->SetCamera(camera);
    fl->SetModelMatrix(item.Matrix);
    this->SetVisibility(s->Visibility, item.Data, item.Matrix, view, linearDepth != nullptr);
    if (!linearDepth)
    {
      for (const Item& other : items)
      {
        s->Visibility->AddOccluder(other.Data, other.Matrix);
      }
    }
    s->Visibility->Update();
    sink.Append(s->Visibility->GetOutput(), item.Matrix);
  }
  for (auto it = in.Cache.begin(); it != in.Cache.end();)
  {
    it = it->second->Seen ? std::next(it) : in.Cache.erase(it);
  }
  in.Depth->GetPointData()->SetScalars(nullptr);
  return sink.Finish(in.Strokes);
}

//------------------------------------------------------------------------------
void vtkStylizeFeatureStrokes::SetVisibility(vtkStylizeLineVisibility* vis, vtkPolyData* data,
  vtkMatrix4x4* matrix, const View& view, bool depthBuffer)
{
  Internals& in = *this->Internal;
  Surface& s = *in.Cache[data];
  if (s.EdgeTime < data->GetMTime())
  {
    s.MeanEdge = MeanEdgeLength(data);
    s.EdgeTime = data->GetMTime();
  }
  // A contour interpolated inside a coarse mesh's triangles lies up to about an edge behind
  // the polygons that draw its silhouette (the ray-cast reference starts an edge away too).
  vis->SetWorldTolerance(s.MeanEdge * ScaleOf(matrix));
  vis->SetCamera(view.Renderer->GetActiveCamera());
  vis->SetModelMatrix(matrix);
  vis->SetViewportSize(in.Size);
  vis->SetImageSize(view.FullSize[0], view.FullSize[1]);
  vis->SetImageOffset(view.FullOffset[0], view.FullOffset[1]);
  vis->RemoveAllOccluders();
  vis->SetMethod(
    depthBuffer ? vtkStylizeLineVisibility::DEPTH_BUFFER : vtkStylizeLineVisibility::RAY_CAST);
  vis->SetDepthImage(depthBuffer ? in.Depth.GetPointer() : nullptr);
}

//------------------------------------------------------------------------------
void vtkStylizeFeatureStrokes::Rasterize(std::vector<float>& coverage)
{
  Internals& in = *this->Internal;
  const int W = in.Size[0], H = in.Size[1];
  coverage.assign(static_cast<size_t>(W) * H, 0.0f);
  vtkPolyData* strokes = in.Strokes;
  vtkPoints* points = strokes->GetPoints();
  vtkDataArray* widths = strokes->GetPointData()->GetArray("StrokeWidth");
  if (!points || !widths)
  {
    return;
  }
  vtkCellArray* cells = strokes->GetLines();
  vtkIdType n;
  const vtkIdType* ids;
  for (cells->InitTraversal(); cells->GetNextCell(n, ids);)
  {
    for (vtkIdType s = 0; s + 1 < n; ++s)
    {
      double a[3], b[3];
      points->GetPoint(ids[s], a);
      points->GetPoint(ids[s + 1], b);
      const double ra = 0.5 * widths->GetTuple1(ids[s]);
      const double rb = 0.5 * widths->GetTuple1(ids[s + 1]);
      const double reach = std::max(ra, rb) + 1.0;
      const int x0 = std::max(0, static_cast<int>(std::floor(std::min(a[0], b[0]) - reach)));
      const int x1 = std::min(W - 1, static_cast<int>(std::ceil(std::max(a[0], b[0]) + reach)));
      const int y0 = std::max(0, static_cast<int>(std::floor(std::min(a[1], b[1]) - reach)));
      const int y1 = std::min(H - 1, static_cast<int>(std::ceil(std::max(a[1], b[1]) + reach)));
      const double dx = b[0] - a[0], dy = b[1] - a[1];
      const double len2 = dx * dx + dy * dy;
      for (int y = y0; y <= y1; ++y)
      {
        for (int x = x0; x <= x1; ++x)
        {
          const double px = x + 0.5 - a[0], py = y + 0.5 - a[1];
          const double t =
            len2 > 0.0 ? std::min(1.0, std::max(0.0, (px * dx + py * dy) / len2)) : 0.0;
          const double d = std::hypot(px - t * dx, py - t * dy);
          const double r = ra + t * (rb - ra);
          float& c = coverage[static_cast<size_t>(y) * W + x];
          c = std::max(c, Coverage(d, r));
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeFeatureStrokes::Upload(vtkOpenGLRenderWindow* window)
{
  Internals& in = *this->Internal;
  this->Rasterize(in.Coverage);
  if (!in.Texture)
  {
    in.Texture = vtkTextureObject::New();
  }
  in.Texture->SetContext(window);
  in.Texture->SetMinificationFilter(vtkTextureObject::Nearest);
  in.Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  in.Texture->SetWrapS(vtkTextureObject::ClampToEdge);
  in.Texture->SetWrapT(vtkTextureObject::ClampToEdge);
  in.Texture->Create2DFromRaw(static_cast<unsigned int>(in.Size[0]),
    static_cast<unsigned int>(in.Size[1]), 1, VTK_FLOAT, in.Coverage.data());
  return in.Texture;
}

//------------------------------------------------------------------------------
void vtkStylizeFeatureStrokes::Free(vtkWindow* w)
{
  if (this->Internal->Texture)
  {
    if (w)
    {
      this->Internal->Texture->ReleaseGraphicsResources(w);
    }
    this->Internal->Texture->Delete();
    this->Internal->Texture = nullptr;
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizeFeatureStrokes::GetTextureBytes()
{
  const vtkTextureObject* t = this->Internal->Texture;
  return t ? static_cast<vtkIdType>(this->Internal->Size[0]) * this->Internal->Size[1] * 4 : 0;
}
