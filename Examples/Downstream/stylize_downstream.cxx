// Renders a sphere with the Comic lighting model through the G-buffer and writes a PNG.
#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkStylizeGBufferPass.h>
#include <vtkStylizeLightingPass.h>
#include <vtkWindowToImageFilter.h>

int main(int argc, char* argv[])
{
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(200, 200);
  window->AddRenderer(renderer);

  vtkNew<vtkStylizeLightingPass> lighting;
  lighting->SetModelToComic();
  vtkNew<vtkStylizeGBufferPass> gbuffer;
  gbuffer->SetLightingPass(lighting);
  renderer->SetPass(gbuffer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(argc > 1 ? argv[1] : "downstream.png");
  writer->SetInputConnection(capture->GetOutputPort());
  writer->Write();
  window->Finalize();
  return 0;
}
