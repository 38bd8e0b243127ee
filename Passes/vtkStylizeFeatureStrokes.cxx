#include "vtkStylizeFeatureStrokes.h"
#include "vtkStylizeFeatureStrokesScene.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkStylizeFeatureLines.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLineVisibility.h"
#include "vtkStylizeRayOccluder.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

using namespace vtkStylizeFeatureStrokesScene;

namespace
{

/**
 * Over several processes (each rendering its own pieces): the scene's bounds and each actor's
 * data bounds, over every process, so that every piece gets the thresholds and the taper the
 * whole data would; false (nothing set) when the processes do not show the same actors.
 */
bool ShareBounds(vtkMultiProcessController* c, const std::vector<vtkActor*>& actors,
  vtkStylizeFeatureStrokes::View& view)
{
  const int count = static_cast<int>(actors.size());
  int least = count, most = count;
  c->AllReduce(&count, &least, 1, vtkCommunicator::MIN_OP);
  c->AllReduce(&count, &most, 1, vtkCommunicator::MAX_OP);
  if (least != most)
  {
    return false;
  }
  // lows and highs of the scene, then of each actor's data
  std::vector<double> lo(3 * (count + 1), VTK_DOUBLE_MAX), hi(3 * (count + 1), -VTK_DOUBLE_MAX);
  auto add = [&](size_t slot, const double* b)
  {
    if (b && vtkMath::AreBoundsInitialized(b))
    {
      for (int i = 0; i < 3; ++i)
      {
        lo[3 * slot + i] = b[2 * i];
        hi[3 * slot + i] = b[2 * i + 1];
      }
    }
  };
  double scene[6];
  view.Renderer->ComputeVisiblePropBounds(scene);
  add(0, scene);
  for (size_t a = 0; a < actors.size(); ++a)
  {
    add(a + 1, actors[a]->GetMapper()->GetBounds());
  }
  std::vector<double> los(lo.size()), his(hi.size());
  c->AllReduce(lo.data(), los.data(), static_cast<vtkIdType>(lo.size()), vtkCommunicator::MIN_OP);
  c->AllReduce(hi.data(), his.data(), static_cast<vtkIdType>(hi.size()), vtkCommunicator::MAX_OP);
  auto bounds = [&](size_t slot, double* b)
  {
    for (int i = 0; i < 3; ++i)
    {
      b[2 * i] = los[3 * slot + i];
      b[2 * i + 1] = his[3 * slot + i];
    }
  };
  bounds(0, view.SceneBounds);
  view.ObjectBounds.assign(actors.size(), {});
  for (size_t a = 0; a < actors.size(); ++a)
  {
    bounds(a + 1, view.ObjectBounds[a].data());
  }
  return true;
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
  std::map<std::pair<vtkDataSet*, bool>, std::unique_ptr<Surface>> Cache;
  vtkNew<vtkPolyData> Strokes;
  vtkNew<vtkImageData> Depth;
  vtkNew<vtkFloatArray> LinearDepth;
  vtkNew<vtkFloatArray> LayerDepth; // (a translucent layer's scene depth, kept between frames)
  int Size[2] = { 0, 0 };
  vtkTextureObject* Texture = nullptr;
  std::vector<float> Coverage;
  vtkWeakPointer<vtkRenderer> LastRenderer; // of the last RenderFrame()
  /** Channels of Coverage: 1 (ink), or 2 (ink, and the iso-lines' halo) when the last
   * Build() drew iso-lines. */
  int Channels = 1;
  double PointSize = 1.0; // pixels per point of the last Build() (the halo's width)
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
  for (int k = 0; k < Kinds; ++k)
  {
    const double r = 0.5 * settings.Widths[k] * pointSize;
    widest = std::max(
      widest, k == vtkStylizeFeatureLines::ISOLINE && r > 0.0 ? HaloRadius(r, pointSize) : r);
  }
  return widest + 1.0;
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
/**
 * A figure's translucent surfaces (visible actors with translucent polygons, a volume's fog
 * included), each as a ray occluder of its opacity (its actor's, times its direct RGBA colours'
 * alpha); `reach`: the scene's diameter (how far a parallel projection's rays go).
 */
std::vector<vtkSmartPointer<vtkStylizeRayOccluder>> Veils(vtkRenderer* ren, double& reach)
{
  std::vector<vtkSmartPointer<vtkStylizeRayOccluder>> veils;
  double b[6];
  ren->ComputeVisiblePropBounds(b);
  reach = vtkMath::AreBoundsInitialized(b) ? 2.0 *
        std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
          (b[5] - b[4]) * (b[5] - b[4])) +
      1.0
                                           : 1.0;
  vtkPropCollection* props = ren->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    auto* actor = vtkActor::SafeDownCast(prop);
    vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
    auto* data = mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
    if (!data || !actor->GetVisibility() || !actor->HasTranslucentPolygonalGeometry() ||
      actor->GetProperty()->GetRepresentation() != VTK_SURFACE)
    {
      continue; // (composite and other data left out)
    }
    // the colours' alpha, where the mapper draws RGBA bytes as they are
    vtkDataArray* rgba = nullptr;
    if (mapper->GetScalarVisibility() && mapper->GetColorMode() == VTK_COLOR_MODE_DIRECT_SCALARS)
    {
      rgba = mapper->GetScalarMode() == VTK_SCALAR_MODE_USE_POINT_FIELD_DATA
        ? data->GetPointData()->GetArray(mapper->GetArrayName())
        : data->GetPointData()->GetScalars();
      rgba = rgba && rgba->GetNumberOfComponents() == 4 && rgba->GetDataType() == VTK_UNSIGNED_CHAR
        ? rgba
        : nullptr;
    }
    auto veil = vtkSmartPointer<vtkStylizeRayOccluder>::New();
    veil->SetSurface(data, actor->GetMatrix());
    veil->SetOpacity(actor->GetProperty()->GetOpacity(), rgba);
    veils.push_back(veil);
  }
  return veils;
}

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
    this->Inks->SetName("StrokeInk");
    if (!camera)
    {
      return;
    }
    camera->GetPosition(this->Eye);
    camera->GetDirectionOfProjection(this->Dop);
    this->Parallel = camera->GetParallelProjection() != 0;
    // The projection of the whole image, and the scene's depth range for the taper.
    this->Projection->DeepCopy(camera->GetCompositeProjectionTransformMatrix(
      view.ViewportSize[0] / std::max(1.0, view.ViewportSize[1]), -1.0, 1.0));
    this->ModelView->DeepCopy(camera->GetViewTransformMatrix());
    double b[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
    if (vtkMath::AreBoundsInitialized(view.SceneBounds))
    {
      std::copy(view.SceneBounds, view.SceneBounds + 6, b);
    }
    else
    {
      view.Renderer->ComputeVisiblePropBounds(b);
    }
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

  /**
   * Translucent surfaces between the lines and the eye: each stroke point's ink is then the
   * share of light they let through (StrokeInk), as a frame's translucent layers cover the lines.
   */
  void SetVeils(const std::vector<vtkSmartPointer<vtkStylizeRayOccluder>>& veils, double reach)
  {
    this->Veils = veils;
    this->Reach = reach;
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
        double x = (c[0] / w + 1.0) * 0.5 * this->V.ViewportSize[0] - this->V.ViewportOffset[0];
        double y = (c[1] / w + 1.0) * 0.5 * this->V.ViewportSize[1] - this->V.ViewportOffset[1];
        if (!std::isfinite(x) || !std::isfinite(y))
        {
          x = y = -1.0e6;
        }
        const double f = strength ? strength->GetTuple1(ids[i]) : 1.0;
        this->Lines->InsertCellPoint(this->Points->InsertNextPoint(x, y, 0.0));
        this->Widths->InsertNextValue(static_cast<float>(this->Width(kind, -e[2], f)));
        if (!this->Veils.empty())
        {
          this->Inks->InsertNextValue(static_cast<float>(this->Through(p, matrix)));
        }
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
    if (!this->Veils.empty())
    {
      out->GetPointData()->AddArray(this->Inks);
    }
    out->GetCellData()->AddArray(this->Kinds);
    return this->Lines->GetNumberOfCells();
  }

private:
  /** The share of light the veils let through from model point `p` to the eye. */
  double Through(const double p[4], vtkMatrix4x4* matrix) const
  {
    double w[4];
    matrix->MultiplyPoint(p, w);
    const double h = w[3] != 0.0 ? w[3] : 1.0;
    const double a[3] = { w[0] / h, w[1] / h, w[2] / h };
    double b[3];
    for (int r = 0; r < 3; ++r)
    {
      b[r] = this->Parallel ? a[r] - this->Reach * this->Dop[r] : this->Eye[r];
    }
    double through = 1.0;
    for (const auto& veil : this->Veils)
    {
      through *= veil->Transmittance(a, b);
    }
    return through;
  }

  /** A stroke's width in pixels at eye depth z and strength f. */
  double Width(int kind, double z, double f) const
  {
    // (a setting that is not finite counts as 0: the clamp macros let NaN through)
    auto share = [](double v) { return std::isfinite(v) ? std::min(1.0, std::max(0.0, v)) : 0.0; };
    const double depth = this->Range > 0.0 ? (z - this->Nearest) / this->Range : 0.0;
    const double taper = 1.0 - share(this->S.DepthTaper) * share(depth);
    const double strength = std::isfinite(f) ? share(f) : 1.0;
    const double fade = 1.0 - share(this->S.StrengthTaper) * (1.0 - strength);
    double w = this->S.Widths[kind] * this->V.PointSize * taper * fade;
    w = w > 0.0 ? std::max(w, this->V.MinimumWidth) : w;
    return std::isfinite(w) ? std::min(1.0e4, std::max(0.0, w)) : 0.0;
  }

  const View& V;
  const Settings& S;
  vtkNew<vtkMatrix4x4> Projection, ModelView;
  double Nearest = 0.0, Range = 0.0;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Lines;
  vtkNew<vtkFloatArray> Widths;
  vtkNew<vtkUnsignedCharArray> Kinds;
  vtkNew<vtkFloatArray> Inks;
  std::vector<vtkSmartPointer<vtkStylizeRayOccluder>> Veils;
  double Eye[3] = { 0.0, 0.0, 0.0 }, Dop[3] = { 0.0, 0.0, -1.0 };
  bool Parallel = false;
  double Reach = 1.0; // (a parallel projection's rays: this far towards the viewer)
};

