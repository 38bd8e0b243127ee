#include "vtkstylizeInput.h"

#include "vtkstylizeCommon.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkContourFilter.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkStylizePrincipalCurvatures.h"
#include "vtkStylizeReader.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vtkstylize
{
std::string SupportedExtensions()
{
  return vtkStylizeReader::GetSupportedExtensions();
}

bool IsSupportedInput(const std::string& path)
{
  return vtkStylizeReader::IsSupportedFile(path);
}

vtkSmartPointer<vtkDataObject> ReadInput(
  const std::string& path, int timeStep, double memoryMiB, double seconds)
{
  vtkNew<vtkStylizeReader> reader;
  reader->SetFileName(path.c_str());
  reader->SetTimeStep(timeStep);
  if (memoryMiB >= 0.0)
  {
    reader->SetMemoryLimit(memoryMiB > 0.0 ? memoryMiB : 1e9);
  }
  reader->SetTimeLimit(seconds);
  ClearVTKErrors();
  reader->Update();
  ClearVTKErrors(); // (the reader's error is in its ErrorMessage, the executive's says it failed)
  const std::string error = reader->GetErrorMessage();
  if (!error.empty())
  {
    // The reading process's own limits name the option that raises them.
    if (error.find("(the reader's time limit)") != std::string::npos)
    {
      Fail(error + "; raise it with --read-time-limit");
    }
    if (error.find("the reader's limit") != std::string::npos)
    {
      Fail(error + "; raise it with --memory-limit");
    }
    Fail(error + (SaysOutOfMemory(error) ? MemoryLimitText() : std::string()));
  }
  for (int i = 0; i < reader->GetNumberOfWarnings(); ++i)
  {
    Warn(reader->GetWarning(i));
  }
  return reader->GetOutputDataObject(0);
}

namespace
{

/** Point scalars to contour an image with: the active ones, else the first 1-component array. */
vtkDataArray* ContourScalars(vtkImageData* image)
{
  vtkPointData* pd = image->GetPointData();
  if (pd->GetScalars())
  {
    return pd->GetScalars();
  }
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (array && array->GetNumberOfComponents() == 1 && array->GetName())
    {
      return array;
    }
  }
  return nullptr;
}

/**
 * Otsu's threshold of component 0 of the array: the value that splits its values into the two
 * classes of largest between-class variance, over a 256-bin histogram of [lo, hi] (finite values
 * only). When several bin boundaries tie, the middle one is taken (two populations with a gap
 * between them are split in the middle of the gap). Returns false when there is nothing to
 * split (fewer than two distinct finite values).
 */
bool OtsuThreshold(vtkDataArray* array, double lo, double hi, double& threshold)
{
  constexpr int bins = 256;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi))
  {
    return false;
  }
  std::vector<double> histogram(bins, 0.0);
  const double scale = bins / (hi - lo);
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    const double v = array->GetComponent(i, 0);
    if (std::isfinite(v))
    {
      const int b = std::min(bins - 1, std::max(0, static_cast<int>((v - lo) * scale)));
      histogram[b] += 1.0;
    }
  }
  double total = 0.0, totalSum = 0.0;
  for (int b = 0; b < bins; ++b)
  {
    total += histogram[b];
    totalSum += histogram[b] * (b + 0.5);
  }
  // Between-class variance of a split after bin k: w0 w1 (mu0 - mu1)^2, in bin units.
  double w0 = 0.0, sum0 = 0.0, best = -1.0;
  int first = -1, last = -1;
  for (int k = 0; k < bins - 1; ++k)
  {
    w0 += histogram[k];
    sum0 += histogram[k] * (k + 0.5);
    const double w1 = total - w0;
    if (w0 <= 0.0 || w1 <= 0.0)
    {
      continue;
    }
    const double d = sum0 / w0 - (totalSum - sum0) / w1;
    const double variance = w0 * w1 * d * d;
    if (variance > best * (1.0 + 1e-12))
    {
      best = variance;
      first = last = k;
    }
    else if (variance >= best * (1.0 - 1e-12))
    {
      last = k;
    }
  }
  if (first < 0)
  {
    return false;
  }
  // The boundary after bin k is lo + (k + 1) / scale; the middle of the tied boundaries.
  threshold = lo + (0.5 * (first + last) + 1.0) / scale;
  return threshold > lo && threshold < hi;
}

