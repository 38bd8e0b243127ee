// Hidden-line removal against an analytic reference: a cube seen from above a corner, partly
// behind a sphere (another actor). The strokes' centre lines are compared with the cube's edges
// and the sphere's outline as they project, each sample visible unless the cube's own faces or
// the sphere hide it: precision and recall within 1.5 px, for the frame's strokes (depth buffer)
// and for a vector figure's (ray cast).
#include "vtkLineArtPass.h"
#include "vtkStylizeTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCubeSource.h"
#include "vtkMatrix4x4.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <array>
#include <cmath>
#include <vector>

using namespace stylizetest;

namespace
{
constexpr int W = 400, H = 300;
using Vec = std::array<double, 3>;
using Pixel = std::array<double, 2>;

Vec Add(const Vec& a, const Vec& b, double s = 1.0)
{
  return { a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2] };
}
double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

struct Reference
{
  Vec Eye, Center;
  double Radius;
  vtkNew<vtkMatrix4x4> ToClip;

  bool Project(const Vec& p, Pixel& out) const
  {
    const double in[4] = { p[0], p[1], p[2], 1.0 };
    double c[4];
    this->ToClip->MultiplyPoint(in, c);
    out = { (c[0] / c[3] + 1.0) * 0.5 * W, (c[1] / c[3] + 1.0) * 0.5 * H };
    return c[3] > 0.0;
  }

  /** Whether the segment from p to the eye passes through the sphere. */
  bool BehindSphere(const Vec& p) const
  {
    const Vec d = Add(this->Eye, p, -1.0);
    const Vec m = Add(p, this->Center, -1.0);
    const double a = Dot(d, d), b = Dot(m, d), c = Dot(m, m) - this->Radius * this->Radius;
    const double disc = b * b - a * c;
    if (disc < 0.0)
    {
      return false;
    }
    const double t = (-b - std::sqrt(disc)) / a;
    return t > 1e-6 && t < 1.0;
  }
};

/** Samples of the visible reference lines, every 0.5 px: the cube's front edges, the outline. */
std::vector<Pixel> ReferenceSamples(const Reference& ref)
{
  std::vector<Pixel> out;
  auto add = [&](const Vec& a, const Vec& b, bool sphere)
  {
    Pixel pa, pb;
    ref.Project(a, pa);
    ref.Project(b, pb);
    const int n = std::max(1, static_cast<int>(std::hypot(pb[0] - pa[0], pb[1] - pa[1]) * 2));
    for (int i = 0; i <= n; ++i)
    {
      const Vec p = Add(a, Add(b, a, -1.0), static_cast<double>(i) / n);
      Pixel q;
      if (ref.Project(p, q) && (sphere || !ref.BehindSphere(p)))
      {
        out.push_back(q);
      }
    }
  };
  // The cube [-1, 1]^3 seen from +x +y +z: the edges not on the far corner (-1, -1, -1).
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int s1 = -1; s1 <= 1; s1 += 2)
    {
      for (int s2 = -1; s2 <= 1; s2 += 2)
      {
        if (s1 < 0 && s2 < 0)
        {
          continue; // an edge at the far corner: hidden by the cube
        }
        Vec a{}, b{};
        a[axis] = -1.0;
        b[axis] = 1.0;
        a[(axis + 1) % 3] = b[(axis + 1) % 3] = s1;
        a[(axis + 2) % 3] = b[(axis + 2) % 3] = s2;
        add(a, b, false);
      }
    }
  }
  // The sphere's outline: the circle where the view grazes it.
  const Vec u = Add(ref.Eye, ref.Center, -1.0);
  const double d = std::sqrt(Dot(u, u));
  const Vec n = { u[0] / d, u[1] / d, u[2] / d };
  const Vec c = Add(ref.Center, n, ref.Radius * ref.Radius / d);
  const double r = ref.Radius * std::sqrt(d * d - ref.Radius * ref.Radius) / d;
  Vec e1 = { -n[1], n[0], 0.0 };
  const double l1 = std::sqrt(Dot(e1, e1));
  e1 = { e1[0] / l1, e1[1] / l1, 0.0 };
  const Vec e2 = { n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2],
    n[0] * e1[1] - n[1] * e1[0] };
  for (int i = 0; i < 1440; ++i)
  {
    const double t = 2.0 * 3.141592653589793 * i / 1440;
    const Vec a = Add(Add(c, e1, r * std::cos(t)), e2, r * std::sin(t));
    const Vec b = Add(Add(c, e1, r * std::cos(t + 0.005)), e2, r * std::sin(t + 0.005));
    add(a, b, true);
  }
  return out;
}

