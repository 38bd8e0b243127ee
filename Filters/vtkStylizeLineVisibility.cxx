#include "vtkStylizeLineVisibility.h"
#include "vtkStylizeRayOccluder.h"

#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkStylizeLineVisibility);
vtkCxxSetObjectMacro(vtkStylizeLineVisibility, DepthImage, vtkImageData);

struct vtkStylizeLineVisibility::Internals
{
  struct Occluder
  {
    vtkSmartPointer<vtkPolyData> Surface;
    vtkSmartPointer<vtkMatrix4x4> Matrix;
  };
  std::vector<Occluder> Occluders;
  std::vector<vtkSmartPointer<vtkStylizeRayOccluder>> Shared; // (built, shared)
};

namespace
{
/** The view's projection and the visibility test of one point (in the lines' coordinates). */
class Tester
{
public:
  /**
   * `size`: the depth image's pixels; `full`, `offset`: the whole image's size and the depth
   * image's lower-left corner in it (a tile of a larger image; `size` and 0 otherwise).
   */
  Tester(vtkCamera* camera, vtkMatrix4x4* model, const int size[2], const double full[2],
    const double offset[2])
    : Width(size[0])
    , Height(size[1])
    , FullWidth(full[0])
    , FullHeight(full[1])
    , OffsetX(offset[0])
    , OffsetY(offset[1])
  {
    vtkNew<vtkMatrix4x4> toWorld;
    if (model)
    {
      toWorld->DeepCopy(model);
    }
    vtkMatrix4x4* projection =
      camera->GetCompositeProjectionTransformMatrix(full[0] / full[1], -1.0, 1.0);
    vtkMatrix4x4::Multiply4x4(projection, toWorld, this->ToClip);
    this->ToWorld->DeepCopy(toWorld);
    this->Parallel = camera->GetParallelProjection() != 0;
    camera->GetClippingRange(this->Near, this->Far);
    camera->GetPosition(this->Eye);
    camera->GetDirectionOfProjection(this->Direction);
    this->TanHalf = std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0);
    this->ParallelScale = camera->GetParallelScale();
  }

  /** Window coordinates (pixels, and depth in [0, 1]) of p; false behind the viewer. */
  bool Project(const double p[3], double win[3]) const
  {
    const double in[4] = { p[0], p[1], p[2], 1.0 };
    double c[4];
    this->ToClip->MultiplyPoint(in, c);
    if (!(c[3] > 0.0))
    {
      return false;
    }
    win[0] = (c[0] / c[3] + 1.0) * 0.5 * this->FullWidth - this->OffsetX;
    win[1] = (c[1] / c[3] + 1.0) * 0.5 * this->FullHeight - this->OffsetY;
    win[2] = (c[2] / c[3] + 1.0) * 0.5;
    return std::isfinite(win[0] + win[1] + win[2]);
  }

  /** The distance along the view axis of window depth d. */
  double EyeDepth(double d) const
  {
    if (this->Parallel)
    {
      return this->Near + d * (this->Far - this->Near);
    }
    const double z = 2.0 * d - 1.0;
    return 2.0 * this->Near * this->Far / ((this->Far + this->Near) - z * (this->Far - this->Near));
  }

  /** The size of a pixel at eye depth z. */
  double PixelSize(double z) const
  {
    return this->Parallel ? 2.0 * this->ParallelScale / this->FullHeight
                          : 2.0 * z * this->TanHalf / this->FullHeight;
  }

  /** Whether window position win lies in the viewport and between the clipping planes. */
  bool InView(const double win[3]) const
  {
    return win[0] >= 0.0 && win[0] < this->Width && win[1] >= 0.0 && win[1] < this->Height &&
      win[2] >= 0.0 && win[2] <= 1.0;
  }

  void ToWorldPoint(const double p[3], double w[3]) const
  {
    const double in[4] = { p[0], p[1], p[2], 1.0 };
    double out[4];
    this->ToWorld->MultiplyPoint(in, out);
    for (int i = 0; i < 3; ++i)
    {
      w[i] = out[i] / out[3];
    }
  }

  vtkNew<vtkMatrix4x4> ToClip, ToWorld;
  int Width, Height;
  double FullWidth, FullHeight, OffsetX, OffsetY;
  bool Parallel = false;
  double Near = 0.1, Far = 1.0, TanHalf = 1.0, ParallelScale = 1.0;
  double Eye[3], Direction[3];
};

