#include "vtkStylizeDepthPeeler.h"

#include "vtkCameraPass.h"
#include "vtkInformation.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShaderProgram.h"
#include "vtkStylizeGBufferClearPass.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeGBufferTransfer.h"
#include "vtkStylizeRankCompositor.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkStylizeDepthPeeler);

using Part = vtkStylizeRankCompositor::Part;

//------------------------------------------------------------------------------
vtkStylizeDepthPeeler::vtkStylizeDepthPeeler()
{
  this->ClearPass = vtkStylizeGBufferClearPass::New();
  this->ClearPass->Layer = true;
  this->LayerSequence = vtkSequencePass::New();
}

//------------------------------------------------------------------------------
vtkStylizeDepthPeeler::~vtkStylizeDepthPeeler()
{
  vtkStylizeShaderUtilities::FreeTexture(this->PeelDepthTexture, nullptr);
  this->LayerSequence->Delete();
  this->ClearPass->Delete();
}

//------------------------------------------------------------------------------
void vtkStylizeDepthPeeler::SetLayerPasses(vtkRenderPass* lights, vtkRenderPass* translucent)
{
  vtkNew<vtkRenderPassCollection> layer;
  layer->AddItem(this->ClearPass);
  layer->AddItem(lights);
  layer->AddItem(translucent);
  this->LayerSequence->SetPasses(layer);
}

//------------------------------------------------------------------------------
vtkStylizeGBufferClearPass* vtkStylizeDepthPeeler::GetClearPass()
{
  return this->ClearPass;
}

//------------------------------------------------------------------------------
bool vtkStylizeDepthPeeler::HasTranslucentGeometry(const vtkRenderState* s)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (prop && prop->GetVisibility() && prop->HasTranslucentPolygonalGeometry())
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkStylizeDepthPeeler::RenderLayer(
  const vtkRenderState* s, vtkStylizeGBufferPass* gbuffer, vtkStylizeGBufferPass* opaque, int index)
{
  if (!opaque || !opaque->GetDepthTexture() || index < 0 ||
    (index > 0 && !gbuffer->GetDepthTexture()))
  {
    return false;
  }
  vtkRenderPass* image = gbuffer->SceneImagePass;
  gbuffer->SceneImagePass = nullptr; // a layer always comes from the geometry
  this->LayerIndex = index;
  this->Opaque = opaque;
  this->OpaqueDepth = opaque->GetDepthTexture();
  this->HasSamples = false;
  this->ClearPass->UseImageBackground = opaque->GetImageBackgroundApplied();
  for (int i = 0; i < 3; ++i)
  {
    this->ClearPass->ImageBackground[i] = static_cast<float>(opaque->GetImageBackground()[i]);
  }
  // Several processes (ParaView's render ranks), each with its own props: every one peels in
  // front of the composited opaque depth and behind the whole scene's previous layer, and the
  // layer is composited by depth to process 0.
  vtkMultiProcessController* controller = opaque->GetController();
  const bool distributed = controller && controller->GetNumberOfProcesses() > 1;
  this->Compositor->SetController(distributed ? controller : nullptr);
  if (distributed && index == 0)
  {
    this->ShareOpaqueDepth(opaque);
  }
  bool rendered = gbuffer->RenderGeometry(s);
  if (distributed)
  {
    // (the answer is every process's, so that all of them go on to the next layer or stop)
    this->HasSamples = this->CompositeLayer(gbuffer, rendered);
    rendered = true;
  }
  this->Compositor->SetController(nullptr);
  this->LayerIndex = -1;
  this->Opaque = nullptr;
  this->OpaqueDepth = nullptr;
  gbuffer->SceneImagePass = image;
  return rendered && this->HasSamples;
}

//------------------------------------------------------------------------------
void vtkStylizeDepthPeeler::SwapPeelDepth(vtkTextureObject*& depth)
{
  if (this->LayerIndex > 0)
  {
    std::swap(depth, this->PeelDepthTexture);
  }
}

//------------------------------------------------------------------------------
void vtkStylizeDepthPeeler::AllocatePeelDepth(vtkOpenGLRenderWindow* renWin, int w, int h)
{
  if (this->LayerIndex > 0)
  {
    vtkStylizeShaderUtilities::EnsureScreenTexture(
      this->PeelDepthTexture, renWin, w, h, GL_DEPTH_COMPONENT32F, false);
  }
}

