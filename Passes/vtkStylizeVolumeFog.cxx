#include "vtkStylizeVolumeFog.h"

#include "vtkAbstractCellLocator.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProbeFilter.h"
#include "vtkSMPTools.h"
#include "vtkScalarsToColors.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

namespace
{
/** The fog's steps (half samples) from a haze point before the side of the haze is read. */
constexpr int Settle = 3;
/** The samples of material past where a chord looks solid that its depth needs (Chord()). */
constexpr int Margin = 2;

/** The steps either side of a solid sample within which the solid surface drawn is sought. */
constexpr double Near = 4.0;

/**
 * x to the power p, by squaring when p is a whole number up to 128 (a specular power: VTK's
 * default is 10), else std::pow: each lit sample of the fog takes one, and std::pow was a tenth
 * of the fog's time.
 */
inline double PowerOf(double x, double p)
{
  if (p >= 0.0 && p <= 128.0 && p == std::floor(p))
  {
    unsigned n = static_cast<unsigned>(p);
    double result = 1.0;
    for (double base = x; n != 0; n >>= 1u, base *= base)
    {
      result = (n & 1u) ? result * base : result;
    }
    return result;
  }
  return std::pow(x, p);
}

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

/**
 * The first step k at or past the point (its samples at steps 0.5 + k) in the image, the ray
 * entering it at step `first`: a point of a surface closed past the image's faces (padded) lies
 * outside it, where VTK's ray caster takes no samples (the image's values clamped there would
 * add the faces' opacity again).
 */
int FirstInside(double first)
{
  return first > 0.5 ? static_cast<int>(std::ceil(std::min(first - 0.5, 1e9))) : 0;
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

/** The fog's tables: opacity and colour over the scalars' range, the scalars as floats. */
struct FogTables
{
  static constexpr int Bins = 1024;
  std::vector<double> Alpha, Rgb;
  std::vector<float> Values;
  std::vector<char> Valid; // (a resampled image: where it lies in the data; empty: everywhere)
  double Lo = 0.0, Width = 1.0;
  // Blocks of Block^3 cells where every sample's opacity is 0 (the rays step over them).
  static constexpr int Block = 8;
  std::vector<char> Empty;
  int Blocks[3] = { 0, 0, 0 };
};

/** Marks `t`'s blocks whose voxels' values all have opacity 0 (`dims`: the image's). */
void MarkEmptyBlocks(FogTables& t, const int dims[3])
{
  constexpr int B = FogTables::Block;
  constexpr int bins = FogTables::Bins;
  for (int a = 0; a < 3; ++a)
  {
    t.Blocks[a] = std::max(1, (dims[a] - 1 + B - 1) / B);
  }
  // per bin range [lo, hi]: empty when no bin in it is above 0 (prefix counts of non-zero bins)
  std::vector<int> count(bins + 1, 0);
  for (int i = 0; i < bins; ++i)
  {
    count[i + 1] = count[i] + (t.Alpha[i] > 0.0 ? 1 : 0);
  }
  const size_t n = static_cast<size_t>(t.Blocks[0]) * t.Blocks[1] * t.Blocks[2];
  t.Empty.assign(n, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(n),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType b = begin; b < end; ++b)
      {
        const int bi[3] = { static_cast<int>(b % t.Blocks[0]),
          static_cast<int>((b / t.Blocks[0]) % t.Blocks[1]),
          static_cast<int>(b / (static_cast<vtkIdType>(t.Blocks[0]) * t.Blocks[1])) };
        // (the cells of the block use the voxels up to the next block's first)
        float lo = VTK_FLOAT_MAX, hi = -VTK_FLOAT_MAX;
        for (int k = bi[2] * B; k <= std::min((bi[2] + 1) * B, dims[2] - 1); ++k)
        {
          for (int j = bi[1] * B; j <= std::min((bi[1] + 1) * B, dims[1] - 1); ++j)
          {
            const size_t row = (static_cast<size_t>(k) * dims[1] + j) * dims[0];
            for (int i = bi[0] * B; i <= std::min((bi[0] + 1) * B, dims[0] - 1); ++i)
            {
              lo = std::min(lo, t.Values[row + i]);
              hi = std::max(hi, t.Values[row + i]);
            }
          }
        }
        auto binOf = [&](double value)
        {
          return std::min(
            std::max(static_cast<int>((value - t.Lo) / t.Width * (bins - 1) + 0.5), 0), bins - 1);
        };
        t.Empty[b] = count[binOf(hi) + 1] - count[binOf(lo)] == 0;
      }
    });
}