/** DEPTH_BUFFER: a sample against the farthest depth of the pixels within a pixel of it. */
class DepthTest
{
public:
  DepthTest(const Tester& view, double tolerance, double worldTolerance, bool viewDepth)
    : View(view)
    , Tolerance(tolerance)
    , WorldTolerance(worldTolerance)
    , ViewDepth(viewDepth)
  {
  }

  /** The depth image, if it is float, one component, the viewport's size. */
  bool SetImage(vtkImageData* image)
  {
    vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
    int dims[3] = { 0, 0, 0 };
    if (image)
    {
      image->GetDimensions(dims);
    }
    if (!scalars || scalars->GetDataType() != VTK_FLOAT || dims[0] != this->View.Width ||
      dims[1] != this->View.Height || scalars->GetNumberOfComponents() != 1 ||
      scalars->GetNumberOfTuples() < static_cast<vtkIdType>(dims[0]) * dims[1])
    {
      return false;
    }
    this->Depth = static_cast<const float*>(scalars->GetVoidPointer(0));
    return true;
  }

  /**
   * Whether a sample at window position win (in the view) is visible; `contour`: the sample is
   * on an occluding contour, which gets the WorldTolerance too.
   */
  bool Visible(const double win[3], bool contour) const
  {
    const int w = this->View.Width, h = this->View.Height;
    const int i0 = std::max(0, static_cast<int>(std::ceil(win[0] - 1.5)));
    const int i1 = std::min(w - 1, static_cast<int>(std::floor(win[0] + 0.5)));
    const int j0 = std::max(0, static_cast<int>(std::ceil(win[1] - 1.5)));
    const int j1 = std::min(h - 1, static_cast<int>(std::floor(win[1] + 0.5)));
    double farthest = 0.0;
    for (int j = j0; j <= j1; ++j)
    {
      for (int i = i0; i <= i1; ++i)
      {
        const double d = this->Depth[static_cast<size_t>(j) * w + i];
        // background: window depth 1, view depth 0 (or not finite)
        if (this->ViewDepth ? !(d > 0.0 && d < VTK_DOUBLE_MAX) : !(d < 1.0))
        {
          return true; // background next to the sample
        }
        farthest = std::max(farthest, d);
      }
    }
    const double z = this->View.EyeDepth(win[2]);
    const double occluder = this->ViewDepth ? farthest : this->View.EyeDepth(farthest);
    const double world = contour ? this->WorldTolerance : 0.0;
    return occluder >= z - std::max(world, this->Tolerance * this->View.PixelSize(z));
  }

  /**
   * Whether a sample of a boundary at window position win, the boundary running along screen
   * direction (dx, dy), lies inside the surface: the depth two pixels to each side of it is a
   * surface within tolerance of the sample's (the seam between two pieces of one surface, not
   * an edge of the object).
   */
  bool Seam(const double win[3], double dx, double dy) const
  {
    const double len = std::hypot(dx, dy);
    if (!(len > 0.0))
    {
      return false;
    }
    const double nx = -dy / len, ny = dx / len;
    const double z = this->View.EyeDepth(win[2]);
    const double tolerance =
      std::max(this->WorldTolerance, 2.0 * this->Tolerance * this->View.PixelSize(z));
    for (double side : { -2.0, 2.0 })
    {
      const int i = static_cast<int>(std::floor(win[0] + side * nx));
      const int j = static_cast<int>(std::floor(win[1] + side * ny));
      if (i < 0 || j < 0 || i >= this->View.Width || j >= this->View.Height)
      {
        return false;
      }
      const double d = this->Depth[static_cast<size_t>(j) * this->View.Width + i];
      if (this->ViewDepth ? !(d > 0.0 && d < VTK_DOUBLE_MAX) : !(d < 1.0))
      {
        return false; // background on that side: the object's edge
      }
      const double there = this->ViewDepth ? d : this->View.EyeDepth(d);
      if (std::abs(there - z) > tolerance)
      {
        return false;
      }
    }
    return true;
  }

private:
  const Tester& View;
  double Tolerance;
  double WorldTolerance;
  bool ViewDepth;
  const float* Depth = nullptr;
};

/** RAY_CAST: a ray from the sample toward the viewer against the occluders. */
class RayCast
{
public:
  explicit RayCast(const Tester& view)
    : View(view)
  {
  }