//------------------------------------------------------------------------------
void vtkStylizeDepthPeeler::Begin(const vtkRenderState* s, vtkCameraPass* camera)
{
  vtkOpenGLRenderWindow* renWin =
    static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  camera->SetDelegatePass(this->LayerSequence);
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    // Translucent actors write the depth (as vtkSSAOPass has them do): each pixel keeps one
    // surface, the nearest the shaders let through.
    vtkProp* prop = s->GetPropArray()[i];
    vtkInformation* info = prop ? prop->GetPropertyKeys() : nullptr;
    if (info)
    {
      info->Set(vtkOpenGLActor::GLDepthMaskOverride(), 1);
    }
  }
  this->Blend = ostate->GetEnumState(GL_BLEND);
  ostate->vtkglDisable(GL_BLEND);
  this->OpaqueDepth->Activate();
  if (this->LayerIndex > 0)
  {
    this->PeelDepthTexture->Activate();
  }
  if (!this->Query)
  {
    glGenQueries(1, &this->Query);
  }
  glBeginQuery(GL_ANY_SAMPLES_PASSED, this->Query);
}

//------------------------------------------------------------------------------
void vtkStylizeDepthPeeler::End(
  const vtkRenderState* s, vtkCameraPass* camera, vtkRenderPass* geometry)
{
  vtkOpenGLRenderWindow* renWin =
    static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow());
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  GLuint samples = 0;
  glGetQueryObjectuiv(this->Query, GL_QUERY_RESULT, &samples);
  this->HasSamples = samples != 0;
  if (this->LayerIndex > 0)
  {
    this->PeelDepthTexture->Deactivate();
  }
  this->OpaqueDepth->Deactivate();
  if (this->Blend)
  {
    renWin->GetState()->vtkglEnable(GL_BLEND);
  }
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    vtkInformation* info = prop ? prop->GetPropertyKeys() : nullptr;
    if (info)
    {
      info->Remove(vtkOpenGLActor::GLDepthMaskOverride());
    }
  }
  camera->SetDelegatePass(geometry);
}

//------------------------------------------------------------------------------
std::string vtkStylizeDepthPeeler::FragmentCode(
  std::string& fragmentShader, const std::string& depth) const
{
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
    "//VTK::System::Dec\nuniform sampler2D stylizeOpaqueDepth;\n"
    "uniform sampler2D stylizePeelDepth;\nuniform int stylizePeel;\n",
    false);
  return "  {\n"
         "    ivec2 stylizeTexel = ivec2(gl_FragCoord.xy);\n"
         "    float stylizeZ = " +
    depth +
    ";\n"
    "    if (stylizeZ > texelFetch(stylizeOpaqueDepth, stylizeTexel, 0).r ||\n"
    "      (stylizePeel == 1 && stylizeZ <= texelFetch(stylizePeelDepth, stylizeTexel, 0).r))\n"
    "    {\n"
    "      discard;\n"
    "    }\n"
    "  }\n";
}

