#include "vtkStylizeVolumeFog.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkScalarsToColors.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
/** The fog's steps (half samples) from a haze point before the side of the haze is read. */
constexpr int Settle = 3;

/** Accumulated premultiplied `rgba` as the point's colour and opacity (times `scale`), bytes. */
void WriteRGBA(vtkUnsignedCharArray* out, vtkIdType id, const double rgba[4], double scale)
{
  for (int c = 0; c < 3; ++c)
  {
    const double colour = rgba[3] > 0.0 ? rgba[c] / rgba[3] : 0.0;
    out->SetTypedComponent(
      id, c, static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, colour)))));
  }
  const double a = std::min(1.0, std::max(0.0, rgba[3] * scale));
  out->SetTypedComponent(id, 3, static_cast<unsigned char>(std::lround(255.0 * a)));
}

/** The steps t (from the point, along di) of the ray inside the image's index box. */
void RayExtent(const double ijk[3], const double di[3], const int e[6], const int dims[3],
  double& first, double& last)
{
  first = -1e30;
  last = 1e30;
  for (int a = 0; a < 3; ++a)
  {
    const double q = ijk[a] - e[2 * a];
    if (std::abs(di[a]) > 1e-12)
    {
      const double ta = -q / di[a], tb = (dims[a] - 1 - q) / di[a];
      first = std::max(first, std::min(ta, tb));
      last = std::min(last, std::max(ta, tb));
    }
    else if (q < 0.0 || q > dims[a] - 1)
    {
      last = -1e30;
    }
  }
}

/** The fog's tables: opacity and colour over the scalars' range, the scalars as floats. */
struct FogTables
{
  static constexpr int Bins = 1024;
  std::vector<double> Alpha, Rgb;
  std::vector<float> Values;
  std::vector<char> Valid; // (a resampled image: where it lies in the data; empty: everywhere)
  double Lo = 0.0, Width = 1.0;
};

/** Fills `t` for `image`'s `scalars`; false for an empty or non-finite range. */
bool MakeFogTables(vtkImageData* image, vtkDataArray* scalars, vtkPiecewiseFunction* opacity,
  vtkScalarsToColors* colors, vtkDataArray* mask, FogTables& t)
{
  double range[2];
  scalars->GetRange(range, 0);
  if (!(range[1] >= range[0]) || !std::isfinite(range[0]) || !std::isfinite(range[1]))
  {
    return false;
  }
  constexpr int bins = FogTables::Bins;
  t.Alpha.resize(bins);
  t.Rgb.resize(3 * bins);
  t.Lo = range[0];
  t.Width = std::max(range[1] - range[0], 1e-30);
  opacity->GetTable(t.Lo, t.Lo + t.Width, bins, t.Alpha.data());
  for (int i = 0; i < bins; ++i)
  {
    colors->GetColor(t.Lo + t.Width * i / (bins - 1), &t.Rgb[3 * i]);
  }
  const vtkIdType n = image->GetNumberOfPoints();
  t.Values.resize(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = scalars->GetComponent(i, 0);
    t.Values[i] = static_cast<float>(std::isfinite(v) ? v : t.Lo);
  }
  if (mask && mask->GetNumberOfTuples() == n)
  {
    t.Valid.resize(t.Values.size());
    for (vtkIdType i = 0; i < n; ++i)
    {
      t.Valid[i] = mask->GetComponent(i, 0) != 0.0;
    }
  }
  return true;
}

/** The affine map from `image`'s coordinates to its continuous index: t0 + x[a] tx[a]. */
void IndexTransform(vtkImageData* image, double t0[3], double tx[3][3])
{
  const double zero[3] = { 0.0, 0.0, 0.0 };
  image->TransformPhysicalPointToContinuousIndex(zero, t0);
  for (int a = 0; a < 3; ++a)
  {
    double axis[3] = { 0.0, 0.0, 0.0 };
    axis[a] = 1.0;
    image->TransformPhysicalPointToContinuousIndex(axis, tx[a]);
    for (int b = 0; b < 3; ++b)
    {
      tx[a][b] -= t0[b];
    }
  }
}

}