  /** An occluder, in world coordinates through its matrix (may be null): built here. */
  void AddOccluder(vtkPolyData* surface, vtkMatrix4x4* matrix)
  {
    vtkNew<vtkStylizeRayOccluder> occluder;
    occluder->SetSurface(surface, matrix);
    this->Add(occluder);
  }

  /** A built occluder, shared with its other users (it is only read). */
  void Add(vtkStylizeRayOccluder* occluder)
  {
    if (!occluder || occluder->GetNumberOfTriangles() == 0)
    {
      return;
    }
    double bounds[6];
    occluder->GetBounds(bounds);
    this->Box.AddBounds(bounds);
    // (the mean edge over the occluders, each weighted by its sampled edges, at most 30000)
    const double samples =
      3.0 * static_cast<double>(std::min<vtkIdType>(occluder->GetNumberOfTriangles(), 10000));
    this->EdgeSum += occluder->GetMeanEdgeLength() * samples;
    this->EdgeCount += samples;
    this->Occluders.push_back(occluder);
  }

  /** Whether a sample p (window position win) of a contour or another line sees the viewer. */
  bool Visible(const double p[3], const double win[3], bool contour) const
  {
    const double size = this->Box.IsValid() ? this->Box.GetDiagonalLength() : 0.0;
    // The ray starts 3 pixel widths from the sample, a contour's one mean edge length (if
    // longer): a contour's ray grazes its own surface, whose polygons lie up to about half an
    // edge off the interpolated contour. The other lines lie on their polygons (as the depth
    // test's tolerance, which is a pixel's but a contour's): an edge's start let a line behind a
    // thin wall's rim show through it.
    const double edge = contour && this->EdgeCount > 0 ? this->EdgeSum / this->EdgeCount : 0.0;
    const double start = std::max(edge, 3.0 * this->View.PixelSize(this->View.EyeDepth(win[2])));
    double from[3], to[3], dir[3];
    this->View.ToWorldPoint(p, from);
    double length = 4.0 * size;
    if (this->View.Parallel)
    {
      dir[0] = -this->View.Direction[0];
      dir[1] = -this->View.Direction[1];
      dir[2] = -this->View.Direction[2];
    }
    else
    {
      vtkMath::Subtract(this->View.Eye, from, dir);
      length = vtkMath::Norm(dir);
    }
    if (vtkMath::Normalize(dir) == 0.0 || start >= length)
    {
      return true;
    }
    for (int i = 0; i < 3; ++i)
    {
      to[i] = from[i] + length * dir[i];
      from[i] += start * dir[i];
    }
    for (const auto& occluder : this->Occluders)
    {
      if (occluder->Blocks(from, to))
      {
        return false;
      }
    }
    return true;
  }

private:
  const Tester& View;
  std::vector<vtkSmartPointer<vtkStylizeRayOccluder>> Occluders;
  vtkBoundingBox Box;
  double EdgeSum = 0.0;
  double EdgeCount = 0.0;
};

/** Cuts the input's polylines into runs of one visibility, into the output. */
class Splitter
{
public:
  Splitter(vtkPolyData* input, vtkPolyData* output, bool visibleOnly)
    : Input(input)
    , Output(output)
    , VisibleOnly(visibleOnly)
  {
    this->Points->SetDataTypeToDouble();
    output->GetPointData()->InterpolateAllocate(input->GetPointData());
    output->GetCellData()->CopyAllocate(input->GetCellData());
    this->PointVisibility->SetName("FeatureVisibility");
    this->CellVisibility->SetName("FeatureVisibility");
  }

  /** Where a polyline's visibility changes: its first sample's, then each change. */
  struct Changes
  {
    bool First = false;
    std::vector<std::pair<vtkIdType, double>> Cuts; // (segment, parameter along it)
  };