/** Fills `t` for the volume; false for an empty or non-finite range. */
bool MakeFogTables(const vtkStylizeVolumeFog::Volume& v, FogTables& t)
{
  double range[2];
  v.Scalars->GetFiniteRange(range, 0); // (non-finite values are read as the lowest)
  if (!(range[1] >= range[0]) || !std::isfinite(range[0]) || !std::isfinite(range[1]))
  {
    return false;
  }
  constexpr int bins = FogTables::Bins;
  t.Alpha.resize(bins);
  t.Rgb.resize(3 * bins);
  t.Lo = range[0];
  t.Width = std::max(range[1] - range[0], 1e-30);
  v.Opacity->GetTable(t.Lo, t.Lo + t.Width, bins, t.Alpha.data());
  for (int i = 0; i < bins; ++i)
  {
    v.Colors->GetColor(t.Lo + t.Width * i / (bins - 1), &t.Rgb[3 * i]);
  }
  const vtkIdType n = v.Image->GetNumberOfPoints();
  t.Values.resize(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double value = v.Scalars->GetComponent(i, 0);
    t.Values[i] = static_cast<float>(std::isfinite(value) ? value : t.Lo);
  }
  t.Valid.clear();
  if (v.Mask && v.Mask->GetNumberOfTuples() == n)
  {
    t.Valid.resize(t.Values.size());
    for (vtkIdType i = 0; i < n; ++i)
    {
      t.Valid[i] = v.Mask->GetComponent(i, 0) != 0.0;
    }
  }
  const int* e = v.Image->GetExtent();
  const int dims[3] = { e[1] - e[0] + 1, e[3] - e[2] + 1, e[5] - e[4] + 1 };
  MarkEmptyBlocks(t, dims);
  return true;
}

/** One ray through the image's index space: its samples' opacity, colour and lighting. */
struct FogRay
{
  const FogTables& T;
  const vtkStylizeVolumeFog::Shading& Light;
  const int* E;    // the image's extent
  const int* Dims; // its dimensions
  const double (*Tx)[3];
  double Ijk[3], Di[3]; // the ray's start and step in index space
  double ToLight[3];    // towards the headlight, in the image's coordinates (unit)
  const double* Step;   // per table bin, the opacity of a step (as the volume's mapper takes it)
  double Rgba[4] = { 0.0, 0.0, 0.0, 0.0 };
  // The solid surface as drawn (vtkStylizeVolumeFog::Accumulate()'s `drawn`), or null; the ray's
  // start and step in the image's coordinates.
  vtkAbstractCellLocator* Drawn = nullptr;
  std::mutex* DrawnLock = nullptr;
  vtkGenericCell* DrawnCell = nullptr; // (the queries' cell, used under DrawnLock)
  double X0[3] = { 0.0, 0.0, 0.0 }, Dx[3] = { 0.0, 0.0, 0.0 };