//------------------------------------------------------------------------------
bool vtkStylizeAccumulateHaze(vtkPolyData* haze, vtkImageData* image, vtkDataArray* scalars,
  vtkPiecewiseFunction* opacity, vtkScalarsToColors* colors, double unit, double level,
  double solid, double scale, const double eye[3], const double dop[3], bool parallel,
  vtkDataArray* mask, vtkUnsignedCharArray* out)
{
  const int* e = image->GetExtent();
  const vtkIdType n = haze->GetNumberOfPoints();
  if (!scalars || scalars->GetNumberOfTuples() != image->GetNumberOfPoints() || n == 0 ||
    e[1] < e[0] || e[3] < e[2] || e[5] < e[4] || !(unit > 0.0))
  {
    return false;
  }
  FogTables tables;
  if (!MakeFogTables(image, scalars, opacity, colors, mask, tables))
  {
    return false;
  }
  constexpr int bins = FogTables::Bins;
  const std::vector<double>& alphaTable = tables.Alpha;
  const std::vector<double>& rgbTable = tables.Rgb;
  const std::vector<float>& values = tables.Values;
  const std::vector<char>& valid = tables.Valid;
  const double lo = tables.Lo, width = tables.Width;
  const int dims[3] = { e[1] - e[0] + 1, e[3] - e[2] + 1, e[5] - e[4] + 1 };
  const double* spacing = image->GetSpacing();
  const double step =
    0.5 * std::min({ std::abs(spacing[0]), std::abs(spacing[1]), std::abs(spacing[2]) });
  if (!(step > 0.0))
  {
    return false;
  }
  const double power = step / unit;
  // index = t0 + x[0] tx[0] + x[1] tx[1] + x[2] tx[2] (the image's origin, spacing, direction)
  double t0[3], tx[3][3];
  IndexTransform(image, t0, tx);
  auto toIndex = [&](const double p[3], double ijk[3], bool vector)
  {
    for (int b = 0; b < 3; ++b)
    {
      ijk[b] = (vector ? 0.0 : t0[b]) + p[0] * tx[0][b] + p[1] * tx[1][b] + p[2] * tx[2][b];
    }
  };
  out->SetNumberOfComponents(4);
  out->SetNumberOfTuples(n);
  vtkPoints* points = haze->GetPoints();
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType id = begin; id < end; ++id)
      {
        double x[3], d[3], ijk[3], di[3];
        points->GetPoint(id, x);
        for (int a = 0; a < 3; ++a)
        {
          d[a] = parallel ? dop[a] : x[a] - eye[a];
        }
        const double length = vtkMath::Norm(d);
        double rgba[4] = { 0.0, 0.0, 0.0, 0.0 };
        if (length > 0.0)
        {
          toIndex(x, ijk, false);
          const double move[3] = { d[0] / length * step, d[1] / length * step,
            d[2] / length * step };
          toIndex(move, di, true);
          // the ray's steps inside the image: from the point, t in [first, last]
          double first, last;
          RayExtent(ijk, di, e, dims, first, last);
          // The opacity at t (and its table bin).
          auto opacityAt = [&](double t, int& bin)
          {
            int i0[3];
            double f[3];
            for (int a = 0; a < 3; ++a)
            {
              const double q = std::min(
                std::max(ijk[a] + t * di[a] - e[2 * a], 0.0), static_cast<double>(dims[a] - 1));
              i0[a] = std::min(static_cast<int>(q), std::max(dims[a] - 2, 0));
              f[a] = dims[a] > 1 ? q - i0[a] : 0.0;
            }
            double v = 0.0;
            bool inside = true;
            for (int c = 0; c < 8; ++c)
            {
              const int o[3] = { c & 1, (c >> 1) & 1, (c >> 2) & 1 };
              double w = 1.0;
              vtkIdType index = 0;
              for (int a = 2; a >= 0; --a)
              {
                w *= o[a] ? f[a] : 1.0 - f[a];
                index = index * dims[a] + std::min(i0[a] + o[a], dims[a] - 1);
              }
              v += w * values[static_cast<size_t>(index)];
              inside = inside && (valid.empty() || valid[static_cast<size_t>(index)]);
            }
            if (!inside)
            {
              bin = 0;
              return 0.0; // outside the data: nothing
            }
            bin = std::min(
              std::max(static_cast<int>((v - lo) / width * (bins - 1) + 0.5), 0), bins - 1);
            return alphaTable[bin];
          };
          auto add = [&](double sample, int bin)
          {
            const double alpha =
              (1.0 - std::pow(1.0 - std::min(sample, 1.0), power)) * (1.0 - rgba[3]);
            for (int a = 0; a < 3; ++a)
            {
              rgba[a] += alpha * rgbTable[3 * bin + a];
            }
            rgba[3] += alpha;
          };
          // The ray's part this point stands for, so that the shell's layers, composited front
          // to back, add up to the whole ray: in front of it, the fog from where the ray enters
          // the image unless the haze is crossed there (a nearer layer's part); behind it, the
          // fog up to the next crossing of the haze, the solid surface or the image's end.
          int bin = 0;
          for (double t = first + 0.5; t < -1.0 && last >= first; t += 1.0)
          {
            const double sample = opacityAt(t, bin);
            if (sample >= level)
            {
              rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0.0;
              break;
            }
            add(sample, bin);
          }
          // (which side of the haze the ray is on: a sample away from the point, where the
          // point's own crossing is behind)
          bool within = false;
          for (int k = 0; 0.5 + k <= last && rgba[3] < 0.995; ++k)
          {
            const double sample = opacityAt(0.5 + k, bin);
            if (sample >= solid || (k > Settle && (sample >= level) != within))
            {
              break; // the solid surface, or the haze's next layer
            }
            within = k == Settle ? sample >= level : within;
            add(sample, bin);
          }
        }
        WriteRGBA(out, id, rgba, scale);
      }
    });
  return true;
}
