#include "vtkStylizeStylePass.h"

#include "vtkStylizeGBufferPass.h"

//------------------------------------------------------------------------------
vtkStylizeStylePass::vtkStylizeStylePass() = default;

//------------------------------------------------------------------------------
vtkStylizeStylePass::~vtkStylizeStylePass() = default;

//------------------------------------------------------------------------------
void vtkStylizeStylePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scene: "
     << (this->DelegatePass ? "the delegate's image (colour and depth)" : "the geometry") << "\n";
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::RenderScene(const vtkRenderState* s, int channels)
{
  vtkStylizeGBufferPass* gbuffer = this->GetGBufferPass();
  gbuffer->SetSceneImagePass(this->DelegatePass);
  gbuffer->SetChannels(channels);
  if (!gbuffer->RenderGeometry(s))
  {
    this->FinishScene(s);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::FinishScene(const vtkRenderState* s)
{
  vtkStylizeGBufferPass* gbuffer = this->GetGBufferPass();
  gbuffer->RenderAfterGeometry(s);
  this->NumberOfRenderedProps = gbuffer->GetNumberOfRenderedProps();
}
