#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeStylePass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkFloatArray.h"
#include "vtkHomogeneousTransform.h"
#include "vtkLightsPass.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkOverlayPass.h"
#include "vtkProperty.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkSequencePass.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkStylizeDepthPeeler.h"
#include "vtkStylizeGBufferClearPass.h"
#include "vtkStylizeGBufferImagePath.h"
#include "vtkStylizeGBufferPassInternals.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkTextureObject.h"
#include "vtkTransform.h"
#include "vtkTranslucentPass.h"
#include "vtkVolumetricPass.h"
#include "vtk_glew.h"

#include "vtkStylizeCompositeFS.h"
#include "vtkStylizeDepthFS.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <sstream>
#include <vector>

namespace
{
/**
 * Maps the camera's normalized device coordinates by x' = sx x + tx, y' = sy y + ty while it
 * lives (through the camera's user transform, composed after the user's own), then restores it.
 */
class ScopedScreenTransform
{
public:
  ScopedScreenTransform(vtkCamera* camera, const double t[4])
  {
    if (!camera || (t[0] == 1.0 && t[1] == 1.0 && t[2] == 0.0 && t[3] == 0.0))
    {
      return;
    }
    for (int i = 0; i < 4; ++i)
    {
      if (!std::isfinite(t[i]) || (i < 2 && !(t[i] > 0.0)))
      {
        return;
      }
    }
    this->Camera = camera;
    this->Saved = camera->GetUserTransform();
    vtkNew<vtkMatrix4x4> m;
    m->SetElement(0, 0, t[0]);
    m->SetElement(1, 1, t[1]);
    m->SetElement(0, 3, t[2]);
    m->SetElement(1, 3, t[3]);
    vtkNew<vtkTransform> transform;
    transform->SetMatrix(m);
    if (this->Saved)
    {
      transform->Concatenate(this->Saved->GetMatrix());
    }
    camera->SetUserTransform(transform);
  }
  ~ScopedScreenTransform()
  {
    if (this->Camera)
    {
      this->Camera->SetUserTransform(this->Saved);
    }
  }
  ScopedScreenTransform(const ScopedScreenTransform&) = delete;
  ScopedScreenTransform& operator=(const ScopedScreenTransform&) = delete;

private:
  vtkCamera* Camera = nullptr;
  vtkSmartPointer<vtkHomogeneousTransform> Saved;
};

/**
 * Lines and points at their width in points: a tiled (magnified) screenshot renders each tile at
 * the window's size, where VTK's LineWidth and PointSize are pixels; times the tile scale while
 * this lives, they keep their share of the picture (a 2 px streamline of a 3x screenshot is
 * 6 px wide, as in the window). Each actor's property is scaled once and restored.
 */
class ScopedTileWidths
{
public:
  ScopedTileWidths(vtkRenderer* ren, vtkProp** props, int count)
  {
    int scale[2] = { 1, 1 };
    if (ren->GetRenderWindow())
    {
      ren->GetRenderWindow()->GetTileScale(scale);
    }
    const double k = std::max(scale[0], scale[1]);
    for (int i = 0; i < count && k > 1.0; ++i)
    {
      vtkActor* actor = vtkActor::SafeDownCast(props[i]);
      vtkProperty* p = actor ? actor->GetProperty() : nullptr;
      if (!p ||
        std::find_if(this->Saved.begin(), this->Saved.end(),
          [p](const Entry& e) { return e.Property == p; }) != this->Saved.end())
      {
        continue;
      }
      this->Saved.push_back({ p, p->GetLineWidth(), p->GetPointSize() });
      p->SetLineWidth(static_cast<float>(k * p->GetLineWidth()));
      p->SetPointSize(static_cast<float>(k * p->GetPointSize()));
    }
  }
  ~ScopedTileWidths()
  {
    for (const Entry& e : this->Saved)
    {
      e.Property->SetLineWidth(e.LineWidth);
      e.Property->SetPointSize(e.PointSize);
    }
  }
  ScopedTileWidths(const ScopedTileWidths&) = delete;
  ScopedTileWidths& operator=(const ScopedTileWidths&) = delete;

private:
  struct Entry
  {
    vtkProperty* Property;
    float LineWidth;
    float PointSize;
  };
  std::vector<Entry> Saved;
};
}