  /**
   * The image's value at index-space point `q` (clamped to the image); false outside the data.
   * A resampled image's points outside the data are left out of the interpolation, and `q` is in
   * the data where its points in the data weigh at least one half: the data's boundary half way
   * between its last point and the first outside, not a whole voxel inside (which grazing rays
   * at a silhouette would miss).
   */
  bool ValueAt(const double q[3], double& value) const
  {
    int i0[3];
    double f[3];
    for (int a = 0; a < 3; ++a)
    {
      const double c = std::min(std::max(q[a], 0.0), static_cast<double>(this->Dims[a] - 1));
      i0[a] = std::min(static_cast<int>(c), std::max(this->Dims[a] - 2, 0));
      f[a] = this->Dims[a] > 1 ? c - i0[a] : 0.0;
    }
    value = 0.0;
    double weight = 0.0;
    for (int c = 0; c < 8; ++c)
    {
      const int o[3] = { c & 1, (c >> 1) & 1, (c >> 2) & 1 };
      double w = 1.0;
      vtkIdType index = 0;
      for (int a = 2; a >= 0; --a)
      {
        w *= o[a] ? f[a] : 1.0 - f[a];
        index = index * this->Dims[a] + std::min(i0[a] + o[a], this->Dims[a] - 1);
      }
      if (this->T.Valid.empty() || this->T.Valid[static_cast<size_t>(index)])
      {
        value += w * this->T.Values[static_cast<size_t>(index)];
        weight += w;
      }
    }
    if (!(weight >= 0.5))
    {
      return false;
    }
    value /= weight;
    return true;
  }

  /** The sample at step t: its opacity and its table bin (outside the data: 0 and -1). */
  double OpacityAt(double t, int& bin) const
  {
    double q[3], value;
    for (int a = 0; a < 3; ++a)
    {
      q[a] = this->Ijk[a] + t * this->Di[a] - this->E[2 * a];
    }
    if (!this->ValueAt(q, value))
    {
      bin = -1; // (nothing: Add() skips it)
      return 0.0;
    }
    constexpr int bins = FogTables::Bins;
    bin = std::min(
      std::max(static_cast<int>((value - this->T.Lo) / this->T.Width * (bins - 1) + 0.5), 0),
      bins - 1);
    return this->T.Alpha[bin];
  }

  /**
   * The steps from the sample at step t to the next one that can hold fog: past the end of its
   * block when every sample there has opacity 0 (the samples in between add nothing), else 1.
   */
  int Ahead(double t) const
  {
    constexpr int B = FogTables::Block;
    double exit = 1e30;
    int block[3];
    for (int a = 0; a < 3; ++a)
    {
      const double q = this->Ijk[a] - this->E[2 * a];
      const double c = std::min(std::max(q + t * this->Di[a], 0.0), this->Dims[a] - 1.0);
      block[a] = std::min(static_cast<int>(c) / B, this->T.Blocks[a] - 1);
      if (this->Di[a] > 1e-12)
      {
        exit = std::min(exit, ((block[a] + 1) * B - q) / this->Di[a]);
      }
      else if (this->Di[a] < -1e-12)
      {
        exit = std::min(exit, (block[a] * B - q) / this->Di[a]);
      }
    }
    const size_t b =
      (static_cast<size_t>(block[2]) * this->T.Blocks[1] + block[1]) * this->T.Blocks[0] + block[0];
    if (!this->T.Empty[b] || !(exit < 1e29))
    {
      return 1;
    }
    return std::max(1, static_cast<int>(std::min(std::ceil(exit - t), 1e6)));
  }

  /**
   * The colour of the sample at step t (`rgb`: the colour map's) lit as VTK's ray caster lights
   * it (lighting complexity 1): ambient + diffuse |N.L| + specular |N.H|^power, N the gradient by
   * central differences over a voxel, L = H towards the headlight.
   */
  void Lit(double t, double rgb[3]) const
  {
    double g[3], q[3];
    for (int b = 0; b < 3; ++b)
    {
      for (int a = 0; a < 3; ++a)
      {
        q[a] = this->Ijk[a] + t * this->Di[a] - this->E[2 * a] + (a == b ? 1.0 : 0.0);
      }
      double high, low;
      this->ValueAt(q, high);
      q[b] -= 2.0;
      this->ValueAt(q, low);
      g[b] = high - low;
    }
    // d/dx_a = sum_b d/di_b di_b/dx_a
    double n[3];
    for (int a = 0; a < 3; ++a)
    {
      n[a] = g[0] * this->Tx[a][0] + g[1] * this->Tx[a][1] + g[2] * this->Tx[a][2];
    }
    const double length = vtkMath::Norm(n);
    double nDotL = length > 0.0 ? vtkMath::Dot(n, this->ToLight) / length : 0.0;
    nDotL = this->Light.TwoSided ? std::abs(nDotL) : nDotL;
    const double diffuse = nDotL > 0.0 ? this->Light.Diffuse * nDotL : 0.0;
    const double specular =
      nDotL > 0.0 ? this->Light.Specular * PowerOf(nDotL, this->Light.Power) : 0.0;
    for (int a = 0; a < 3; ++a)
    {
      rgb[a] = (this->Light.Ambient + diffuse) * rgb[a] + specular;
    }
  }