/**
 * Sets up the visibility of a surface's lines for this frame: against `depth` (the scene's
 * linear depth, `size` pixels), or by ray casting when it is null.
 */
void SetVisibility(Surface& s, vtkMatrix4x4* matrix, const vtkStylizeFeatureStrokes::View& view,
  const int size[2], vtkImageData* depth)
{
  vtkStylizeLineVisibility* vis = s.Visibility;
  vtkPolyData* surface = s.SurfaceOf();
  if (s.EdgeTime < surface->GetMTime())
  {
    s.MeanEdge = MeanEdgeLength(surface);
    s.EdgeTime = surface->GetMTime();
  }
  // A contour interpolated inside a coarse mesh's triangles lies up to about an edge behind
  // the polygons that draw its silhouette (the ray-cast reference starts an edge away too).
  vis->SetWorldTolerance(s.MeanEdge * ScaleOf(matrix));
  vis->SetCamera(view.Renderer->GetActiveCamera());
  vis->SetModelMatrix(matrix);
  vis->SetViewportSize(size);
  vis->SetImageSize(view.ViewportSize[0], view.ViewportSize[1]);
  vis->SetImageOffset(view.ViewportOffset[0], view.ViewportOffset[1]);
  vis->RemoveAllOccluders();
  vis->SetMethod(
    depth ? vtkStylizeLineVisibility::DEPTH_BUFFER : vtkStylizeLineVisibility::RAY_CAST);
  vis->SetDepthImage(depth);
}

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
      (1 << vtkStylizeFeatureLines::CREASE) | (1 << vtkStylizeFeatureLines::ISOLINE);
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
  in.PointSize = view.PointSize;
  in.Size[1] = std::max(1, view.Size[1]);
  in.Channels =
    settings.IsoLines > 0 && settings.Widths[vtkStylizeFeatureLines::ISOLINE] > 0.0 ? 2 : 1;
  const int mask = KindMask(settings, view.Interactive);
  vtkCamera* camera = view.Renderer ? view.Renderer->GetActiveCamera() : nullptr;
  const std::vector<vtkActor*> actors =
    camera && mask ? LineActors(view.Renderer, settings.Translucent) : std::vector<vtkActor*>();
  const std::vector<Item> items = SurfacesOf(actors, view);
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
    std::unique_ptr<Surface>& s = in.Cache[{ item.Data, item.Wireframe }];
    if (!s || s->Data.GetPointer() != item.Data)
    {
      s.reset(new Surface(item.Data, item.Wireframe));
    }
    s->Seen = true;
  }
  // Ray casting: one locator per occluding surface, built once and queried by every surface's
  // visibility (a locator per pair of surfaces was quadratic in their number). Translucent
  // surfaces' lines are hidden by the opaque surfaces alone (the translucent ones are seen
  // through).
  std::vector<Item> occluding;
  if (!linearDepth)
  {
    occluding = settings.Translucent && !items.empty()
      ? SurfacesOf(LineActors(view.Renderer), View())
      : items;
  }
  std::vector<vtkSmartPointer<vtkStylizeRayOccluder>> occluders;
  for (const Item& other : occluding)
  {
    std::unique_ptr<Surface>& s = in.Cache[{ other.Data, other.Wireframe }];
    if (!s || s->Data.GetPointer() != other.Data)
    {
      s.reset(new Surface(other.Data, other.Wireframe));
    }
    if (!other.Wireframe)
    {
      occluders.push_back(vtkSmartPointer<vtkStylizeRayOccluder>::New());
      occluders.back()->SetSurface(s->SurfaceOf(), other.Matrix);
    }
  }
  if (!linearDepth && !settings.Translucent && !items.empty())
  {
    double reach = 1.0;
    sink.SetVeils(Veils(view.Renderer, reach), reach);
  }
  // Each surface's lines report their progress as this object's (ProgressEvent, over all the
  // surfaces): the line art's first frame of a large mesh takes seconds.
  struct Progress
  {
    vtkObject* Self;
    size_t Done, Count; // surfaces done, surfaces
    static void Call(vtkObject*, unsigned long, void* self, void* data)
    {
      const auto* p = static_cast<Progress*>(self);
      double fraction =
        std::min((static_cast<double>(p->Done) + *static_cast<double*>(data)) / p->Count, 0.999);
      p->Self->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
    }
  } progress{ this, 0, std::max<size_t>(1, items.size()) };
  vtkNew<vtkCallbackCommand> forward;
  forward->SetClientData(&progress);
  forward->SetCallback(&Progress::Call);
  for (const Item& item : items)
  {
    Surface& s = *in.Cache[{ item.Data, item.Wireframe }];
    if (item.Wireframe)
    {
      s.UpdateEdges();
    }
    vtkStylizeFeatureLines* fl = s.Lines;
    fl->SetKindMask(mask);
    fl->SetCreaseAngle(settings.CreaseAngle);
    fl->SetRidgeThreshold(settings.RidgeThreshold);
    fl->SetSuggestiveThreshold(settings.SuggestiveThreshold);
    SetIsoLines(fl, actors[item.Actor], item.Data, settings);
    fl->SetCamera(camera);
    fl->SetModelMatrix(item.Matrix);
    const double invalid[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
    fl->SetObjectBounds(
      item.Actor < view.ObjectBounds.size() ? view.ObjectBounds[item.Actor].data() : invalid);
    SetVisibility(s, item.Matrix, view, in.Size, linearDepth ? in.Depth.GetPointer() : nullptr);
    for (const auto& occluder : occluders)
    {
      s.Visibility->AddSharedOccluder(occluder);
    }
    const unsigned long tag = s.Lines->AddObserver(vtkCommand::ProgressEvent, forward);
    s.Visibility->Update();
    s.Lines->RemoveObserver(tag);
    ++progress.Done;
    sink.Append(s.Visibility->GetOutput(), item.Matrix);
  }
  double done = 1.0; // (also when every surface's lines were kept: no event above)
  this->InvokeEvent(vtkCommand::ProgressEvent, &done);
  // A surface is dropped when its data is gone, or once 8 still frames in a row did not draw it.
  // ParaView's interactive frames draw a decimated copy (LOD) of large data and its still frames
  // the full geometry, with still frames of their own between drags: each kind of frame keeps
  // the other's surface (dropping the full one rebuilt its welded mesh and curvature at every
  // still frame after a drag, the decimated one at a drag's first frame).
  for (auto it = in.Cache.begin(); it != in.Cache.end();)
  {
    Surface& s = *it->second;
    s.UnseenStills = s.Seen ? 0 : s.UnseenStills + (view.Interactive ? 0 : 1);
    const bool keep = s.Data && s.UnseenStills < 8;
    it = keep ? std::next(it) : in.Cache.erase(it);
  }
  in.Depth->GetPointData()->SetScalars(nullptr);
  return sink.Finish(in.Strokes);
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizeFeatureStrokes::BuildFigure(
  const View& view, const Settings& settings, vtkMultiProcessController* c)
{
  if (!c || c->GetNumberOfProcesses() < 2)
  {
    return this->Build(view, settings, nullptr);
  }
  // Every process shows the same actors (ParaView's representations), each its own pieces.
  const std::vector<vtkActor*> actors =
    view.Renderer ? LineActors(view.Renderer) : std::vector<vtkActor*>();
  const int count = static_cast<int>(actors.size());
  int least = count, most = count;
  c->AllReduce(&count, &least, 1, vtkCommunicator::MIN_OP);
  c->AllReduce(&count, &most, 1, vtkCommunicator::MAX_OP);
  if (least != most)
  {
    vtkWarningMacro("the processes show different actors: the figure's lines are process 0's");
    return c->GetLocalProcessId() == 0 ? this->Build(view, settings, nullptr)
                                       : (this->Internal->Strokes->Initialize(), 0);
  }
  constexpr int tag = 95317;
  const int rank = c->GetLocalProcessId();
  std::vector<vtkSmartPointer<vtkPolyData>> local;
  for (vtkActor* actor : actors)
  {
    local.push_back(PolygonsOf(actor->GetMapper()->GetInputDataObject(0, 0)));
  }
  if (rank != 0)
  {
    for (const auto& piece : local)
    {
      c->Send(piece, 0, tag);
    }
    this->Internal->Strokes->Initialize();
    return 0;
  }
  View whole = view;
  whole.Surfaces.assign(actors.size(), nullptr);
  for (size_t a = 0; a < actors.size(); ++a)
  {
    vtkNew<vtkAppendPolyData> append;
    append->AddInputData(local[a]);
    for (int r = 1; r < c->GetNumberOfProcesses(); ++r)
    {
      auto piece = vtkSmartPointer<vtkPolyData>::New();
      c->Receive(piece, r, tag);
      append->AddInputData(piece);
    }
    // (the points the pieces share at a cut are copies with the same coordinates: merged, the
    // cut is no boundary)
    vtkNew<vtkCleanPolyData> merge;
    merge->SetInputConnection(append->GetOutputPort());
    merge->SetTolerance(0.0);
    merge->ConvertLinesToPointsOff();
    merge->ConvertPolysToLinesOff();
    merge->ConvertStripsToPolysOff();
    merge->Update();
    auto joined = vtkSmartPointer<vtkPolyData>::New();
    joined->ShallowCopy(merge->GetOutput());
    whole.Surfaces[a] = joined;
  }
  // (the Surfaces are the whole data: their own bounds are the objects')
  whole.ObjectBounds.clear();
  const vtkIdType strokes = this->Build(whole, settings, nullptr);
  // The joined surfaces are this figure's only: the frames' cache keeps the pieces.
  for (const auto& surface : whole.Surfaces)
  {
    this->Internal->Cache.erase({ surface.GetPointer(), false });
    this->Internal->Cache.erase({ surface.GetPointer(), true });
  }
  return strokes;
}

//------------------------------------------------------------------------------
vtkRenderer* vtkStylizeFeatureStrokes::GetLastRenderer()
{
  return this->Internal->LastRenderer;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkStylizeFeatureStrokes::RenderFigure(vtkStylizeStylePass* style,
  vtkRenderer* renderer, const Settings& settings, int width, int height, int tiles)
{
  View view;
  view.Renderer = renderer;
  view.Size[0] = std::max(1, width);
  view.Size[1] = std::max(1, height);
  view.ViewportSize[0] = view.Size[0];
  view.ViewportSize[1] = view.Size[1];
  view.PointSize = style->GetPixelsPerPoint(view.Size[1], tiles);
  // the frame's strokes replaced: the lines of the same camera are kept per surface (on several
  // processes, collective: the whole data's lines on process 0)
  style->AddVolumeSurfaces(renderer);
  this->BuildFigure(view, settings, style->GetGBufferPass()->GetController());
  style->RemoveVolumeSurfaces();
  return this->GetStrokes();
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeFeatureStrokes::RenderFrame(
  vtkStylizeStylePass* style, const vtkStylizeStylePass::Frame& frame, const Settings& settings)
{
  View view;
  view.Renderer = frame.Renderer;
  this->Internal->LastRenderer = frame.Renderer;
  view.Size[0] = frame.Size[0];
  view.Size[1] = frame.Size[1];
  // The camera projects onto the viewport (a tile: VTK narrows the camera to it), which the
  // guard transform places in the frame's pixels: ndc' = s ndc + t.
  for (int a = 0; a < 2; ++a)
  {
    const double scale = frame.GuardTransform[a], shift = frame.GuardTransform[a + 2];
    view.ViewportSize[a] = scale * frame.Size[a];
    view.ViewportOffset[a] = -0.5 * (shift + 1.0 - scale) * frame.Size[a];
  }
  view.PointSize = style->PointSize(frame);
  view.Interactive = frame.Interactive;
  // A stroke is never thinner than a pixel of the picture (the hairline rule of PostScript and
  // PDF renderers): thinner, its anti-aliased ink breaks into faint dashes as it crosses the
  // pixel rows, and a small view's far outline (points of a 1080-line picture, tapered with
  // depth) vanishes.
  view.MinimumWidth = 1.0;
  Internals& in = *this->Internal;
  vtkFloatArray* depth = in.LinearDepth;
  bool haveDepth =
    style->GetGBufferPass()->DownloadChannel(vtkStylizeGBufferPass::LINEAR_DEPTH_BUFFER, depth);
  if (haveDepth && settings.Translucent && style->GetSceneGBufferPass() != style->GetGBufferPass())
  {
    // A translucent layer's lines are hidden by the layer's surface and by the opaque scene
    // where the layer has none (a depth of 0).
    vtkFloatArray* layer = in.LayerDepth;
    if (style->GetSceneGBufferPass()->DownloadChannel(
          vtkStylizeGBufferPass::LINEAR_DEPTH_BUFFER, layer) &&
      layer->GetNumberOfTuples() == depth->GetNumberOfTuples())
    {
      float* d = depth->GetPointer(0);
      const float* l = layer->GetPointer(0);
      for (vtkIdType i = 0; i < depth->GetNumberOfTuples(); ++i)
      {
        d[i] = l[i] > 0.0f && (d[i] <= 0.0f || l[i] < d[i]) ? l[i] : d[i];
      }
    }
  }
  // Several processes, each with its own pieces: process 0 holds the composited depth, which
  // every process tests its lines against; their ink is combined on process 0.
  vtkMultiProcessController* c = style->GetGBufferPass()->GetController();
  const bool ranks = c && c->GetNumberOfProcesses() > 1;
  if (ranks)
  {
    const vtkIdType pixels = static_cast<vtkIdType>(frame.Size[0]) * frame.Size[1];
    if (!haveDepth || depth->GetNumberOfTuples() != pixels)
    {
      depth->SetNumberOfComponents(1);
      depth->SetNumberOfTuples(pixels);
      depth->Fill(0.0);
    }
    c->Broadcast(depth->GetPointer(0), pixels, 0);
    haveDepth = true;
    ShareBounds(c, LineActors(frame.Renderer, settings.Translucent), view);
  }
  this->Build(view, settings, haveDepth ? depth : nullptr);
  this->Rasterize(in.Coverage);
  if (ranks)
  {
    std::vector<float> combined(in.Coverage.size(), 0.0f);
    c->Reduce(in.Coverage.data(), combined.data(), static_cast<vtkIdType>(combined.size()),
      vtkCommunicator::MAX_OP, 0);
    if (c->GetLocalProcessId() == 0)
    {
      in.Coverage.swap(combined);
    }
  }
  return this->UploadCoverage(frame.Window);
}

//------------------------------------------------------------------------------
void vtkStylizeFeatureStrokes::Rasterize(std::vector<float>& coverage)
{
  Internals& in = *this->Internal;
  const int W = in.Size[0], H = in.Size[1], C = in.Channels;
  coverage.assign(static_cast<size_t>(W) * H * C, 0.0f);
  vtkPolyData* strokes = in.Strokes;
  vtkPoints* points = strokes->GetPoints();
  vtkDataArray* widths = strokes->GetPointData()->GetArray("StrokeWidth");
  vtkDataArray* kinds = strokes->GetCellData()->GetArray("FeatureKind");
  if (!points || !widths)
  {
    return;
  }
  vtkCellArray* cells = strokes->GetLines();
  vtkIdType n, cell = 0;
  const vtkIdType* ids;
  for (cells->InitTraversal(); cells->GetNextCell(n, ids); ++cell)
  {
    // An iso-line clears a halo beside it (HaloRadius()) in the second channel.
    const bool halo = C == 2 && kinds && cell < kinds->GetNumberOfTuples() &&
      static_cast<int>(kinds->GetTuple1(cell)) == vtkStylizeFeatureLines::ISOLINE;
    for (vtkIdType s = 0; s + 1 < n; ++s)
    {
      double a[3], b[3];
      points->GetPoint(ids[s], a);
      points->GetPoint(ids[s + 1], b);
      const double ra = 0.5 * widths->GetTuple1(ids[s]);
      const double rb = 0.5 * widths->GetTuple1(ids[s + 1]);
      const double reach =
        (halo ? HaloRadius(std::max(ra, rb), in.PointSize) : std::max(ra, rb)) + 1.0;
      if (!std::isfinite(a[0] + a[1] + b[0] + b[1] + reach) ||
        std::max(std::abs(a[0]), std::abs(b[0])) > 1.0e7 ||
        std::max(std::abs(a[1]), std::abs(b[1])) > 1.0e7)
      {
        continue; // (off-screen or degenerate: nothing to draw, and no cast out of range)
      }
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
          float* c = &coverage[(static_cast<size_t>(y) * W + x) * C];
          c[0] = std::max(c[0], Coverage(d, r));
          if (halo)
          {
            c[1] = std::max(c[1], Coverage(d, HaloRadius(r, in.PointSize)));
          }
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeFeatureStrokes::Upload(vtkOpenGLRenderWindow* window)
{
  this->Rasterize(this->Internal->Coverage);
  return this->UploadCoverage(window);
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeFeatureStrokes::UploadCoverage(vtkOpenGLRenderWindow* window)
{
  Internals& in = *this->Internal;
  if (!in.Texture)
  {
    in.Texture = vtkTextureObject::New();
  }
  in.Texture->SetContext(window);
  if (in.Texture->GetComponents() != in.Channels)
  {
    // (vtkTextureObject keeps the format of its first upload: one channel's read the interleaved
    // two as a picture twice the size)
    in.Texture->ResetFormatAndType();
  }
  in.Texture->SetMinificationFilter(vtkTextureObject::Nearest);
  in.Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  in.Texture->SetWrapS(vtkTextureObject::ClampToEdge);
  in.Texture->SetWrapT(vtkTextureObject::ClampToEdge);
  in.Texture->Create2DFromRaw(static_cast<unsigned int>(in.Size[0]),
    static_cast<unsigned int>(in.Size[1]), in.Channels, VTK_FLOAT, in.Coverage.data());
  return in.Texture;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeFeatureStrokes::GetTexture()
{
  return this->Internal->Texture;
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
  return t ? static_cast<vtkIdType>(this->Internal->Size[0]) * this->Internal->Size[1] * 4 *
      this->Internal->Channels
           : 0;
}
