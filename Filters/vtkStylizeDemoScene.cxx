#include "vtkStylizeDemoScene.h"

#include "vtkAppendPolyData.h"
#include "vtkArrayCalculator.h"
#include "vtkContourFilter.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageGradient.h"
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
  place->Translate(20.0, 0.0, 0.0);
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

  // Block 2: streamline tubes of the wavelet gradient, coloured by speed.
  vtkNew<vtkPolyData> tubesOut;
  if (this->NumberOfStreamlines > 0)
  {
    vtkNew<vtkImageGradient> gradient;
    gradient->SetInputData(field);
    gradient->SetDimensionality(3);
    gradient->Update();
    vtkNew<vtkImageData> vectors;
    vectors->ShallowCopy(gradient->GetOutput());
    vectors->GetPointData()->SetActiveVectors(
      vectors->GetPointData()->GetScalars()->GetName());
    vtkNew<vtkLineSource> seeds;
    seeds->SetPoint1(-8.0, -8.0, -3.0);
    seeds->SetPoint2(8.0, 8.0, 3.0);
    seeds->SetResolution(std::max(1, this->NumberOfStreamlines - 1));
    vtkNew<vtkStreamTracer> tracer;
    tracer->SetInputData(vectors);
    tracer->SetSourceConnection(seeds->GetOutputPort());
    tracer->SetIntegrationDirectionToBoth();
    tracer->SetIntegratorTypeToRungeKutta45();
    tracer->SetMaximumPropagation(40.0);
    tracer->SetInitialIntegrationStep(0.2);
    tracer->SetComputeVorticity(false);
    vtkNew<vtkArrayCalculator> speed;
    speed->SetInputConnection(tracer->GetOutputPort());
    speed->SetAttributeTypeToPointData();
    speed->AddVectorArrayName(vectors->GetPointData()->GetScalars()->GetName());
    speed->SetFunction((std::string("mag(") + vectors->GetPointData()->GetScalars()->GetName() + ")").c_str());
    speed->SetResultArrayName("Speed");
    vtkNew<vtkTubeFilter> tubes;
    tubes->SetInputConnection(speed->GetOutputPort());
    tubes->SetRadius(0.25);
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