  /**
   * The opacity of the solid material the ray crosses from step t (up to step `last`): from its
   * first sample at least `solid` within 2 Settle steps (t may lie on the material's boundary,
   * which a resampled image places up to a sample away), the samples on while at least `solid`,
   * composited as VTK does, up to vtkStylizeVolumeFog::Thick. With `reached`: the step of the
   * first sample where it reaches `target`, when the material goes on for Margin samples past
   * it, else 0.
   */
  double Chord(
    double t, double last, double solid, double target = 2.0, double* reached = nullptr) const
  {
    int bin = 0, k = 0;
    while (k < 2 * Settle && t + k <= last && this->OpacityAt(t + k, bin) < solid)
    {
      ++k;
    }
    double a = 0.0, found = -1.0;
    for (; t + k <= last && a < vtkStylizeVolumeFog::Thick; ++k)
    {
      if (!(this->OpacityAt(t + k, bin) >= solid) || bin < 0)
      {
        break;
      }
      a += this->Step[bin] * (1.0 - a);
      found = found < 0.0 && a >= target ? t + k : found;
    }
    if (reached)
    {
      // (only where the material goes on for Margin samples past it: a depth there stays in
      // front of the material's far side, the surface's own back)
      bool on = found >= 0.0;
      for (int m = 1; on && m <= Margin; ++m)
      {
        on = found + m <= last && this->OpacityAt(found + m, bin) >= solid && bin >= 0;
      }
      *reached = on ? found : 0.0;
    }
    return a;
  }

  /**
   * The opacity accumulated from where the ray enters the image (step `first`) up to the point
   * (step 0), up to vtkStylizeVolumeFog::Thick.
   */
  double Front(double first) const
  {
    double a = 0.0;
    int bin = 0;
    for (double t = first + 0.5; t < -1.0 && a < vtkStylizeVolumeFog::Thick; t += this->Ahead(t))
    {
      this->OpacityAt(t, bin);
      a += bin < 0 ? 0.0 : this->Step[bin] * (1.0 - a);
    }
    return a;
  }