  /**
   * The visibility along polyline `ids` (n points) sampled every `spacing` pixels of the view,
   * each change located by bisection. Reads only: polylines may be traced in parallel.
   */
  template <class Visible>
  Changes Trace(
    vtkIdType n, const vtkIdType* ids, const Tester& view, double spacing, Visible visible) const
  {
    Changes c;
    if (n < 2)
    {
      return c;
    }
    double p0[3], p1[3];
    this->Input->GetPoint(ids[0], p0);
    this->Input->GetPoint(ids[1], p1);
    bool current = visible(p0, p0, p1);
    c.First = current;
    for (vtkIdType s = 0; s + 1 < n; ++s)
    {
      const vtkIdType a = ids[s], b = ids[s + 1];
      double pa[3], pb[3], wa[3], wb[3];
      this->Input->GetPoint(a, pa);
      this->Input->GetPoint(b, pb);
      double pixels = 1.0;
      if (view.Project(pa, wa) && view.Project(pb, wb))
      {
        pixels = std::hypot(wb[0] - wa[0], wb[1] - wa[1]);
      }
      const int samples =
        static_cast<int>(std::min(1e6, std::max(1.0, std::ceil(pixels / spacing))));
      double previous = 0.0;
      for (int k = 1; k <= samples; ++k)
      {
        const double t = static_cast<double>(k) / samples;
        double p[3];
        this->At(a, b, t, p);
        const bool vis = visible(p, pa, pb);
        if (vis != current)
        {
          // The change located by bisection between the two samples.
          double lo = previous, hi = t;
          for (int i = 0; i < 4; ++i)
          {
            const double mid = 0.5 * (lo + hi);
            double q[3];
            this->At(a, b, mid, q);
            (visible(q, pa, pb) == current ? lo : hi) = mid;
          }
          c.Cuts.emplace_back(s, 0.5 * (lo + hi));
          current = vis;
        }
        previous = t;
      }
    }
    return c;
  }

  /** Polyline `cell` cut into runs at its changes, into the output. */
  void Emit(vtkIdType cell, vtkIdType n, const vtkIdType* ids, const Changes& c)
  {
    if (n < 2)
    {
      return;
    }
    bool current = c.First;
    this->Add(ids[0], ids[1], 0.0, current);
    size_t k = 0;
    for (vtkIdType s = 0; s + 1 < n; ++s)
    {
      const vtkIdType a = ids[s], b = ids[s + 1];
      for (; k < c.Cuts.size() && c.Cuts[k].first == s; ++k)
      {
        this->Add(a, b, c.Cuts[k].second, current);
        this->EndRun(cell, current);
        current = !current;
        this->Add(a, b, c.Cuts[k].second, current);
      }
      this->Add(a, b, 1.0, current);
    }
    this->EndRun(cell, current);
  }

  void Finish()
  {
    this->Output->SetPoints(this->Points);
    this->Output->SetLines(this->Lines);
    this->Output->GetPointData()->AddArray(this->PointVisibility);
    this->Output->GetCellData()->AddArray(this->CellVisibility);
    this->Output->Squeeze();
  }

private:
  void At(vtkIdType a, vtkIdType b, double t, double p[3]) const
  {
    double pa[3], pb[3];
    this->Input->GetPoint(a, pa);
    this->Input->GetPoint(b, pb);
    for (int i = 0; i < 3; ++i)
    {
      p[i] = pa[i] + t * (pb[i] - pa[i]);
    }
  }

  void Add(vtkIdType a, vtkIdType b, double t, bool visible)
  {
    double p[3];
    this->At(a, b, t, p);
    const vtkIdType id = this->Points->InsertNextPoint(p);
    this->Output->GetPointData()->InterpolateEdge(this->Input->GetPointData(), id, a, b, t);
    this->PointVisibility->InsertNextValue(visible ? 1 : 0);
    this->Run.push_back(id);
  }

  void EndRun(vtkIdType cell, bool visible)
  {
    if (this->Run.size() >= 2 && (visible || !this->VisibleOnly))
    {
      const vtkIdType c =
        this->Lines->InsertNextCell(static_cast<vtkIdType>(this->Run.size()), this->Run.data());
      this->Output->GetCellData()->CopyData(this->Input->GetCellData(), cell, c);
      this->CellVisibility->InsertNextValue(visible ? 1 : 0);
    }
    this->Run.clear();
  }

  vtkPolyData* Input;
  vtkPolyData* Output;
  bool VisibleOnly;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Lines;
  vtkNew<vtkUnsignedCharArray> PointVisibility, CellVisibility;
  std::vector<vtkIdType> Run; // the current run's output point ids
};
}

//------------------------------------------------------------------------------
vtkStylizeLineVisibility::vtkStylizeLineVisibility()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkStylizeLineVisibility::~vtkStylizeLineVisibility()
{
  this->SetDepthImage(nullptr);
}

