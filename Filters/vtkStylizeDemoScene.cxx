#include "vtkStylizeDemoScene.h"

#include "vtkAppendPolyData.h"
#include "vtkArrayCalculator.h"
#include "vtkContourFilter.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLineSource.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkRTAnalyticSource.h"
#include "vtkStreamTracer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkTubeFilter.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkStylizeDemoScene);

//------------------------------------------------------------------------------
vtkStylizeDemoScene::vtkStylizeDemoScene()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
void vtkStylizeDemoScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "NumberOfStreamlines: " << this->NumberOfStreamlines << "\n";
}

//------------------------------------------------------------------------------
int vtkStylizeDemoScene::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
  const int half = std::max(8, static_cast<int>(std::lround(20 * this->Resolution)));

  // Block 0: isosurface of the wavelet.
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-half, half, -half, half, -half, half);
  wavelet->SetCenter(0, 0, 0);
  wavelet->Update();
  // Sample spacing so that the wavelet spans [-10, 10] whatever the resolution.
  vtkNew<vtkImageData> field;
  field->ShallowCopy(wavelet->GetOutput());
  const double spacing = 10.0 / half;
  field->SetSpacing(spacing, spacing, spacing);
  field->SetOrigin(0, 0, 0);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(field);
  contour->SetValue(0, this->IsoValue);
  contour->ComputeScalarsOn();
  vtkNew<vtkPolyDataNormals> isoNormals;
  isoNormals->SetInputConnection(contour->GetOutputPort());
  isoNormals->SplittingOff();
  isoNormals->ConsistencyOn();
  isoNormals->Update();
  vtkNew<vtkPolyData> iso;
  iso->ShallowCopy(isoNormals->GetOutput());
  // Block 1: a parametric torus beside the isosurface.
  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(5.0);
  torus->SetCrossSectionRadius(1.8);
  vtkNew<vtkParametricFunctionSource> surface;
  surface->SetParametricFunction(torus);
  const int ures = std::max(16, static_cast<int>(std::lround(96 * this->Resolution)));
  surface->SetUResolution(ures);
  surface->SetVResolution(std::max(8, ures / 2));
  surface->SetScalarModeToNone();
  surface->GenerateNormalsOn();
  vtkNew<vtkTransform> place;
  place->Translate(24.0, 0.0, 0.0);
  place->RotateX(60.0);
  vtkNew<vtkTransformPolyDataFilter> placed;
  placed->SetInputConnection(surface->GetOutputPort());
  placed->SetTransform(place);
  vtkNew<vtkArrayCalculator> height;
  height->SetInputConnection(placed->GetOutputPort());
  height->SetAttributeTypeToPointData();
  height->AddCoordinateScalarVariable("coordsZ", 2);
  height->SetFunction("coordsZ");
  height->SetResultArrayName("Height");
  height->Update();
  vtkNew<vtkPolyData> param;
  param->ShallowCopy(height->GetOutput());

  // Block 2: streamline tubes of a swirling flow around the isosurface (a rotation about the z
  // axis plus an upward drift, v = (-y, x, 2)), coloured by speed.
  vtkNew<vtkPolyData> tubesOut;
  if (this->NumberOfStreamlines > 0)
  {
    const int n = std::max(9, static_cast<int>(std::lround(16 * this->Resolution)));
    vtkNew<vtkImageData> flow;
    flow->SetDimensions(n, n, n);
    const double h = 28.0 / (n - 1);
    flow->SetOrigin(-14.0, -14.0, -14.0);
    flow->SetSpacing(h, h, h);
    vtkNew<vtkFloatArray> velocity;
    velocity->SetName("Velocity");
    velocity->SetNumberOfComponents(3);
    velocity->SetNumberOfTuples(flow->GetNumberOfPoints());
    for (vtkIdType i = 0; i < flow->GetNumberOfPoints(); ++i)
    {
      double p[3];
      flow->GetPoint(i, p);
      velocity->SetTuple3(i, -p[1], p[0], 2.0);
    }
    flow->GetPointData()->SetVectors(velocity);
    vtkNew<vtkLineSource> seeds;
    seeds->SetPoint1(10.5, 0.0, -11.0);
    seeds->SetPoint2(13.0, 0.0, -11.0);
    seeds->SetResolution(std::max(1, this->NumberOfStreamlines - 1));
    vtkNew<vtkStreamTracer> tracer;
    tracer->SetInputData(flow);
    tracer->SetSourceConnection(seeds->GetOutputPort());
    tracer->SetIntegrationDirectionToForward();
    tracer->SetIntegratorTypeToRungeKutta45();
    tracer->SetMaximumPropagation(150.0);
    tracer->SetInitialIntegrationStep(0.2);
    tracer->SetComputeVorticity(false);
    vtkNew<vtkArrayCalculator> speed;
    speed->SetInputConnection(tracer->GetOutputPort());
    speed->SetAttributeTypeToPointData();
    speed->AddVectorArrayName("Velocity");
    speed->SetFunction("mag(Velocity)");
    speed->SetResultArrayName("Speed");
    vtkNew<vtkTubeFilter> tubes;
    tubes->SetInputConnection(speed->GetOutputPort());
    tubes->SetRadius(0.22);
    tubes->SetNumberOfSides(std::max(6, static_cast<int>(std::lround(12 * this->Resolution))));
    tubes->CappingOn();
    vtkNew<vtkTriangleFilter> tris;
    tris->SetInputConnection(tubes->GetOutputPort());
    tris->Update();
    tubesOut->ShallowCopy(tris->GetOutput());
    tubesOut->GetPointData()->SetActiveScalars("Speed");
  }

  output->SetNumberOfBlocks(3);
  output->SetBlock(0, iso);
  output->SetBlock(1, param);
  output->SetBlock(2, tubesOut);
  output->GetMetaData(0u)->Set(vtkMultiBlockDataSet::NAME(), "isosurface");
  output->GetMetaData(1u)->Set(vtkMultiBlockDataSet::NAME(), "parametric");
  output->GetMetaData(2u)->Set(vtkMultiBlockDataSet::NAME(), "streamlines");
  return 1;
}