  /**
   * Where the ray meets the solid surface drawn within Near steps of step t (the surface and the
   * samples may disagree by a sample where the image was resampled), or 1e30.
   */
  double DrawnNear(double t) const
  {
    const double from = t - Near, to = t + Near;
    double a[3], b[3], x[3], pcoords[3], u = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      a[c] = this->X0[c] + from * this->Dx[c];
      b[c] = this->X0[c] + to * this->Dx[c];
    }
    int subId = 0;
    vtkIdType cellId = -1;
    if (this->Drawn->GetDataSet()->GetNumberOfCells() == 0)
    {
      return 1e30; // (nothing solid drawn)
    }
    std::lock_guard<std::mutex> guard(*this->DrawnLock); // (VTK 9.1's locators are not reentrant)
    return this->Drawn->IntersectWithLine(a, b, 0.0, u, x, pcoords, subId, cellId, this->DrawnCell)
      ? from + u * (to - from)
      : 1e30;
  }

  /** Composites the sample at step t (its table bin) behind what is accumulated. */
  void Add(double t, int bin)
  {
    const double alpha = bin < 0 ? 0.0 : this->Step[bin] * (1.0 - this->Rgba[3]);
    if (!(alpha > 0.0))
    {
      return;
    }
    double rgb[3] = { this->T.Rgb[3 * bin], this->T.Rgb[3 * bin + 1], this->T.Rgb[3 * bin + 2] };
    if (this->Light.On)
    {
      this->Lit(t, rgb);
    }
    for (int a = 0; a < 3; ++a)
    {
      this->Rgba[a] += alpha * rgb[a];
    }
    this->Rgba[3] += alpha;
  }

  /**
   * The ray's part a haze point stands for (t from `first` to `last`; the point at 0), so that
   * the shell's layers, composited front to back, add up to the whole ray: in front of it, the
   * fog from where the ray enters the image unless the haze is crossed there (a nearer layer's
   * part); behind it, the fog up to the next crossing of the haze, the solid surface or the
   * image's end. Returns the whole ray's opacity (through the solid material too, as VTK
   * accumulates it) for the ray's nearest layer; for the others, where the ray leaves the haze
   * (the back of a fold, at its silhouette what the eye sees just past it), the opacity from
   * the point on, and -1 where it enters it (a layer hidden behind a nearer one: no outline
   * across the border between the two). Without `wholeRay` (no outline asked for) the ray is
   * not followed past the point's part, and the result is only the part's opacity.
   */
  double March(double first, double last, double level, double solid, bool wholeRay)
  {
    int bin = 0;
    bool nearest = last >= first;
    for (double t = first + 0.5; t < -1.0 && last >= first; t += this->Ahead(t))
    {
      const double sample = this->OpacityAt(t, bin);
      if (sample >= level)
      {
        this->Rgba[0] = this->Rgba[1] = this->Rgba[2] = this->Rgba[3] = 0.0;
        nearest = false;
        break;
      }
      this->Add(t, bin);
    }
    // (which side of the haze the ray is on: a sample away from the point, where the point's own
    // crossing is behind)
    bool within = false;
    bool through = false; // in solid material not drawn (too thin to look solid): fog
    double stop = 1e30;   // where the ray meets the solid surface drawn
    int k = FirstInside(first);
    const int settle = k + Settle;
    for (; 0.5 + k <= last && this->Rgba[3]<0.995; k += k> settle ? this->Ahead(0.5 + k) : 1)
    {
      const double sample = this->OpacityAt(0.5 + k, bin);
      if (sample < solid)
      {
        through = false;
      }
      else if (!through)
      {
        if (!this->Drawn || this->Chord(0.5 + k, last, solid) >= vtkStylizeVolumeFog::Thick)
        {
          break; // the solid surface
        }
        // (thin or nearly so: the solid surface as drawn says whether it is there)
        stop = this->DrawnNear(0.5 + k);
        through = true;
      }
      if (0.5 + k >= stop)
      {
        break; // the solid surface drawn
      }
      if (k > settle && (sample >= level) != within)
      {
        break; // the haze's next layer
      }
      within = k == settle ? sample >= level : within;
      this->Add(0.5 + k, bin);
    }
    // The whole ray's opacity (the nearest layer's points, and from the point on where the ray
    // leaves the haze): on through the haze's other layers and the solid material, as VTK
    // accumulates it.
    const bool leaving = !nearest && !within;
    double whole = this->Rgba[3];
    for (; wholeRay && (nearest || leaving) && 0.5 + k <= last && whole < 0.995;
         k += this->Ahead(0.5 + k))
    {
      this->OpacityAt(0.5 + k, bin);
      whole += bin < 0 ? 0.0 : this->Step[bin] * (1.0 - whole);
    }
    return nearest || leaving ? whole : -1.0;
  }
};
}

/** The tables and what they were made for (the scalars, mask and functions, their times). */
struct vtkStylizeVolumeFog::Tables
{
  FogTables Fog;
  const void* Keys[4] = { nullptr, nullptr, nullptr, nullptr };
  vtkMTimeType Time = 0;
};

//------------------------------------------------------------------------------
vtkStylizeVolumeFog::vtkStylizeVolumeFog() = default;

//------------------------------------------------------------------------------
vtkStylizeVolumeFog::~vtkStylizeVolumeFog() = default;