std::vector<Pixel> StrokeSamples(vtkPolyData* strokes)
{
  std::vector<Pixel> out;
  vtkCellArray* lines = strokes->GetLines();
  vtkIdType n;
  const vtkIdType* ids;
  for (lines->InitTraversal(); lines && lines->GetNextCell(n, ids);)
  {
    for (vtkIdType i = 0; i + 1 < n; ++i)
    {
      double a[3], b[3];
      strokes->GetPoint(ids[i], a);
      strokes->GetPoint(ids[i + 1], b);
      const int k = std::max(1, static_cast<int>(std::hypot(b[0] - a[0], b[1] - a[1]) * 2));
      for (int j = 0; j <= k; ++j)
      {
        const double t = static_cast<double>(j) / k;
        out.push_back({ a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) });
      }
    }
  }
  return out;
}

/** The share of `test`'s samples within `tol` pixels of one of `reference`'s (on a grid). */
double Near(const std::vector<Pixel>& test, const std::vector<Pixel>& reference, double tol)
{
  std::vector<char> grid(static_cast<size_t>(W) * H, 0);
  const int r = static_cast<int>(std::ceil(tol));
  for (const Pixel& p : reference)
  {
    for (int dy = -r; dy <= r; ++dy)
    {
      for (int dx = -r; dx <= r; ++dx)
      {
        const int x = static_cast<int>(std::floor(p[0])) + dx;
        const int y = static_cast<int>(std::floor(p[1])) + dy;
        if (x >= 0 && x < W && y >= 0 && y < H && std::hypot(dx, dy) <= tol)
        {
          grid[static_cast<size_t>(y) * W + x] = 1;
        }
      }
    }
  }
  size_t hits = 0, count = 0;
  for (const Pixel& p : test)
  {
    const int x = static_cast<int>(std::floor(p[0])), y = static_cast<int>(std::floor(p[1]));
    if (x >= 0 && x < W && y >= 0 && y < H)
    {
      ++count;
      hits += grid[static_cast<size_t>(y) * W + x];
    }
  }
  return count ? static_cast<double>(hits) / count : 0.0;
}
}

int TestLineArtHidden(int, char*[])
{
  auto win = MakeWindow(W, H);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(1, 1, 1);
  win->AddRenderer(ren);
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(2);
  cube->SetYLength(2);
  cube->SetZLength(2);
  vtkNew<vtkPolyDataMapper> cm;
  cm->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkActor> ca;
  ca->SetMapper(cm);
  ren->AddActor(ca);

  Reference ref;
  const Vec toEye = { 0.55, 0.62, 0.56 };
  const double len = std::sqrt(Dot(toEye, toEye));
  ref.Eye = { 9.0 * toEye[0] / len, 9.0 * toEye[1] / len, 9.0 * toEye[2] / len };
  // A sphere between the cube's near corner and the eye, off the axis.
  ref.Center = { 3.4 * toEye[0] / len + 0.35, 3.4 * toEye[1] / len, 3.4 * toEye[2] / len - 0.3 };
  ref.Radius = 0.45;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(ref.Center.data());
  sphere->SetRadius(ref.Radius);
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(64);
  vtkNew<vtkPolyDataMapper> sm;
  sm->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sa;
  sa->SetMapper(sm);
  ren->AddActor(sa);

  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(ref.Eye.data());
  cam->SetFocalPoint(0, 0, 0);
  cam->SetViewUp(0, 0, 1);
  cam->SetViewAngle(30);
  cam->SetClippingRange(1.0, 20.0);
  ref.ToClip->DeepCopy(cam->GetCompositeProjectionTransformMatrix(double(W) / H, -1, 1));

  vtkNew<vtkLineArtPass> pass;
  ren->SetPass(pass);
  win->Render();
  const std::vector<Pixel> reference = ReferenceSamples(ref);
  vtkNew<vtkPolyData> frame;
  frame->DeepCopy(pass->GetStrokes());
  for (vtkPolyData* strokes : { frame.GetPointer(), pass->ComputeFigureStrokes(W, H, 1) })
  {
    const bool exact = strokes != frame.GetPointer();
    const std::vector<Pixel> test = StrokeSamples(strokes);
    // 1.5 px: the depth test's neighbourhood lets a line show a pixel past an occluder's edge.
    const double precision = Near(test, reference, 1.5);
    const double recall = Near(reference, test, 1.5);
    std::printf("%s strokes: %zu samples, precision %.4f, recall %.4f\n",
      exact ? "figure (ray cast)" : "frame (depth buffer)", test.size(), precision, recall);
    STYLIZE_CHECK(precision >= 0.99 && recall >= 0.99, "%s: precision %.4f recall %.4f",
      exact ? "figure" : "frame", precision, recall);
  }
  win->Finalize();
  return Failures == 0 ? 0 : 1;
}