vtkStandardNewMacro(vtkStylizeGBufferPass);
vtkCxxSetObjectMacro(vtkStylizeGBufferPass, LightingPass, vtkStylizeLightingPass);
vtkCxxSetObjectMacro(vtkStylizeGBufferPass, SceneImagePass, vtkRenderPass);
vtkCxxSetObjectMacro(vtkStylizeGBufferPass, ChannelSource, vtkStylizeGBufferPass);

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::SetImageBackground(double r, double g, double b)
{
  const double in[3] = { r, g, b };
  double rgb[3];
  for (int i = 0; i < 3; ++i)
  {
    rgb[i] = std::isnan(in[i]) ? 0.0 : std::min(1.0, std::max(0.0, in[i]));
  }
  if (rgb[0] != this->ImageBackground[0] || rgb[1] != this->ImageBackground[1] ||
    rgb[2] != this->ImageBackground[2])
  {
    std::copy(rgb, rgb + 3, this->ImageBackground);
    this->Modified();
  }
}
vtkCxxSetObjectMacro(vtkStylizeGBufferPass, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
vtkStylizeGBufferPass::vtkStylizeGBufferPass()
  : Internals(new vtkInternals)
{
  this->GeometryCameraPass = vtkCameraPass::New();
  this->GeometrySequence = vtkSequencePass::New();
  vtkNew<vtkRenderPassCollection> geometry;
  vtkNew<vtkLightsPass> lights;
  vtkNew<vtkOpaquePass> opaque;
  geometry->AddItem(this->Internals->ClearPass);
  geometry->AddItem(lights);
  geometry->AddItem(opaque);
  this->GeometrySequence->SetPasses(geometry);
  this->GeometryCameraPass->SetDelegatePass(this->GeometrySequence);

  this->AfterSequence = vtkSequencePass::New();
  vtkNew<vtkRenderPassCollection> after;
  vtkNew<vtkTranslucentPass> translucent;
  vtkNew<vtkVolumetricPass> volumetric;
  after->AddItem(translucent);
  after->AddItem(volumetric);
  this->AfterSequence->SetPasses(after);
  this->VolumeSequence = vtkSequencePass::New();
  vtkNew<vtkRenderPassCollection> volumes;
  volumes->AddItem(volumetric);
  this->VolumeSequence->SetPasses(volumes);
  this->Internals->Peeler->SetLayerPasses(lights, translucent);
  this->OverlayPass = vtkOverlayPass::New();
  this->AnnotationSequence = vtkSequencePass::New();
  vtkNew<vtkRenderPassCollection> annotations;
  vtkNew<vtkOpaquePass> annotationOpaque;
  vtkNew<vtkTranslucentPass> annotationTranslucent;
  annotations->AddItem(annotationOpaque);
  annotations->AddItem(annotationTranslucent);
  annotations->AddItem(volumetric); // (the volumes a channel source left out)
  this->AnnotationSequence->SetPasses(annotations);
  this->ShaderStageTime.Modified();
}

//------------------------------------------------------------------------------
vtkStylizeGBufferPass::~vtkStylizeGBufferPass()
{
  this->SetLightingPass(nullptr);
  this->SetSceneImagePass(nullptr);
  this->SetChannelSource(nullptr);
  this->SetController(nullptr);
  this->FreeTextures(nullptr);
  this->GeometryCameraPass->Delete();
  this->GeometrySequence->Delete();
  this->AfterSequence->Delete();
  this->VolumeSequence->Delete();
  this->OverlayPass->Delete();
  this->AnnotationSequence->Delete();
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Channels: " << ((this->Channels & NORMAL) ? "normal " : "")
     << ((this->Channels & POSITION) ? "position " : "")
     << ((this->Channels & LINEAR_DEPTH) ? "linear-depth " : "")
     << ((this->Channels & DIRECTION) ? "direction" : "") << "\n";
  os << indent << "Precision: " << (this->Precision == FULL ? "full" : "half") << "\n";
  os << indent << "NormalPrecision: " << (this->NormalPrecision == FULL ? "full" : "half") << "\n";
  os << indent << "PositionSpace: " << (this->PositionSpace == VIEW ? "view" : "object") << "\n";
  os << indent << "Viewport: " << this->Viewport[0] << " " << this->Viewport[1] << " "
     << this->Viewport[2] << " " << this->Viewport[3] << "\n";
  os << indent << "LightingPass: " << (this->LightingPass ? "set" : "(none: VTK lighting)") << "\n";
  os << indent << "ChannelSource: " << (this->ChannelSource ? "set" : "(none)") << "\n";
  os << indent << "ImageBackground: " << this->ImageBackground[0] << " " << this->ImageBackground[1]
     << " " << this->ImageBackground[2] << (this->UseImageBackground ? " (used)" : " (off)")
     << "\n";
  os << indent
     << "Controller: " << (this->Controller ? this->Controller->GetNumberOfProcesses() : 1)
     << " process(es)\n";
  os << indent << "SceneImagePass: "
     << (this->SceneImagePass ? this->SceneImagePass->GetClassName() : "(none: the geometry)")
     << "\n";
  os << indent << "GeometryResolution: " << this->GeometryResolution[0] << " x "
     << this->GeometryResolution[1] << (this->GeometryResolution[0] > 0 ? "" : " (viewport)")
     << "\n";
  os << indent << "GeometryScreenTransform: " << this->GeometryScreenTransform[0] << " "
     << this->GeometryScreenTransform[1] << " " << this->GeometryScreenTransform[2] << " "
     << this->GeometryScreenTransform[3] << "\n";
  os << indent << "AfterScreenShift: " << this->AfterScreenShift[0] << " "
     << this->AfterScreenShift[1] << "\n";
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::SetGeometryResolution(int w, int h)
{
  w = std::max(0, w);
  h = std::max(0, h);
  if (w != this->GeometryResolution[0] || h != this->GeometryResolution[1])
  {
    this->GeometryResolution[0] = w;
    this->GeometryResolution[1] = h;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::SetGeometryScreenTransform(double sx, double sy, double tx, double ty)
{
  const double t[4] = { sx, sy, tx, ty };
  if (!std::isfinite(sx) || !std::isfinite(sy) || !std::isfinite(tx) || !std::isfinite(ty) ||
    !(sx > 0.0) || !(sy > 0.0))
  {
    return;
  }
  std::copy(t, t + 4, this->GeometryScreenTransform);
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::SetAfterScreenShift(double tx, double ty)
{
  if (std::isfinite(tx) && std::isfinite(ty))
  {
    this->AfterScreenShift[0] = tx;
    this->AfterScreenShift[1] = ty;
  }
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::AllocateTextures(vtkOpenGLRenderWindow* renWin, int w, int h)
{
  // Precision per channel: the colour at Precision, the normal and direction channels at the
  // larger of Precision and NormalPrecision.
  const int normalPrecision = std::max(this->Precision, this->NormalPrecision);
  const bool colorChanged = this->AllocatedPrecision != this->Precision;
  const bool normalChanged = this->AllocatedNormalPrecision != normalPrecision;
  this->AllocatedPrecision = this->Precision;
  this->AllocatedNormalPrecision = normalPrecision;
  const int colorFormat = this->Precision == FULL ? GL_RGBA32F : GL_RGBA16F;
  const int normalFormat = normalPrecision == FULL ? GL_RGBA32F : GL_RGBA16F;
  using Utilities = vtkStylizeShaderUtilities;
  auto make = [&](vtkTextureObject*& tex, int internalFormat, bool changed = false)
  { Utilities::EnsureScreenTexture(tex, renWin, w, h, internalFormat, changed); };
  auto drop = [&](vtkTextureObject*& tex) { Utilities::FreeTexture(tex, renWin); };
  make(this->ColorTexture, colorFormat, colorChanged);
  make(this->DepthTexture, GL_DEPTH_COMPONENT32F);
  if (this->Channels & NORMAL)
  {
    make(this->NormalTexture, normalFormat, normalChanged);
  }
  else
  {
    drop(this->NormalTexture);
  }
  if (this->Channels & POSITION)
  {
    make(this->PositionTexture, GL_RGBA32F);
  }
  else
  {
    drop(this->PositionTexture);
  }
  if (this->Channels & LINEAR_DEPTH)
  {
    make(this->LinearDepthTexture, GL_R32F);
  }
  else
  {
    drop(this->LinearDepthTexture);
  }
  if (this->Channels & DIRECTION)
  {
    make(this->DirectionTexture, normalFormat, normalChanged);
  }
  else
  {
    drop(this->DirectionTexture);
  }
  if (!this->FrameBufferObject)
  {
    this->FrameBufferObject = vtkOpenGLFramebufferObject::New();
    this->FrameBufferObject->SetContext(renWin);
  }
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::FreeTextures(vtkWindow* w)
{
  for (vtkTextureObject** tex : { &this->ColorTexture, &this->NormalTexture, &this->PositionTexture,
         &this->LinearDepthTexture, &this->DepthTexture, &this->DirectionTexture })
  {
    vtkStylizeShaderUtilities::FreeTexture(*tex, w);
  }
  if (this->FrameBufferObject)
  {
    if (w)
    {
      this->FrameBufferObject->ReleaseGraphicsResources(w);
    }
    this->FrameBufferObject->Delete();
    this->FrameBufferObject = nullptr;
  }
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeGBufferPass::GetBufferTexture(int buffer)
{
  switch (buffer)
  {
    case COLOR_BUFFER:
      return this->ColorTexture;
    case NORMAL_BUFFER:
      return this->NormalTexture;
    case POSITION_BUFFER:
      return this->PositionTexture;
    case DEPTH_BUFFER:
      return this->DepthTexture;
    case LINEAR_DEPTH_BUFFER:
      return this->LinearDepthTexture;
    case DIRECTION_BUFFER:
      return this->DirectionTexture;
    default:
      return nullptr;
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::BeginFrame(vtkRenderer* ren, int& w, int& h)
{
  int x, y;
  ren->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  this->Viewport[0] = x;
  this->Viewport[1] = y;
  this->Viewport[2] = w;
  this->Viewport[3] = h;
  if (w < 1 || h < 1)
  {
    return false;
  }
  vtkCamera* camera = ren->GetActiveCamera();
  camera->GetClippingRange(this->DepthRange);
  this->LogarithmicDepth = !this->SceneFromImage && !camera->GetParallelProjection() &&
    this->DepthRange[0] > 0.0 &&
    this->DepthRange[1] > this->DepthRange[0] * this->LogarithmicDepthRatio;
  vtkStylizeDepthPeeler* peeler = this->Internals->Peeler;
  const bool layer = peeler->GetLayerIndex() >= 0;
  if (layer)
  {
    // A translucent layer's depth is compared with the opaque scene's: the same mapping.
    this->LogarithmicDepth = peeler->GetOpaque()->LogarithmicDepth;
  }
  if (this->Channels != this->BuiltChannels || this->PositionSpace != this->BuiltPositionSpace ||
    this->LogarithmicDepth != this->BuiltLogarithmicDepth || layer != this->BuiltLayer)
  {
    this->BuiltChannels = this->Channels;
    this->BuiltPositionSpace = this->PositionSpace;
    this->BuiltLogarithmicDepth = this->LogarithmicDepth;
    this->BuiltLayer = layer;
    this->ShaderStageTime.Modified();
  }
  if (this->GeometryResolution[0] > 0 && this->GeometryResolution[1] > 0)
  {
    w = this->GeometryResolution[0];
    h = this->GeometryResolution[1];
  }
  this->GeometrySize[0] = w;
  this->GeometrySize[1] = h;
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::AttachTextures(int w, int h)
{
  vtkOpenGLFramebufferObject* fbo = this->FrameBufferObject;
  vtkTextureObject* const attachments[5] = { this->ColorTexture, this->NormalTexture,
    this->PositionTexture, this->LinearDepthTexture, this->DirectionTexture };
  unsigned int n = 0;
  for (vtkTextureObject* texture : attachments)
  {
    n += texture ? 1 : 0;
  }
  if (n != this->NumberOfAttachments)
  {
    fbo->RemoveColorAttachments(8); // the channel set changed: drop the old attachments
  }
  unsigned int index = 0;
  for (vtkTextureObject* texture : attachments)
  {
    if (texture)
    {
      fbo->AddColorAttachment(index++, texture);
    }
  }
  this->NumberOfAttachments = n;
  this->Internals->ClearPass->Attachments = n;
  this->Internals->Peeler->GetClearPass()->Attachments = n;
  fbo->AddDepthAttachment(this->DepthTexture);
  fbo->ActivateDrawBuffers(n);
  // VTK's state cache compares the list with the first n entries of the last list set, whatever
  // framebuffer that was: right after another G-buffer with as many attachments (this pass as
  // ParaView's per-rank pass, under a style's G-buffer) it skips the call and this framebuffer
  // keeps drawing into its first attachment alone. Set the list itself.
  GLenum buffers[8];
  for (unsigned int i = 0; i < n && i < 8; ++i)
  {
    buffers[i] = GL_COLOR_ATTACHMENT0 + i;
  }
  glDrawBuffers(static_cast<GLsizei>(std::min(n, 8u)), buffers);
  fbo->StartNonOrtho(w, h);
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::RenderGeometry(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  this->SceneFromImage = this->SceneImagePass != nullptr;
  this->ImageBackgroundApplied = false; // set by the image path
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  int w, h;
  if (!renWin || !this->BeginFrame(ren, w, h))
  {
    return false;
  }
  vtkStylizeDepthPeeler* peeler = this->Internals->Peeler;
  peeler->SwapPeelDepth(this->DepthTexture);
  this->AllocateTextures(renWin, w, h);
  peeler->AllocatePeelDepth(renWin, w, h);

  vtkOpenGLFramebufferObject* fbo = this->FrameBufferObject;
  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  this->AttachTextures(w, h);
  this->Internals->View->DeepCopy(ren->GetActiveCamera()->GetModelViewTransformMatrix());
  vtkMatrix4x4::Invert(this->Internals->View, this->Internals->InverseView);
  ren->GetActiveCamera()->GetClippingRange(this->Internals->ClippingRange);
  if (this->SceneFromImage)
  {
    this->Internals->ImagePath->Render(s, this, renWin, w, h, this->Internals->InverseView);
  }
  else
  {
    this->RenderProps(s, fbo);
  }
  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();
  vtkOpenGLCheckErrorMacro("failed after vtkStylizeGBufferPass::RenderGeometry");
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::RenderProps(const vtkRenderState* s, vtkOpenGLFramebufferObject* fbo)
{
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkRenderState sfbo(ren);
  sfbo.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  sfbo.SetFrameBuffer(fbo);
  sfbo.SetRequiredKeys(s->GetRequiredKeys());

  ScopedScreenTransform screen(ren->GetActiveCamera(), this->GeometryScreenTransform);
  ScopedTileWidths widths(ren, s->GetPropArray(), s->GetPropArrayCount());
  this->PreRender(&sfbo);
  vtkStylizeDepthPeeler* peeler = this->Internals->Peeler;
  const bool layer = peeler->GetLayerIndex() >= 0;
  if (layer)
  {
    peeler->Begin(&sfbo, this->GeometryCameraPass);
  }
  // Blending (VTK keeps it on for opaque geometry) applies to the colour alone: the other
  // channels keep what the nearest fragment wrote. Blended by their alpha (the direction's
  // confidence, 0 on lines), they would mix with whatever the same pixel held before, which
  // depends on the order the triangles are drawn in: a rank's piece of a mesh would give other
  // directions than the whole mesh.
  const unsigned int n = this->NumberOfAttachments;
  for (unsigned int i = 1; i < n; ++i)
  {
    glDisablei(GL_BLEND, i);
  }
  if (this->LightingPass)
  {
    this->LightingPass->RenderWithLighting(&sfbo, this->GeometryCameraPass);
  }
  else
  {
    this->GeometryCameraPass->Render(&sfbo);
  }
  this->NumberOfRenderedProps += this->GeometryCameraPass->GetNumberOfRenderedProps();
  if (layer)
  {
    peeler->End(&sfbo, this->GeometryCameraPass, this->GeometrySequence);
  }
  if (renWin->GetState()->GetEnumState(GL_BLEND))
  {
    // (glDisablei leaves VTK's state cache unaware: the cached GL_BLEND holds for every buffer)
    for (unsigned int i = 1; i < n; ++i)
    {
      glEnablei(GL_BLEND, i);
    }
  }
  this->PostRender(&sfbo);
  ++this->GeometryRenders;
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::CompositeToOutput(const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin || !this->ColorTexture || this->Viewport[2] < 1 || this->Viewport[3] < 1)
  {
    return;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  static const std::string declarations = std::string(vtkStylizeDepthFS) + vtkStylizeCompositeFS;
  vtkShaderProgram* program =
    this->Internals->CompositeQuad.Prepare(renWin, declarations, "  stylizeComposite();\n");
  if (!program)
  {
    vtkErrorMacro("Could not build the G-buffer composite shader.");
    return;
  }
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  ostate->vtkglViewport(this->Viewport[0], this->Viewport[1], this->Viewport[2], this->Viewport[3]);
  ostate->vtkglScissor(this->Viewport[0], this->Viewport[1], this->Viewport[2], this->Viewport[3]);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  this->ColorTexture->Activate();
  this->DepthTexture->Activate();
  program->SetUniformi("stylizeColorTexture", this->ColorTexture->GetTextureUnit());
  program->SetUniformi("stylizeDepthTexture", this->DepthTexture->GetTextureUnit());
  program->SetUniformi("stylizeDiscardBackground", ren->Transparent() ? 1 : 0);
  this->SetDepthMappingUniforms(program);
  this->Internals->CompositeQuad.Render();
  this->DepthTexture->Deactivate();
  this->ColorTexture->Deactivate();
  vtkOpenGLCheckErrorMacro("failed after vtkStylizeGBufferPass::CompositeToOutput");
}

//------------------------------------------------------------------------------
namespace
{
/** Draws into the renderer's (tiled) viewport, scissored, depth-tested with GL_LEQUAL against
 * what is there; the viewport, scissor and its test restored on leaving. */
struct ScopedRendererViewport
{
  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglScissor Scissor;
  vtkOpenGLState::ScopedglEnableDisable ScissorTest;

  explicit ScopedRendererViewport(vtkRenderer* ren)
    : State(static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState())
    , Viewport(State)
    , Scissor(State)
    , ScissorTest(State, GL_SCISSOR_TEST)
  {
    int w, h, x, y;
    ren->GetTiledSizeAndOrigin(&w, &h, &x, &y);
    this->State->vtkglViewport(x, y, w, h);
    this->State->vtkglEnable(GL_SCISSOR_TEST);
    this->State->vtkglScissor(x, y, w, h);
    this->State->vtkglEnable(GL_DEPTH_TEST);
    this->State->vtkglDepthFunc(GL_LEQUAL);
  }
};
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::RenderAnnotations(const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  std::vector<vtkProp*> props = this->AfterProps;
  if (this->Controller && this->Controller->GetNumberOfProcesses() > 1 && this->ChannelSource &&
    this->ChannelSource->GetLeaveOutVolumes() && !ren->GetSelector())
  {
    // the volumes the channel sources left out, each process's pieces composited over process
    // 0's picture in visibility order (every process takes part, with volumes or not)
    std::vector<vtkProp*> volumes;
    auto volume = [](vtkProp* prop) { return prop && prop->IsA("vtkVolume"); };
    std::copy_if(props.begin(), props.end(), std::back_inserter(volumes), volume);
    props.erase(std::remove_if(props.begin(), props.end(), volume), props.end());
    this->Internals->PlainVolumes->Render(s, volumes, this->VolumeSequence, this->Controller);
  }
  if (props.empty())
  {
    return;
  }
  // the annotations, as VTK draws them, over the stylized picture (depth-tested against it)
  ScopedRendererViewport viewport(ren);
  vtkRenderState annotations(ren);
  annotations.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  annotations.SetFrameBuffer(s->GetFrameBuffer());
  this->AnnotationSequence->Render(&annotations);
  this->NumberOfRenderedProps += this->AnnotationSequence->GetNumberOfRenderedProps();
  this->OverlayPass->Render(&annotations);
  this->NumberOfRenderedProps += this->OverlayPass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::RenderAfterGeometry(const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin)
  {
    return;
  }
  if (this->SceneFromImage)
  {
    // an image already holds everything but the annotations a style leaves plain
    this->RenderAnnotations(s);
    return;
  }
  ScopedRendererViewport viewport(ren);

  const double shift[4] = { 1.0, 1.0, this->AfterScreenShift[0], this->AfterScreenShift[1] };
  ScopedScreenTransform screen(ren->GetActiveCamera(), shift);
  ScopedTileWidths widths(ren, s->GetPropArray(), s->GetPropArrayCount());
  ScopedTileWidths annotationWidths(
    ren, this->AfterProps.data(), static_cast<int>(this->AfterProps.size()));
  // (a hardware selection draws everything: translucent props stay pickable)
  vtkSequencePass* after =
    this->DrawTranslucent || ren->GetSelector() ? this->AfterSequence : this->VolumeSequence;
  if (this->LightingPass)
  {
    this->LightingPass->RenderWithLighting(s, after);
  }
  else
  {
    after->Render(s);
  }
  this->NumberOfRenderedProps += after->GetNumberOfRenderedProps();
  this->RenderAnnotations(s);
  this->OverlayPass->Render(s);
  this->NumberOfRenderedProps += this->OverlayPass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::HasTranslucentGeometry(const vtkRenderState* s)
{
  return vtkStylizeDepthPeeler::HasTranslucentGeometry(s);
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::RenderTranslucentLayer(
  const vtkRenderState* s, vtkStylizeGBufferPass* opaque, int index)
{
  return this->Internals->Peeler->RenderLayer(s, this, opaque, index);
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::Render(const vtkRenderState* state)
{
  // (LeaveOutAnnotations, LeaveOutVolumes: the state without them; a hardware selection keeps
  // them pickable)
  std::vector<vtkProp*> props;
  vtkRenderState scene(state->GetRenderer());
  const vtkRenderState* s = state;
  if ((this->LeaveOutAnnotations || this->LeaveOutVolumes) && !state->GetRenderer()->GetSelector())
  {
    for (int i = 0; i < state->GetPropArrayCount(); ++i)
    {
      vtkProp* prop = state->GetPropArray()[i];
      if (!(this->LeaveOutAnnotations && vtkStylizeStylePass::IsAnnotation(prop)) &&
        !(this->LeaveOutVolumes && prop && prop->IsA("vtkVolume")))
      {
        props.push_back(prop);
      }
    }
    scene.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
    scene.SetFrameBuffer(state->GetFrameBuffer());
    scene.SetRequiredKeys(state->GetRequiredKeys());
    s = &scene;
  }
  int rendered = 0;
  if (this->RenderGeometry(s))
  {
    rendered = this->NumberOfRenderedProps;
    this->CompositeToOutput(s);
  }
  this->RenderAfterGeometry(s);
  this->NumberOfRenderedProps += rendered;
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::DownloadChannel(int buffer, vtkFloatArray* out)
{
  vtkTextureObject* tex = this->GetBufferTexture(buffer);
  if (!tex || !out || !this->FrameBufferObject)
  {
    return false;
  }
  const int rect[4] = { 0, 0, static_cast<int>(tex->GetWidth()),
    static_cast<int>(tex->GetHeight()) };
  const int comps = (buffer == DEPTH_BUFFER || buffer == LINEAR_DEPTH_BUFFER) ? 1 : 4;
  out->SetNumberOfComponents(comps);
  out->SetNumberOfTuples(static_cast<vtkIdType>(rect[2]) * rect[3]);
  this->ReadBuffer(buffer, rect, out->GetPointer(0));
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::ReadBuffer(int buffer, const int rect[4], float* out)
{
  vtkOpenGLFramebufferObject* fbo = this->FrameBufferObject;
  fbo->SaveCurrentBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  fbo->Bind(GL_READ_FRAMEBUFFER);
  if (buffer == DEPTH_BUFFER)
  {
    glReadPixels(rect[0], rect[1], rect[2], rect[3], GL_DEPTH_COMPONENT, GL_FLOAT, out);
  }
  else
  {
    // Attachments: the colour, then those allocated of normal, position, linear depth and
    // direction, in this order.
    vtkTextureObject* const order[5] = { this->ColorTexture, this->NormalTexture,
      this->PositionTexture, this->LinearDepthTexture, this->DirectionTexture };
    const int slot = buffer == COLOR_BUFFER ? 0
      : buffer == NORMAL_BUFFER             ? 1
      : buffer == POSITION_BUFFER           ? 2
      : buffer == LINEAR_DEPTH_BUFFER       ? 3
                                            : 4;
    unsigned int index = 0;
    for (int i = 0; i < slot; ++i)
    {
      index += order[i] ? 1 : 0;
    }
    fbo->GetContext()->GetState()->vtkglReadBuffer(GL_COLOR_ATTACHMENT0 + index);
    glReadPixels(rect[0], rect[1], rect[2], rect[3],
      buffer == LINEAR_DEPTH_BUFFER ? GL_RED : GL_RGBA, GL_FLOAT, out);
  }
  fbo->UnBind(GL_READ_FRAMEBUFFER);
  fbo->RestorePreviousBindingsAndBuffers(GL_READ_FRAMEBUFFER);
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Internals->CompositeQuad.Release(w);
  this->Internals->ImagePath->ReleaseGraphicsResources(w);
  this->Internals->Peeler->ReleaseGraphicsResources(w);
  this->Internals->PlainVolumes->ReleaseGraphicsResources(w);
  this->FreeTextures(w);
  if (this->SceneImagePass)
  {
    this->SceneImagePass->ReleaseGraphicsResources(w);
  }
  this->GeometryCameraPass->ReleaseGraphicsResources(w);
  this->AfterSequence->ReleaseGraphicsResources(w);
  this->AnnotationSequence->ReleaseGraphicsResources(w);
  this->OverlayPass->ReleaseGraphicsResources(w);
  if (this->LightingPass)
  {
    this->LightingPass->ReleaseGraphicsResources(w);
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizeGBufferPass::GetTextureBytes()
{
  vtkIdType total = this->Internals->ImagePath->GetTextureBytes();
  for (vtkTextureObject* t : { this->ColorTexture, this->NormalTexture, this->PositionTexture,
         this->LinearDepthTexture, this->DepthTexture, this->DirectionTexture })
  {
    total += vtkStylizeShaderUtilities::TextureBytes(t);
  }
  return total;
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::GetFlatBackground(vtkRenderer* ren, float rgba[4])
{
  vtkRenderWindow* win = ren ? ren->GetRenderWindow() : nullptr;
  if (!win || ren->Transparent() || !win->GetErase() || !ren->GetErase() ||
    ren->GetGradientBackground() || ren->GetTexturedBackground())
  {
    return false;
  }
  // A flat background as the 8-bit window shows it: the colour target is half-float, and a
  // background such as 0.1 or 0.5 (255 c = k + 1/2) would otherwise come out one level darker
  // than in a plain render, under the styles and the overlays drawn on them.
  double c[3];
  ren->GetBackground(c);
  for (int i = 0; i < 3; ++i)
  {
    const double v = std::isfinite(c[i]) ? std::min(1.0, std::max(0.0, c[i])) : 0.0;
    rgba[i] = static_cast<float>(std::round(v * 255.0) / 255.0);
  }
  rgba[3] = 1.0f;
  return true;
}