//------------------------------------------------------------------------------
bool vtkStylizeVolumeFog::Prepare(const Volume& v, Rays& r)
{
  vtkImageData* image = v.Image;
  const int* e = image ? image->GetExtent() : nullptr;
  if (!image || !v.Opacity || !v.Colors || !v.Scalars ||
    v.Scalars->GetNumberOfTuples() != image->GetNumberOfPoints() || e[1] < e[0] || e[3] < e[2] ||
    e[5] < e[4] || !(v.Unit > 0.0))
  {
    return false;
  }
  // (the tables again only when the scalars, the mask or the functions changed)
  const void* keys[4] = { v.Scalars, v.Mask, v.Opacity, v.Colors };
  const vtkMTimeType time = std::max({ v.Scalars->GetMTime(),
    v.Mask ? v.Mask->GetMTime() : vtkMTimeType(0), v.Opacity->GetMTime(), v.Colors->GetMTime() });
  if (!this->Kept || !std::equal(keys, keys + 4, this->Kept->Keys) || time > this->Kept->Time)
  {
    this->Kept.reset(new Tables);
    if (!MakeFogTables(v, this->Kept->Fog))
    {
      this->Kept.reset();
      return false;
    }
    std::copy(keys, keys + 4, this->Kept->Keys);
    this->Kept->Time = time;
  }
  const FogTables& tables = this->Kept->Fog;
  std::copy(e, e + 6, r.Extent);
  for (int a = 0; a < 3; ++a)
  {
    r.Dims[a] = e[2 * a + 1] - e[2 * a] + 1;
  }
  const double* spacing = image->GetSpacing();
  r.Step = 0.5 * std::min({ std::abs(spacing[0]), std::abs(spacing[1]), std::abs(spacing[2]) });
  if (!(r.Step > 0.0))
  {
    return false;
  }
  // (each bin's opacity over a step, as VTK's mapper corrects it for the sample distance)
  r.Corrected.resize(tables.Alpha.size());
  for (size_t i = 0; i < r.Corrected.size(); ++i)
  {
    const double a = std::min(std::max(tables.Alpha[i], 0.0), 1.0);
    r.Corrected[i] = v.Attenuation ? 1.0 - std::exp(-a * r.Step / v.Unit)
                                   : 1.0 - std::pow(1.0 - a, r.Step / v.Unit);
  }
  // index = t0 + x[0] tx[0] + x[1] tx[1] + x[2] tx[2] (the image's origin, spacing, direction)
  IndexTransform(image, r.T0, r.Tx);
  return true;
}

//------------------------------------------------------------------------------
template <typename Work>
void vtkStylizeVolumeFog::ForRays(vtkPolyData* surface, const Volume& v, const Rays& r,
  const double eye[3], const double dop[3], bool parallel, Work work)
{
  auto toIndex = [&](const double p[3], double ijk[3], bool vector)
  {
    for (int b = 0; b < 3; ++b)
    {
      ijk[b] = (vector ? 0.0 : r.T0[b]) + p[0] * r.Tx[0][b] + p[1] * r.Tx[1][b] + p[2] * r.Tx[2][b];
    }
  };
  const FogTables& tables = this->Kept->Fog;
  vtkPoints* points = surface->GetPoints();
  vtkSMPTools::For(0, surface->GetNumberOfPoints(),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType id = begin; id < end; ++id)
      {
        FogRay ray{ tables, v.Light, r.Extent, r.Dims, r.Tx, {}, {}, {}, r.Corrected.data() };
        ray.Drawn = r.Drawn;
        ray.DrawnLock = r.Lock;
        ray.DrawnCell = r.Cell;
        double x[3], d[3];
        points->GetPoint(id, x);
        for (int a = 0; a < 3; ++a)
        {
          d[a] = parallel ? dop[a] : x[a] - eye[a];
        }
        const double length = vtkMath::Norm(d);
        double first = 0.0, last = -1e30; // (no ray: nothing accumulated)
        if (length > 0.0)
        {
          toIndex(x, ray.Ijk, false);
          const double move[3] = { d[0] / length * r.Step, d[1] / length * r.Step,
            d[2] / length * r.Step };
          toIndex(move, ray.Di, true);
          std::copy(x, x + 3, ray.X0);
          std::copy(move, move + 3, ray.Dx);
          for (int a = 0; a < 3; ++a)
          {
            ray.ToLight[a] = -d[a] / length;
          }
          RayExtent(ray.Ijk, ray.Di, r.Extent, r.Dims, first, last);
        }
        work(id, ray, first, last);
      }
    });
}

