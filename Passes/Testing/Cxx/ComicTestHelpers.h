// The comic tests' shared scene (the standard test objects through a comic pass), gray levels
// and the side-lit scene of the tone and hatch tests.
#ifndef ComicTestHelpers_h
#define ComicTestHelpers_h

#include "vtkComicPass.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeTestUtilities.h"

namespace stylizetest
{
constexpr int W = 400, H = 300;

using Configure = std::function<void(vtkRenderer*, vtkComicPass*)>;

/** The standard test scene through a comic pass (1 point = 1 pixel at h rows). */
inline vtkSmartPointer<vtkImageData> RenderComic(const Configure& configure, int w = W, int h = H,
  int magnify = 1, double scale = 1.0, bool parallel = false)
{
  return RenderThroughPass<vtkComicPass>(configure, w, h, parallel, magnify, scale,
    [h](vtkComicPass* comic) { comic->SetReferenceHeight(h); });
}

/**
 * The object-space (= world: the test actors are untransformed) positions of a frame from the
 * G-buffer (4 components, w = 1 on surfaces), the renderer's pass restored after.
 */
inline void RenderPositions(vtkRenderer* ren, vtkRenderWindow* win, vtkFloatArray* out)
{
  vtkNew<vtkStylizeGBufferPass> g;
  g->SetChannels(vtkStylizeGBufferPass::POSITION);
  g->SetPositionSpace(vtkStylizeGBufferPass::OBJECT);
  vtkSmartPointer<vtkRenderPass> previous = ren->GetPass();
  ren->SetPass(g);
  win->Render();
  g->DownloadChannel(vtkStylizeGBufferPass::POSITION_BUFFER, out);
  g->ReleaseGraphicsResources(win);
  ren->SetPass(previous);
}

/** Gray value (0..255) of pixel i of an RGB image. */
inline double Gray(vtkImageData* img, vtkIdType i)
{
  vtkDataArray* s = img->GetPointData()->GetScalars();
  return (s->GetComponent(i, 0) + s->GetComponent(i, 1) + s->GetComponent(i, 2)) / 3.0;
}

/**
 * A w x h window on white with one actor of `source` (no specular) lit by one scene light at
 * (x, 0, z), pointing at the origin.
 */
inline TestScene MakeSideLitScene(int w, int h, vtkPolyDataAlgorithm* source, double x, double z)
{
  TestScene scene;
  scene.Window = MakeWindow(w, h);
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scene.Window->AddRenderer(scene.Renderer);
  scene.Renderer->SetBackground(1, 1, 1);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetSpecular(0.0);
  scene.Renderer->AddActor(actor);
  scene.Renderer->RemoveAllLights();
  scene.Renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(x, 0.0, z);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  scene.Renderer->AddLight(light);
  return scene;
}
}

#endif