vtkSmartPointer<vtkPolyData> ToSurface(vtkDataSet* input, const std::optional<double>& isoValue,
  const std::string& what, std::optional<double>& contourValue)
{
  vtkDataSet* ds = input; // (read by vtkStylizeReader: validated, finite points only)
  if (auto* pd = vtkPolyData::SafeDownCast(ds))
  {
    return pd;
  }
  ClearVTKErrors();
  vtkSmartPointer<vtkPolyData> surface;
  auto* image = vtkImageData::SafeDownCast(ds);
  int dims[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  vtkDataArray* scalars = image ? ContourScalars(image) : nullptr;
  if (image && scalars && dims[0] > 1 && dims[1] > 1 && dims[2] > 1)
  {
    double range[2];
    scalars->GetFiniteRange(range, 0);
    const std::string name = scalars->GetName() ? scalars->GetName() : "scalars";
    if (!(range[0] <= range[1]))
    {
      Fail(what + ": " + Quote(name) +
        " holds no finite value (NaN or infinity everywhere): " + "there is nothing to contour");
    }
    double iso = 0.5 * (range[0] + range[1]);
    if (isoValue)
    {
      iso = *isoValue;
    }
    else
    {
      // Otsu's threshold separates the two main populations of the values (object and
      // background); the middle of the range is the fallback (and it is what a constant
      // array gets, whose contour is empty).
      const bool otsu = OtsuThreshold(scalars, range[0], range[1], iso);
      if (!otsu)
      {
        iso = 0.5 * (range[0] + range[1]);
      }
      Note(what + ": contour of " + Quote(name) + " at " + FormatNumber(iso) + " (" +
        (otsu ? "Otsu's threshold" : "the middle") + " of its values in [" +
        FormatNumber(range[0]) + ", " + FormatNumber(range[1]) + "]; choose another with --iso)");
    }
    vtkNew<vtkContourFilter> contour;
    contour->SetInputData(image);
    contour->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, scalars->GetName());
    contour->SetValue(0, iso);
    contour->ComputeScalarsOff();
    contour->ComputeNormalsOn();
    contour->Update();
    CheckVTKErrors(what + ": contouring failed");
    surface = contour->GetOutput();
    contourValue = iso;
    if (surface->GetNumberOfCells() == 0)
    {
      Fail(what + ": the contour of " + Quote(name) + " at " + FormatNumber(iso) +
        " is empty (the scalar range is [" + FormatNumber(range[0]) + ", " +
        FormatNumber(range[1]) + "]; see --iso)");
    }
  }
  else
  {
    vtkNew<vtkDataSetSurfaceFilter> extract;
    extract->SetInputData(ds);
    extract->Update();
    CheckVTKErrors(what + ": surface extraction failed");
    surface = extract->GetOutput();
  }
  return surface;
}
} // namespace

/** Turns a data object (dataset or multiblock tree) into parts. */
void CollectParts(vtkDataObject* data, const std::optional<double>& isoValue,
  const std::string& what, std::vector<Part>& parts)
{
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkStylizeReader::ForEachBlock(composite,
      [&](vtkCompositeDataIterator* it, const std::string& name)
      {
        vtkDataObject* leaf = it->GetCurrentDataObject();
        if (vtkCompositeDataSet::SafeDownCast(leaf))
        {
          CollectParts(leaf, isoValue, what, parts);
          return;
        }
        auto* ds = vtkDataSet::SafeDownCast(leaf);
        if (!ds)
        {
          Fail(what + ": block " + Quote(name) + " is a " + leaf->GetClassName() +
            ", which cannot be rendered");
        }
        Part part{ name, nullptr, std::nullopt };
        part.Surface = ToSurface(ds, isoValue, what + " (block " + Quote(name) + ")", part.Contour);
        parts.push_back(part);
      });
    return;
  }
  auto* ds = vtkDataSet::SafeDownCast(data);
  if (!ds)
  {
    Fail(
      what + ": the data is a " + std::string(data->GetClassName()) + ", which cannot be rendered");
  }
  Part part{ std::string(), nullptr, std::nullopt };
  part.Surface = ToSurface(ds, isoValue, what, part.Contour);
  parts.push_back(part);
}

/** Drops empty parts, fails when nothing is left, adds normals where missing. */
void FinishParts(std::vector<Part>& parts, const std::string& what)
{
  vtkIdType points = 0;
  std::vector<Part> kept;
  for (Part& p : parts)
  {
    points += p.Surface->GetNumberOfPoints();
    if (p.Surface->GetNumberOfPoints() > 0 && p.Surface->GetNumberOfCells() > 0)
    {
      kept.push_back(p);
    }
  }
  if (points == 0)
  {
    Fail(what + ": the data contains no points");
  }
  if (kept.empty())
  {
    Fail(what + ": the data contains no cells (" + std::to_string(static_cast<long long>(points)) +
      " points but nothing to draw)");
  }
  ClearVTKErrors();
  for (Part& p : kept)
  {
    if (!p.Surface->GetPointData()->GetNormals() &&
      (p.Surface->GetNumberOfPolys() > 0 || p.Surface->GetNumberOfStrips() > 0))
    {
      vtkNew<vtkPolyDataNormals> normals;
      normals->SetInputData(p.Surface);
      normals->ConsistencyOn();
      normals->SplittingOn();
      normals->SetFeatureAngle(45.0);
      ReportProgress(normals, "normals");
      normals->Update();
      p.Surface = normals->GetOutput();
    }
  }
  CheckVTKErrors(what + ": computing normals failed");
  parts = kept;
}

void AddPrincipalDirections(
  std::vector<Part>& parts, const std::string& what, double smoothingRadius)
{
  ClearVTKErrors();
  for (Part& p : parts)
  {
    if (p.Surface->GetNumberOfPolys() > 0 || p.Surface->GetNumberOfStrips() > 0)
    {
      vtkNew<vtkStylizePrincipalCurvatures> curvatures;
      curvatures->SetInputData(p.Surface);
      curvatures->SetSmoothingRadius(smoothingRadius);
      ReportProgress(curvatures, "principal curvatures");
      curvatures->Update();
      p.Surface = curvatures->GetOutput();
    }
  }
  CheckVTKErrors(what + ": computing the principal curvatures failed");
}
} // namespace vtkstylize