//------------------------------------------------------------------------------
bool vtkStylizeVolumeFog::Accumulate(vtkPolyData* haze, const Volume& v, double level, double solid,
  double scale, const double eye[3], const double dop[3], bool parallel, vtkUnsignedCharArray* out,
  vtkFloatArray* whole, vtkAbstractCellLocator* drawn)
{
  const vtkIdType n = haze->GetNumberOfPoints();
  Rays r;
  if (n == 0 || !this->Prepare(v, r))
  {
    return false;
  }
  std::mutex lock;
  vtkNew<vtkGenericCell> cell;
  r.Drawn = drawn;
  r.Lock = &lock;
  r.Cell = cell;
  out->SetNumberOfComponents(4);
  out->SetNumberOfTuples(n);
  if (whole)
  {
    whole->SetNumberOfComponents(1);
    whole->SetNumberOfTuples(n);
  }
  this->ForRays(haze, v, r, eye, dop, parallel,
    [&](vtkIdType id, FogRay& ray, double first, double last)
    {
      const double opacity = ray.March(first, last, level, solid, whole != nullptr);
      WriteRGBA(out, id, ray.Rgba, scale);
      if (whole)
      {
        whole->SetValue(id, static_cast<float>(opacity >= 0.0 ? opacity * scale : -1.0));
      }
    });
  return true;
}