//------------------------------------------------------------------------------
void vtkStylizeDepthPeeler::SetShaderParameters(vtkShaderProgram* program)
{
  if (this->LayerIndex >= 0 && program->IsUniformUsed("stylizeOpaqueDepth"))
  {
    program->SetUniformi("stylizeOpaqueDepth", this->OpaqueDepth->GetTextureUnit());
    const bool peel = this->LayerIndex > 0;
    program->SetUniformi("stylizePeel", peel ? 1 : 0);
    program->SetUniformi(
      "stylizePeelDepth", (peel ? this->PeelDepthTexture : this->OpaqueDepth)->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
void vtkStylizeDepthPeeler::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkStylizeShaderUtilities::FreeTexture(this->PeelDepthTexture, w);
  this->LayerSequence->ReleaseGraphicsResources(w);
  if (this->Query && w)
  {
    // (the context is current while VTK releases graphics resources)
    glDeleteQueries(1, &this->Query);
  }
  this->Query = 0;
}

//------------------------------------------------------------------------------
void vtkStylizeDepthPeeler::ShareOpaqueDepth(vtkStylizeGBufferPass* opaque)
{
  // Every process's opaque G-buffer has process 0's size (the same view on every rank).
  const int w = opaque->GetGeometrySize()[0];
  const int h = opaque->GetGeometrySize()[1];
  vtkMultiProcessController* controller = this->Compositor->GetController();
  const bool root = controller->GetLocalProcessId() == 0;
  Part part;
  if (root)
  {
    vtkStylizeGBufferTransfer::ReadPart(opaque, part, std::vector<int>(), w, h);
  }
  this->Compositor->BroadcastDepth(part, w, h);
  if (!root && opaque->GetDepthTexture())
  {
    std::vector<float> whole(static_cast<size_t>(w) * h, 1.0f);
    for (int y = 0; y < part.Rect[3]; ++y)
    {
      std::copy_n(&part.Depth[static_cast<size_t>(y) * part.Rect[2]], part.Rect[2],
        &whole[static_cast<size_t>(y + part.Rect[1]) * w + part.Rect[0]]);
    }
    const int rect[4] = { 0, 0, w, h };
    vtkStylizeGBufferTransfer::UploadTexels(
      opaque->GetDepthTexture(), rect, vtkStylizeGBufferPass::DEPTH_BUFFER, whole.data());
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeDepthPeeler::CompositeLayer(vtkStylizeGBufferPass* gbuffer, bool rendered)
{
  const int w = gbuffer->GetGeometrySize()[0];
  const int h = gbuffer->GetGeometrySize()[1];
  const bool root = this->Compositor->GetController()->GetLocalProcessId() == 0;
  rendered = rendered && this->HasSamples;
  std::vector<int> buffers; // every channel the layer holds
  for (int buffer : { vtkStylizeGBufferPass::COLOR_BUFFER, vtkStylizeGBufferPass::NORMAL_BUFFER,
         vtkStylizeGBufferPass::POSITION_BUFFER, vtkStylizeGBufferPass::LINEAR_DEPTH_BUFFER,
         vtkStylizeGBufferPass::DIRECTION_BUFFER })
  {
    if (gbuffer->GetBufferTexture(buffer))
    {
      buffers.push_back(buffer);
    }
  }
  const std::vector<int> components = vtkStylizeGBufferTransfer::ComponentsOf(buffers);
  // 1. The other processes' layers, nearest by depth, to process 0.
  Part others;
  if (!root && rendered)
  {
    vtkStylizeGBufferTransfer::ReadPart(gbuffer, others, buffers, w, h);
  }
  this->Compositor->Reduce(others, components, w, h);

  // 2. Process 0 lays them into its own layer where they are nearer (its own pixels read over
  // the union, its background included) and keeps the result in its textures.
  Part layer;
  if (root)
  {
    Part mine;
    if (rendered)
    {
      vtkStylizeGBufferTransfer::ReadPart(gbuffer, mine, std::vector<int>(), w, h);
    }
    int bounds[4];
    vtkStylizeRankCompositor::UnionRect(mine.Rect, others.Rect, bounds);
    if (bounds[2] > 0 && bounds[3] > 0 && gbuffer->GetDepthTexture())
    {
      vtkStylizeGBufferTransfer::ReadPart(gbuffer, layer, buffers, w, h, bounds);
      if (others.Area() > 0)
      {
        vtkStylizeRankCompositor::Paste(layer, others, components, true);
      }
      for (size_t c = 0; c < buffers.size(); ++c)
      {
        vtkStylizeGBufferTransfer::UploadTexels(
          gbuffer->GetBufferTexture(buffers[c]), layer.Rect, buffers[c], layer.Channels[c].data());
      }
      vtkStylizeGBufferTransfer::UploadTexels(gbuffer->GetDepthTexture(), layer.Rect,
        vtkStylizeGBufferPass::DEPTH_BUFFER, layer.Depth.data());
    }
  }

  // 3. Every process peels the next layer behind this one: the layer's depth from process 0.
  this->Compositor->BroadcastDepth(layer, w, h);
  if (!root && gbuffer->GetDepthTexture())
  {
    vtkStylizeGBufferTransfer::UploadTexels(gbuffer->GetDepthTexture(), layer.Rect,
      vtkStylizeGBufferPass::DEPTH_BUFFER, layer.Depth.data());
  }
  return layer.Area() > 0;
}
