#include "vtkStylizeFigureLayerSource.h"

#include "vtkContextActor.h"
#include "vtkContextScene.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkStylizeStylePass.h"
#include "vtkWindowToImageFilter.h"

#include <vector>

vtkStandardNewMacro(vtkStylizeFigureLayerSource);
vtkCxxSetObjectMacro(vtkStylizeFigureLayerSource, RenderWindow, vtkRenderWindow);

//------------------------------------------------------------------------------
vtkStylizeFigureLayerSource::~vtkStylizeFigureLayerSource()
{
  this->SetRenderWindow(nullptr);
}

//------------------------------------------------------------------------------
void vtkStylizeFigureLayerSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderWindow: " << this->RenderWindow << "\n";
}

//------------------------------------------------------------------------------
vtkStylizeStylePass* vtkStylizeFigureLayerSource::FindStylePass()
{
  if (!this->RenderWindow)
  {
    return nullptr;
  }
  vtkRendererCollection* renderers = this->RenderWindow->GetRenderers();
  renderers->InitTraversal();
  while (vtkRenderer* ren = renderers->GetNextItem())
  {
    if (auto* style = vtkStylizeStylePass::SafeDownCast(ren->GetPass()))
    {
      return style;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
vtkRenderer* vtkStylizeFigureLayerSource::FindStyleRenderer()
{
  vtkStylizeStylePass* style = this->FindStylePass();
  vtkRendererCollection* renderers =
    this->RenderWindow ? this->RenderWindow->GetRenderers() : nullptr;
  if (!style || !renderers)
  {
    return nullptr;
  }
  renderers->InitTraversal();
  while (vtkRenderer* ren = renderers->GetNextItem())
  {
    if (ren->GetPass() == style)
    {
      return ren;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
void vtkStylizeFigureLayerSource::RenderFrame()
{
  if (this->RenderWindow)
  {
    this->RenderWindow->Render();
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeFigureLayerSource::CaptureLayer(
  int layer, const double* key, int magnification, vtkImageData* out)
{
  vtkStylizeStylePass* style = this->FindStylePass();
  vtkRenderWindow* window = this->RenderWindow;
  if (!style || !window)
  {
    return false;
  }
  const int previous = style->SwapLayer(layer);
  struct Saved
  {
    vtkRenderer* Renderer;
    double Background[3];
    bool Gradient;
    bool Textured;
  };
  std::vector<Saved> saved;
  if (key)
  {
    vtkRendererCollection* renderers = window->GetRenderers();
    renderers->InitTraversal();
    while (vtkRenderer* ren = renderers->GetNextItem())
    {
      Saved s{ ren, { 0, 0, 0 }, ren->GetGradientBackground(), ren->GetTexturedBackground() };
      ren->GetBackground(s.Background);
      saved.push_back(s);
      ren->SetBackground(key[0], key[1], key[2]);
      ren->GradientBackgroundOff();
      ren->TexturedBackgroundOff();
    }
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOn();
  grab->SetScale(magnification);
  grab->Update();
  out->DeepCopy(grab->GetOutput());
  for (const Saved& s : saved)
  {
    s.Renderer->SetBackground(s.Background);
    s.Renderer->SetGradientBackground(s.Gradient);
    s.Renderer->SetTexturedBackground(s.Textured);
  }
  style->SwapLayer(previous);
  return out->GetNumberOfPoints() > 0;
}

//------------------------------------------------------------------------------
bool vtkStylizeFigureLayerSource::PaintContextOverlay(
  vtkProp* actor, vtkViewport* viewport, vtkContext2D* painter)
{
  auto* contextActor = vtkContextActor::SafeDownCast(actor);
  vtkContextScene* scene = contextActor ? contextActor->GetScene() : nullptr;
  if (!scene || !painter)
  {
    return false;
  }
  if (auto* renderer = vtkRenderer::SafeDownCast(viewport))
  {
    scene->SetRenderer(renderer);
  }
  scene->Paint(painter);
  return true;
}