//------------------------------------------------------------------------------
bool vtkStylizeVolumeFog::SolidOpacity(vtkPolyData* surface, const Volume& v, double solid,
  const double eye[3], const double dop[3], bool parallel, vtkFloatArray* out, vtkFloatArray* reach)
{
  const vtkIdType n = surface->GetNumberOfPoints();
  Rays r;
  if (n == 0 || !this->Prepare(v, r))
  {
    return false;
  }
  out->SetNumberOfComponents(1);
  out->SetNumberOfTuples(n);
  if (reach)
  {
    reach->SetNumberOfComponents(1);
    reach->SetNumberOfTuples(n);
  }
  this->ForRays(surface, v, r, eye, dop, parallel,
    [&](vtkIdType id, FogRay& ray, double first, double last)
    {
      const double front = ray.Front(first);
      // (the chord's share that brings the whole to LooksSolid; none when the front does)
      const double target = front < LooksSolid ? (LooksSolid - front) / (1.0 - front) : 0.0;
      double at = 0.0;
      const double chord =
        ray.Chord(0.5 + FirstInside(first), last, solid, target, reach ? &at : nullptr);
      out->SetValue(id, static_cast<float>(front + (1.0 - front) * chord));
      if (reach)
      {
        at = front < LooksSolid && std::isfinite(at) ? std::max(at, 0.0) : 0.0;
        reach->SetValue(id, static_cast<float>(at * r.Step));
      }
    });
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> vtkStylizeVolumeFog::GatherImage(
  vtkDataSet* piece, const char* name, vtkMultiProcessController* c, int points)
{
  // The union of the pieces' bounds: lows and negated highs, one reduction.
  const bool held = piece && piece->GetNumberOfPoints() > 0 && name;
  double local[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  if (held)
  {
    double b[6];
    piece->GetBounds(b);
    for (int a = 0; a < 3; ++a)
    {
      local[a] = b[2 * a];
      local[3 + a] = -b[2 * a + 1];
    }
  }
  // An image piece's extent (lows and negated highs; no image: an empty one, so that the union
  // is no grid unless every piece holding data is an image).
  auto* grid = vtkImageData::SafeDownCast(piece);
  const int* e = grid ? grid->GetExtent() : nullptr;
  const bool isImage = held && e && grid->GetPointData()->GetArray(name);
  int lows[6] = { VTK_INT_MAX, VTK_INT_MAX, VTK_INT_MAX, VTK_INT_MAX, VTK_INT_MAX, VTK_INT_MAX };
  int images = held && !isImage ? 0 : 1, allImages = 0;
  if (isImage)
  {
    for (int a = 0; a < 3; ++a)
    {
      lows[a] = e[2 * a];
      lows[3 + a] = -e[2 * a + 1];
    }
  }
  double all[6];
  int extent[6];
  // (one process, or none: its own piece, sampled as several processes sample theirs)
  const bool several = c && c->GetNumberOfProcesses() > 1;
  auto reduce = [&](auto* in, auto* out, vtkIdType n, int op)
  {
    if (several)
    {
      c->AllReduce(in, out, n, op);
    }
    else
    {
      std::copy(in, in + n, out);
    }
  };
  reduce(local, all, 6, vtkCommunicator::MIN_OP);
  reduce(lows, extent, 6, vtkCommunicator::MIN_OP);
  reduce(&images, &allImages, 1, vtkCommunicator::MIN_OP);
  if (!(all[0] < VTK_DOUBLE_MAX))
  {
    return nullptr; // (no piece holds data)
  }
  double bounds[6];
  for (int a = 0; a < 3; ++a)
  {
    bounds[2 * a] = all[a];
    bounds[2 * a + 1] = std::max(-all[3 + a], all[a]);
  }
  int dims[3];
  vtkIdType gridPoints = allImages && extent[0] < VTK_INT_MAX ? 1 : 0;
  for (int a = 0; a < 3 && gridPoints > 0; ++a)
  {
    dims[a] = std::max(1, -extent[3 + a] - extent[a] + 1);
    gridPoints = dims[a] > 1 ? gridPoints * dims[a] : 0; // (a flat image: resampled)
    gridPoints = gridPoints > GatheredGridPoints ? 0 : gridPoints;
  }
  if (gridPoints == 0)
  {
    const double longest =
      std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1e-30 });
    for (int a = 0; a < 3; ++a)
    {
      dims[a] = std::max(
        2, static_cast<int>(std::lround(points * (bounds[2 * a + 1] - bounds[2 * a]) / longest)));
    }
  }
  const vtkIdType n = static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2];
  // Each piece's values where it holds data, and 1 there: summed over the processes. (Probed:
  // ParaView's factory makes vtkResampleToImage a parallel filter, which would split the image.)
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims);
  image->SetOrigin(bounds[0], bounds[2], bounds[4]);
  image->SetSpacing((bounds[1] - bounds[0]) / (dims[0] - 1),
    (bounds[3] - bounds[2]) / (dims[1] - 1), (bounds[5] - bounds[4]) / (dims[2] - 1));
  std::vector<float> sums(2 * static_cast<size_t>(n), 0.0f), totals(sums.size());
  if (held)
  {
    vtkNew<vtkProbeFilter> probe;
    probe->SetInputData(image);
    probe->SetSourceData(piece);
    probe->Update();
    vtkDataSet* sampled = probe->GetOutput();
    vtkDataArray* values = sampled->GetPointData()->GetArray(name);
    vtkDataArray* mask = sampled->GetPointData()->GetArray(probe->GetValidPointMaskArrayName());
    for (vtkIdType i = 0; values && mask && i < n; ++i)
    {
      const double v = values->GetComponent(i, 0);
      if (mask->GetComponent(i, 0) != 0.0 && std::isfinite(v))
      {
        sums[i] = static_cast<float>(v);
        sums[n + i] = 1.0f;
      }
    }
  }
  reduce(sums.data(), totals.data(), static_cast<vtkIdType>(sums.size()), vtkCommunicator::SUM_OP);
  vtkNew<vtkFloatArray> values;
  values->SetName(name ? name : "");
  values->SetNumberOfTuples(n);
  vtkNew<vtkUnsignedCharArray> valid;
  valid->SetName("vtkValidPointMask");
  valid->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const float count = totals[n + i];
    values->SetValue(i, count > 0.0f ? totals[i] / count : 0.0f);
    valid->SetValue(i, count > 0.0f ? 1 : 0);
  }
  image->GetPointData()->AddArray(values);
  image->GetPointData()->AddArray(valid);
  return image;
}