//------------------------------------------------------------------------------
void vtkStylizeLineVisibility::SetViewportSize(int width, int height)
{
  width = std::max(1, std::min(65536, width));
  height = std::max(1, std::min(65536, height));
  if (width != this->ViewportSize[0] || height != this->ViewportSize[1])
  {
    this->ViewportSize[0] = width;
    this->ViewportSize[1] = height;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkStylizeLineVisibility::SetImageSize(double width, double height)
{
  auto clamp = [](double v) { return std::isfinite(v) ? std::max(0.0, std::min(1.0e7, v)) : 0.0; };
  width = clamp(width);
  height = clamp(height);
  if (width != this->ImageSize[0] || height != this->ImageSize[1])
  {
    this->ImageSize[0] = width;
    this->ImageSize[1] = height;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkStylizeLineVisibility::SetImageOffset(double x, double y)
{
  auto clamp = [](double v)
  { return std::isfinite(v) ? std::max(-1.0e7, std::min(1.0e7, v)) : 0.0; };
  x = clamp(x);
  y = clamp(y);
  if (x != this->ImageOffset[0] || y != this->ImageOffset[1])
  {
    this->ImageOffset[0] = x;
    this->ImageOffset[1] = y;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkStylizeLineVisibility::AddOccluder(vtkPolyData* surface, vtkMatrix4x4* matrix)
{
  if (surface)
  {
    this->Internal->Occluders.push_back({ surface, matrix });
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkStylizeLineVisibility::AddSharedOccluder(vtkStylizeRayOccluder* occluder)
{
  if (occluder)
  {
    this->Internal->Shared.push_back(occluder);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkStylizeLineVisibility::RemoveAllOccluders()
{
  this->Internal->Occluders.clear();
  this->Internal->Shared.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
vtkMTimeType vtkStylizeLineVisibility::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->DepthImage)
  {
    t = std::max(t, this->DepthImage->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------
int vtkStylizeLineVisibility::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* given = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!given || !output)
  {
    return 0;
  }
  // The lines without the point and cell arrays that hold fewer values than there are points or
  // cells (read past their end when the runs' values are interpolated and copied), with a
  // warning.
  vtkNew<vtkPolyData> checked;
  checked->ShallowCopy(given);
  auto dropShort = [this](vtkDataSetAttributes* data, vtkIdType needed, const char* what)
  {
    for (int i = data->GetNumberOfArrays() - 1; i >= 0; --i)
    {
      vtkAbstractArray* array = data->GetAbstractArray(i);
      if (array && array->GetNumberOfTuples() < needed)
      {
        vtkWarningMacro(<< what << " array '" << (array->GetName() ? array->GetName() : "")
                        << "' has fewer values than the lines' " << what << "s: ignored.");
        data->RemoveArray(i);
      }
    }
  };
  dropShort(checked->GetPointData(), given->GetNumberOfPoints(), "point");
  dropShort(checked->GetCellData(), given->GetNumberOfCells(), "cell");
  vtkPolyData* input = checked;
  if (!this->Camera)
  {
    vtkErrorMacro("a camera is required");
    return 0;
  }
  const bool tiled = this->ImageSize[0] > 0 && this->ImageSize[1] > 0;
  const double full[2] = { tiled ? this->ImageSize[0] : this->ViewportSize[0],
    tiled ? this->ImageSize[1] : this->ViewportSize[1] };
  const double offset[2] = { tiled ? this->ImageOffset[0] : 0.0,
    tiled ? this->ImageOffset[1] : 0.0 };
  const Tester view(this->Camera, this->ModelMatrix, this->ViewportSize, full, offset);
  DepthTest depth(view, this->DepthTolerance, this->WorldTolerance, this->DepthKind == VIEW_DEPTH);
  RayCast rays(view);
  if (this->Method == DEPTH_BUFFER && !depth.SetImage(this->DepthImage))
  {
    vtkErrorMacro("DEPTH_BUFFER needs a float depth image of ViewportSize pixels");
    return 0;
  }
  if (this->Method == RAY_CAST)
  {
    for (const auto& o : this->Internal->Occluders)
    {
      rays.AddOccluder(o.Surface, o.Matrix);
    }
    for (const auto& occluder : this->Internal->Shared)
    {
      rays.Add(occluder);
    }
  }
  // Lines without a FeatureKind count as contours (the WorldTolerance applies to them). Read
  // here, once: GetTuple1 writes the array's shared tuple buffer, so the threads below must not
  // call it. (Line c's values are cell c's, as the runs' copies below take them: the input is
  // lines alone.)
  vtkDataArray* kindArray = input->GetCellData()->GetArray("FeatureKind");
  const bool kinds = kindArray != nullptr;
  std::vector<double> kindOf(static_cast<size_t>(input->GetNumberOfLines()), 0.0);
  if (kindArray && kindArray->GetNumberOfComponents() > 0)
  {
    const vtkIdType n =
      std::min(static_cast<vtkIdType>(kindOf.size()), kindArray->GetNumberOfTuples());
    for (vtkIdType c = 0; c < n; ++c)
    {
      kindOf[c] = kindArray->GetComponent(c, 0);
    }
  }
  auto visible = [&](const double p[3], const double a[3], const double b[3], bool contour,
                   bool boundary) -> bool
  {
    double win[3];
    if (!view.Project(p, win) || !view.InView(win))
    {
      return false;
    }
    if (this->Method == RAY_CAST)
    {
      return rays.Visible(p, win, contour);
    }
    if (!depth.Visible(win, contour))
    {
      return false;
    }
    double wa[3], wb[3];
    return !(boundary && this->HideSeams && view.Project(a, wa) && view.Project(b, wb) &&
      depth.Seam(win, wb[0] - wa[0], wb[1] - wa[1]));
  };
  // The polylines (copied: a cell array may hand out a reused buffer), traced (in parallel
  // against a depth image), emitted in order: the output does not depend on the thread count.
  std::vector<vtkIdType> offsets(1, 0), ids;
  {
    vtkIdType n;
    const vtkIdType* cellIds;
    vtkCellArray* lines = input->GetLines();
    for (lines->InitTraversal(); lines->GetNextCell(n, cellIds);)
    {
      ids.insert(ids.end(), cellIds, cellIds + n);
      offsets.push_back(static_cast<vtkIdType>(ids.size()));
    }
  }
  const vtkIdType cells = static_cast<vtkIdType>(offsets.size()) - 1;
  Splitter splitter(input, output, this->VisibleOnly);
  std::vector<Splitter::Changes> changes(static_cast<size_t>(cells));
  auto trace = [&](vtkIdType begin, vtkIdType end)
  {
    for (vtkIdType c = begin; c < end; ++c)
    {
      const double kind = c < static_cast<vtkIdType>(kindOf.size()) ? kindOf[c] : 0.0;
      const bool contour = kind == 0.0, boundary = kinds && kind == 1.0;
      changes[c] = splitter.Trace(offsets[c + 1] - offsets[c], ids.data() + offsets[c], view,
        this->SampleSpacing,
        [&](const double p[3], const double a[3], const double b[3])
        { return visible(p, a, b, contour, boundary); });
    }
  };
  // (both methods only read: the depth image, or the occluders' hierarchies)
  vtkSMPTools::For(0, cells, trace);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    splitter.Emit(c, offsets[c + 1] - offsets[c], ids.data() + offsets[c], changes[c]);
  }
  splitter.Finish();
  return 1;
}

//------------------------------------------------------------------------------
void vtkStylizeLineVisibility::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << this->Method << "\n";
  os << indent << "ViewportSize: " << this->ViewportSize[0] << " " << this->ViewportSize[1] << "\n";
  os << indent << "DepthImage: " << this->DepthImage << "\n";
  os << indent << "DepthKind: " << (this->DepthKind == VIEW_DEPTH ? "view" : "window") << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " " << this->ImageSize[1] << "\n";
  os << indent << "ImageOffset: " << this->ImageOffset[0] << " " << this->ImageOffset[1] << "\n";
  os << indent << "Occluders: " << this->Internal->Occluders.size() << " surfaces, "
     << this->Internal->Shared.size() << " shared\n";
  os << indent << "SampleSpacing: " << this->SampleSpacing << "\n";
  os << indent << "DepthTolerance: " << this->DepthTolerance << "\n";
  os << indent << "WorldTolerance: " << this->WorldTolerance << "\n";
  os << indent << "HideSeams: " << this->HideSeams << "\n";
  os << indent << "VisibleOnly: " << this->VisibleOnly << "\n";
}
