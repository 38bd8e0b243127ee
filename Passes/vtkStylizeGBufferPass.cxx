#include "vtkStylizeGBufferPass.h"

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
#include "vtkInformation.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkOverlayPass.h"
#include "vtkProp3D.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkSequencePass.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkTextureObject.h"
#include "vtkTransform.h"
#include "vtkTranslucentPass.h"
#include "vtkVolumetricPass.h"
#include "vtk_glew.h"

#include "vtkStylizeCompositeFS.h"
#include "vtkStylizeDepthFS.h"
#include "vtkStylizeGBufferDirectionFS.h"
#include "vtkStylizeGBufferImpl.h"
#include "vtkStylizeReconstructFS.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

namespace
{
const char* const GBufferTag = "//VTK::StylizeGBuffer::Impl";
// The DIRECTION channel's attribute on the helpers of VTK's composite data mapper.
const char* const TangentDeclaration = "in vec3 tangentMC; // the DIRECTION channel's source\n";

/**
 * First step inside the camera pass: clears what vtkRenderer::Clear() leaves alone in the
 * G-buffer (extra attachments; the colour of layered renderers; everything when the renderer
 * does not erase), so no value of an earlier frame survives.
 */
class vtkStylizeGBufferClearPass : public vtkRenderPass
{
public:
  static vtkStylizeGBufferClearPass* New();
  vtkTypeMacro(vtkStylizeGBufferClearPass, vtkRenderPass);
  void Render(const vtkRenderState* s) override
  {
    vtkRenderer* ren = s->GetRenderer();
    vtkOpenGLRenderWindow* win = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
    vtkOpenGLState* ostate = win->GetState();
    const bool erased = ren->GetRenderWindow()->GetErase() && ren->GetErase();
    const GLfloat zero[4] = { 0.f, 0.f, 0.f, 0.f };
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    float flat[4];
    if (this->Layer)
    {
      // A translucent layer: no surface anywhere yet (alpha 0; the colour of a flat background
      // for the stages that read colour across a silhouette: the one the opaque scene's image
      // stands for where a compositor replaced the renderer's).
      if (this->UseImageBackground)
      {
        std::copy(this->ImageBackground, this->ImageBackground + 3, flat);
      }
      else if (!vtkStylizeGBufferPass::GetFlatBackground(ren, flat))
      {
        std::fill(flat, flat + 3, 0.f);
      }
      flat[3] = 0.f;
      glClearBufferfv(GL_COLOR, 0, flat);
    }
    else if (ren->Transparent() || !erased)
    {
      glClearBufferfv(GL_COLOR, 0, zero);
    }
    else if (vtkStylizeGBufferPass::GetFlatBackground(ren, flat))
    {
      flat[3] = static_cast<float>(ren->GetBackgroundAlpha());
      glClearBufferfv(GL_COLOR, 0, flat);
    }
    if (!erased || this->Layer)
    {
      const GLfloat one = 1.f;
      ostate->vtkglDepthMask(GL_TRUE);
      glClearBufferfv(GL_DEPTH, 0, &one);
    }
    for (unsigned int i = 1; i < this->Attachments; ++i)
    {
      glClearBufferfv(GL_COLOR, static_cast<GLint>(i), zero);
    }
  }
  unsigned int Attachments = 1;
  bool Layer = false; // clears for a translucent layer
  bool UseImageBackground = false; // a layer's background colour is ImageBackground
  float ImageBackground[3] = { 0.f, 0.f, 0.f };

protected:
  vtkStylizeGBufferClearPass() = default;
  ~vtkStylizeGBufferClearPass() override = default;
};
vtkStandardNewMacro(vtkStylizeGBufferClearPass);

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
}

namespace
{
struct ChannelPart;
}

class vtkStylizeGBufferPass::vtkInternals
{
public:
  vtkNew<vtkStylizeGBufferClearPass> ClearPass;
  vtkNew<vtkStylizeGBufferClearPass> LayerClearPass;
  vtkStylizeScreenQuad CompositeQuad;
  vtkStylizeScreenQuad ReconstructQuad;
  vtkNew<vtkMatrix4x4> InverseView;
  vtkNew<vtkMatrix4x4> View;
  vtkNew<vtkMatrix4x4> InverseModel;
  vtkNew<vtkMatrix4x4> Product;
  vtkNew<vtkMatrix4x4> Upload; // a matrix on its way to a shader (transposed)

  // The channel source's channels composited over the processes (on process 0): stored depth,
  // normal, position, direction, inside the rectangle SourceRect (x, y, width, height).
  vtkTextureObject* Composited[4] = { nullptr, nullptr, nullptr, nullptr };
  int SourceRect[4] = { 0, 0, 0, 0 };

  /** The texture of a buffer (COLOR_BUFFER, ..., DEPTH_BUFFER); nullptr when not allocated. */
  static vtkTextureObject* TextureOf(vtkStylizeGBufferPass* self, int buffer)
  {
    switch (buffer)
    {
      case COLOR_BUFFER:
        return self->ColorTexture;
      case NORMAL_BUFFER:
        return self->NormalTexture;
      case POSITION_BUFFER:
        return self->PositionTexture;
      case DEPTH_BUFFER:
        return self->DepthTexture;
      case LINEAR_DEPTH_BUFFER:
        return self->LinearDepthTexture;
      case DIRECTION_BUFFER:
        return self->DirectionTexture;
      default:
        return nullptr;
    }
  }

  // Compositing by depth across processes (each a collective call where it takes a controller).
  /**
   * Reads `self`'s depth and `buffers` (COLOR_BUFFER, ...) inside rect, or when rect is null
   * inside the rectangle where its depth is below 1 (empty where it holds no surface); w x h is
   * its size.
   */
  static void ReadPart(vtkStylizeGBufferPass* self, ChannelPart& part,
    const std::vector<int>& buffers, int w, int h, const int* rect = nullptr);
  /**
   * Sends every process's part to process 0, which keeps the nearest by depth at every pixel (a
   * binary tree, log2(N) steps). Returns true on process 0 (`own` holds the union), false on the
   * others (`own` was sent).
   */
  static bool ReducePart(vtkStylizeGBufferPass* self, vtkMultiProcessController* controller,
    ChannelPart& own, const std::vector<int>& buffers, int w, int h);
  /** Process 0's part's rectangle and depth to every process. */
  static void BroadcastDepth(vtkStylizeGBufferPass* self, vtkMultiProcessController* controller,
    ChannelPart& part, int w, int h);
  /**
   * The other processes' `opaque` G-buffers take process 0's depth (the depth composited over the
   * processes), which their translucent layers must lie in front of.
   */
  static void ShareOpaqueDepth(vtkStylizeGBufferPass* self, vtkMultiProcessController* controller,
    vtkStylizeGBufferPass* opaque);
  /**
   * After every process rendered its layer (RenderTranslucentLayer()): process 0's layer becomes
   * the nearest surface of all the processes' layers at each pixel (every channel), and every
   * process's layer depth becomes that layer's depth, so that the next layer peels behind the
   * whole scene's. Returns whether any process's layer holds a surface (on every process).
   */
  static bool CompositeLayer(
    vtkStylizeGBufferPass* self, vtkMultiProcessController* controller, bool rendered);
};

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
  this->LayerSequence = vtkSequencePass::New();
  vtkNew<vtkRenderPassCollection> layer;
  this->Internals->LayerClearPass->Layer = true;
  layer->AddItem(this->Internals->LayerClearPass);
  layer->AddItem(lights);
  layer->AddItem(translucent);
  this->LayerSequence->SetPasses(layer);
  this->OverlayPass = vtkOverlayPass::New();
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
  this->LayerSequence->Delete();
  this->OverlayPass->Delete();
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
  os << indent << "NormalPrecision: " << (this->NormalPrecision == FULL ? "full" : "half")
     << "\n";
  os << indent << "PositionSpace: " << (this->PositionSpace == VIEW ? "view" : "object") << "\n";
  os << indent << "Viewport: " << this->Viewport[0] << " " << this->Viewport[1] << " "
     << this->Viewport[2] << " " << this->Viewport[3] << "\n";
  os << indent << "LightingPass: " << (this->LightingPass ? "set" : "(none: VTK lighting)")
     << "\n";
  os << indent << "ChannelSource: " << (this->ChannelSource ? "set" : "(none)") << "\n";
  os << indent << "ImageBackground: " << this->ImageBackground[0] << " " << this->ImageBackground[1]
     << " " << this->ImageBackground[2] << (this->UseImageBackground ? " (used)" : " (off)")
     << "\n";
  os << indent << "Controller: "
     << (this->Controller ? this->Controller->GetNumberOfProcesses() : 1) << " process(es)\n";
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
  auto make = [&](vtkTextureObject*& tex, int internalFormat, bool changed = false) {
    Utilities::EnsureScreenTexture(tex, renWin, w, h, internalFormat, changed);
  };
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
  for (vtkTextureObject** tex : { &this->ColorTexture, &this->NormalTexture,
         &this->PositionTexture, &this->LinearDepthTexture, &this->DepthTexture,
         &this->DirectionTexture, &this->ImageColorTexture, &this->ImageDepthTexture,
         &this->PeelDepthTexture })
  {
    vtkStylizeShaderUtilities::FreeTexture(*tex, w);
  }
  for (vtkTextureObject*& tex : this->Internals->Composited)
  {
    vtkStylizeShaderUtilities::FreeTexture(tex, w);
  }
  for (vtkOpenGLFramebufferObject** fbo : { &this->FrameBufferObject, &this->ImageFrameBuffer })
  {
    if (*fbo)
    {
      if (w)
      {
        (*fbo)->ReleaseGraphicsResources(w);
      }
      (*fbo)->Delete();
      *fbo = nullptr;
    }
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::RenderGeometry(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  this->SceneFromImage = this->SceneImagePass != nullptr;
  this->ImageBackgroundApplied = false; // set by RenderSceneImage()
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin)
  {
    return false;
  }
  int w, h, x, y;
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
  if (this->LayerIndex >= 0)
  {
    // A translucent layer's depth is compared with the opaque scene's: the same mapping.
    this->LogarithmicDepth = this->LayerOpaque->LogarithmicDepth;
  }
  const bool layer = this->LayerIndex >= 0;
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
  if (this->LayerIndex > 0)
  {
    // Depth peeling: the previous layer's depth becomes the one this layer lies behind.
    std::swap(this->DepthTexture, this->PeelDepthTexture);
  }
  this->AllocateTextures(renWin, w, h);
  if (this->LayerIndex > 0)
  {
    vtkStylizeShaderUtilities::EnsureScreenTexture(
      this->PeelDepthTexture, renWin, w, h, GL_DEPTH_COMPONENT32F, false);
  }

  vtkOpenGLFramebufferObject* fbo = this->FrameBufferObject;
  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  const unsigned int n = 1 + (this->NormalTexture ? 1 : 0) + (this->PositionTexture ? 1 : 0) +
    (this->LinearDepthTexture ? 1 : 0) + (this->DirectionTexture ? 1 : 0);
  if (n != this->NumberOfAttachments)
  {
    fbo->RemoveColorAttachments(8); // the channel set changed: drop the old attachments
  }
  unsigned int index = 0;
  fbo->AddColorAttachment(index++, this->ColorTexture);
  if (this->NormalTexture)
  {
    fbo->AddColorAttachment(index++, this->NormalTexture);
  }
  if (this->PositionTexture)
  {
    fbo->AddColorAttachment(index++, this->PositionTexture);
  }
  if (this->LinearDepthTexture)
  {
    fbo->AddColorAttachment(index++, this->LinearDepthTexture);
  }
  if (this->DirectionTexture)
  {
    fbo->AddColorAttachment(index++, this->DirectionTexture);
  }
  this->NumberOfAttachments = n;
  this->Internals->ClearPass->Attachments = n;
  this->Internals->LayerClearPass->Attachments = n;
  fbo->AddDepthAttachment(this->DepthTexture);
  fbo->ActivateDrawBuffers(n);
  // VTK's state cache compares the list with the first n entries of the last list set, whatever
  // framebuffer that was: right after another G-buffer with as many attachments (this pass as
  // ParaView's per-rank pass, under a style's G-buffer) it skips the call and this framebuffer
  // keeps drawing into its first attachment alone. Set the list itself.
  {
    GLenum buffers[8];
    for (unsigned int i = 0; i < n && i < 8; ++i)
    {
      buffers[i] = GL_COLOR_ATTACHMENT0 + i;
    }
    glDrawBuffers(static_cast<GLsizei>(std::min(n, 8u)), buffers);
  }
  fbo->StartNonOrtho(w, h);

  this->Internals->View->DeepCopy(ren->GetActiveCamera()->GetModelViewTransformMatrix());
  vtkMatrix4x4::Invert(this->Internals->View, this->Internals->InverseView);

  if (this->SceneFromImage)
  {
    this->RenderSceneImage(s, renWin, w, h);
    fbo->UnBind();
    fbo->RestorePreviousBindingsAndBuffers();
    vtkOpenGLCheckErrorMacro("failed after vtkStylizeGBufferPass::RenderGeometry (image)");
    return true;
  }

  vtkRenderState sfbo(ren);
  sfbo.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  sfbo.SetFrameBuffer(fbo);
  sfbo.SetRequiredKeys(s->GetRequiredKeys());

  ScopedScreenTransform screen(camera, this->GeometryScreenTransform);
  this->PreRender(&sfbo);
  if (layer)
  {
    this->BeginLayer(&sfbo);
  }
  // Blending (VTK keeps it on for opaque geometry) applies to the colour alone: the other
  // channels keep what the nearest fragment wrote. Blended by their alpha (the direction's
  // confidence, 0 on lines), they would mix with whatever the same pixel held before, which
  // depends on the order the triangles are drawn in: a rank's piece of a mesh gave other
  // directions than the whole mesh.
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
    this->EndLayer(&sfbo);
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

  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();
  vtkOpenGLCheckErrorMacro("failed after vtkStylizeGBufferPass::RenderGeometry");
  return true;
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
void vtkStylizeGBufferPass::RenderAfterGeometry(const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin || this->SceneFromImage) // an image already holds everything
  {
    return;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  int w, h, x, y;
  ren->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  ostate->vtkglViewport(x, y, w, h);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  ostate->vtkglScissor(x, y, w, h);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_LEQUAL);

  const double shift[4] = { 1.0, 1.0, this->AfterScreenShift[0], this->AfterScreenShift[1] };
  ScopedScreenTransform screen(ren->GetActiveCamera(), shift);
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
  this->OverlayPass->Render(s);
  this->NumberOfRenderedProps += this->OverlayPass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::HasTranslucentGeometry(const vtkRenderState* s)
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
bool vtkStylizeGBufferPass::RenderTranslucentLayer(
  const vtkRenderState* s, vtkStylizeGBufferPass* opaque, int index)
{
  if (!opaque || !opaque->GetDepthTexture() || index < 0 || (index > 0 && !this->DepthTexture))
  {
    return false;
  }
  vtkRenderPass* image = this->SceneImagePass;
  this->SceneImagePass = nullptr; // a layer always comes from the geometry
  this->LayerIndex = index;
  this->LayerOpaque = opaque;
  this->LayerOpaqueDepth = opaque->GetDepthTexture();
  this->LayerHasSamples = false;
  vtkStylizeGBufferClearPass* clear = this->Internals->LayerClearPass;
  clear->UseImageBackground = opaque->ImageBackgroundApplied;
  for (int i = 0; i < 3; ++i)
  {
    clear->ImageBackground[i] = static_cast<float>(opaque->ImageBackground[i]);
  }
  // Several processes (ParaView's render ranks), each with its own props: every one peels in
  // front of the composited opaque depth and behind the whole scene's previous layer, and the
  // layer is composited by depth to process 0.
  vtkMultiProcessController* controller = opaque->Controller;
  const bool distributed = controller && controller->GetNumberOfProcesses() > 1;
  if (distributed && index == 0)
  {
    vtkInternals::ShareOpaqueDepth(this, controller, opaque);
  }
  bool rendered = this->RenderGeometry(s);
  if (distributed)
  {
    // (the answer is every process's, so that all of them go on to the next layer or stop)
    this->LayerHasSamples = vtkInternals::CompositeLayer(this, controller, rendered);
    rendered = true;
  }
  this->LayerIndex = -1;
  this->LayerOpaque = nullptr;
  this->LayerOpaqueDepth = nullptr;
  this->SceneImagePass = image;
  return rendered && this->LayerHasSamples;
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::BeginLayer(const vtkRenderState* s)
{
  vtkOpenGLRenderWindow* renWin =
    static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  this->GeometryCameraPass->SetDelegatePass(this->LayerSequence);
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
  this->LayerBlend = ostate->GetEnumState(GL_BLEND);
  ostate->vtkglDisable(GL_BLEND);
  this->LayerOpaqueDepth->Activate();
  if (this->LayerIndex > 0)
  {
    this->PeelDepthTexture->Activate();
  }
  if (!this->LayerQuery)
  {
    glGenQueries(1, &this->LayerQuery);
  }
  glBeginQuery(GL_ANY_SAMPLES_PASSED, this->LayerQuery);
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::EndLayer(const vtkRenderState* s)
{
  vtkOpenGLRenderWindow* renWin =
    static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow());
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  GLuint samples = 0;
  glGetQueryObjectuiv(this->LayerQuery, GL_QUERY_RESULT, &samples);
  this->LayerHasSamples = samples != 0;
  if (this->LayerIndex > 0)
  {
    this->PeelDepthTexture->Deactivate();
  }
  this->LayerOpaqueDepth->Deactivate();
  if (this->LayerBlend)
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
  this->GeometryCameraPass->SetDelegatePass(this->GeometrySequence);
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::Render(const vtkRenderState* s)
{
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
void vtkStylizeGBufferPass::RenderSceneImage(
  const vtkRenderState* s, vtkOpenGLRenderWindow* renWin, int gw, int gh)
{
  vtkRenderer* ren = s->GetRenderer();
  const int w = this->Viewport[2];
  const int h = this->Viewport[3];
  using Utilities = vtkStylizeShaderUtilities;
  Utilities::EnsureScreenTexture(this->ImageColorTexture, renWin, w, h,
    this->Precision == FULL ? GL_RGBA32F : GL_RGBA16F);
  Utilities::EnsureScreenTexture(this->ImageDepthTexture, renWin, w, h, GL_DEPTH_COMPONENT32F);
  if (!this->ImageFrameBuffer)
  {
    this->ImageFrameBuffer = vtkOpenGLFramebufferObject::New();
    this->ImageFrameBuffer->SetContext(renWin);
  }

  // 1. The image: the scene pass renders into colour and depth at the viewport's size.
  vtkOpenGLFramebufferObject* image = this->ImageFrameBuffer;
  vtkOpenGLState* ostate = renWin->GetState();
  image->SaveCurrentBindingsAndBuffers();
  image->Bind();
  image->AddColorAttachment(0, this->ImageColorTexture);
  image->ActivateDrawBuffers(1);
  image->AddDepthAttachment(this->ImageDepthTexture);
  image->StartNonOrtho(w, h);
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglScissor(0, 0, w, h);
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  vtkRenderState simage(ren);
  simage.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  simage.SetFrameBuffer(image);
  simage.SetRequiredKeys(s->GetRequiredKeys());
  // The channel source renders this process's geometry inside the image, at the image's size,
  // with this pass's channels.
  vtkStylizeGBufferPass* source = this->ChannelSource;
  const vtkTypeUInt64 sourceRenders = source ? source->GeometryRenders : 0;
  const int sourceChannels = this->Channels & (NORMAL | POSITION | DIRECTION);
  if (source)
  {
    source->SetChannels(sourceChannels);
    source->SetPositionSpace(this->PositionSpace);
    source->SetNormalPrecision(this->Precision == FULL ? FULL : this->NormalPrecision);
    source->SetGeometryResolution(0, 0);
    source->SetGeometryScreenTransform(1.0, 1.0, 0.0, 0.0);
  }
  this->SceneImagePass->Render(&simage);
  this->NumberOfRenderedProps += this->SceneImagePass->GetNumberOfRenderedProps();
  image->UnBind();
  image->RestorePreviousBindingsAndBuffers();
  const bool sourceRendered = source && source->GeometryRenders != sourceRenders &&
    source->GeometrySize[0] == w && source->GeometrySize[1] == h &&
    source->Channels == sourceChannels;
  this->ChannelSourceUsed = false;
  if (source && this->Controller && this->Controller->GetNumberOfProcesses() > 1)
  {
    this->ChannelSourceUsed = this->CompositeChannelSource(renWin, sourceRendered, w, h);
  }
  else if (sourceRendered)
  {
    this->ChannelSourceUsed = true;
    const int whole[4] = { 0, 0, w, h };
    std::copy(whole, whole + 4, this->Internals->SourceRect);
  }
  // The textures the channels come from: the source's own (one process) or the composited ones.
  vtkTextureObject* sourceTextures[4] = { nullptr, nullptr, nullptr, nullptr };
  if (this->ChannelSourceUsed)
  {
    const bool composited = this->Controller && this->Controller->GetNumberOfProcesses() > 1;
    vtkTextureObject* const own[4] = { source->DepthTexture, source->NormalTexture,
      source->PositionTexture, source->DirectionTexture };
    for (int i = 0; i < 4; ++i)
    {
      sourceTextures[i] = composited ? this->Internals->Composited[i] : own[i];
    }
  }

  // 2. The G-buffer from the image (the G-buffer's framebuffer is bound again).
  // The requested channels, in attachment order, with literal gl_FragData indices.
  std::ostringstream body;
  body << "  stylizeReconstruct();\n  gl_FragData[0] = stylizeOutColor;\n";
  int index = 1;
  for (auto channel : { std::make_pair(this->NormalTexture, "stylizeOutNormal"),
         std::make_pair(this->PositionTexture, "stylizeOutPosition"),
         std::make_pair(this->LinearDepthTexture, "stylizeOutLinearDepth"),
         std::make_pair(this->DirectionTexture, "stylizeOutDirection") })
  {
    if (channel.first)
    {
      body << "  gl_FragData[" << index++ << "] = " << channel.second << ";\n";
    }
  }
  std::string defines = this->PositionSpace == OBJECT ? "#define STYLIZE_POSITION_WORLD\n" : "";
  if (this->ChannelSourceUsed)
  {
    defines += "#define STYLIZE_CHANNEL_SOURCE\n";
    const char* const names[4] = { nullptr, "NORMAL", "POSITION", "DIRECTION" };
    for (int i = 1; i < 4; ++i)
    {
      if (sourceTextures[i])
      {
        defines += std::string("#define STYLIZE_SOURCE_") + names[i] + "\n";
      }
    }
  }
  vtkShaderProgram* program = this->Internals->ReconstructQuad.Prepare(
    renWin, defines + vtkStylizeDepthFS + vtkStylizeReconstructFS, body.str());
  if (!program)
  {
    vtkErrorMacro("Could not build the G-buffer reconstruction shader.");
    return;
  }
  // The projection the image was rendered with, inverted (vtkShaderProgram uploads row-major
  // data as GLSL columns, hence the transposes).
  // (The aspect as vtkCamera::GetProjectionTransformMatrix(vtkRenderer*) computes it; that
  // method returns a new, transposed matrix.)
  double aspect[2], viewportAspect[2];
  ren->ComputeAspect();
  ren->GetAspect(aspect);
  ren->vtkViewport::ComputeAspect();
  ren->vtkViewport::GetAspect(viewportAspect);
  const double aspectRatio =
    aspect[0] * viewportAspect[1] / (aspect[1] * viewportAspect[0]) * w / static_cast<double>(h);
  vtkMatrix4x4* upload = this->Internals->Upload;
  vtkMatrix4x4::Invert(
    ren->GetActiveCamera()->GetProjectionTransformMatrix(aspectRatio, -1.0, 1.0), upload);
  upload->Transpose();
  program->SetUniformMatrix("stylizeInverseProjection", upload);
  vtkMatrix4x4::Transpose(this->Internals->InverseView, upload);
  program->SetUniformMatrix("stylizeInverseView", upload);

  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  ostate->vtkglViewport(0, 0, gw, gh);
  ostate->vtkglScissor(0, 0, gw, gh);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const double* t = this->GeometryScreenTransform;
  vtkStylizeUniforms uniforms(program);
  uniforms.Texture("stylizeImageColor", this->ImageColorTexture)
    .Texture("stylizeImageDepth", this->ImageDepthTexture)
    .Float4("stylizeScreenTransform", t[0], t[1], t[2], t[3])
    .Float2("stylizeImageSize", w, h);
  const double* bg = this->ImageBackground;
  const double* current = ren->GetBackground();
  this->ImageBackgroundApplied = this->UseImageBackground &&
    (std::abs(current[0] - bg[0]) > 1e-6 || std::abs(current[1] - bg[1]) > 1e-6 ||
      std::abs(current[2] - bg[2]) > 1e-6);
  uniforms.Float4(
    "stylizeImageBackground", bg[0], bg[1], bg[2], this->ImageBackgroundApplied ? 1 : 0);
  if (this->ChannelSourceUsed)
  {
    const int* r = this->Internals->SourceRect;
    uniforms.Texture("stylizeSourceDepth", sourceTextures[0])
      .Texture("stylizeSourceNormal", sourceTextures[1])
      .Texture("stylizeSourcePosition", sourceTextures[2])
      .Texture("stylizeSourceDirection", sourceTextures[3])
      .Float4("stylizeSourceRect", r[0], r[1], r[2], r[3]);
    source->SetDepthMappingUniforms(program);
  }
  this->Internals->ReconstructQuad.Render();
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::DownloadChannel(int buffer, vtkFloatArray* out)
{
  vtkTextureObject* tex = vtkInternals::TextureOf(this, buffer);
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
namespace
{
// One process's part of a composite by depth: the rectangle (x, y, width, height) where it drew
// a surface and, inside it row by row, the stored depth and each channel (Components floats per
// pixel, in the order of the buffers composited).
struct ChannelPart
{
  int Rect[4] = { 0, 0, 0, 0 };
  std::vector<float> Depth;
  std::vector<std::vector<float>> Channels;

  vtkIdType Area() const { return static_cast<vtkIdType>(this->Rect[2]) * this->Rect[3]; }
};

const int ChannelTag = 735310; // and the next 6

// Floats per pixel of a G-buffer channel.
int ComponentsOf(int buffer)
{
  return buffer == vtkStylizeGBufferPass::LINEAR_DEPTH_BUFFER ? 1 : 4;
}

// Copies `from`'s pixels into `to`, whose rectangle holds `from`'s: all of them, or (nearer) only
// those nearer than what `to` holds.
void PastePart(ChannelPart& to, const ChannelPart& from, const std::vector<int>& components,
  bool nearer)
{
  for (int y = 0; y < from.Rect[3]; ++y)
  {
    for (int x = 0; x < from.Rect[2]; ++x)
    {
      const vtkIdType a = static_cast<vtkIdType>(y) * from.Rect[2] + x;
      const vtkIdType b = static_cast<vtkIdType>(y + from.Rect[1] - to.Rect[1]) * to.Rect[2] +
        (x + from.Rect[0] - to.Rect[0]);
      if (nearer && !(from.Depth[a] < to.Depth[b]))
      {
        continue;
      }
      to.Depth[b] = from.Depth[a];
      for (size_t c = 0; c < components.size(); ++c)
      {
        const int n = components[c];
        std::copy_n(&from.Channels[c][n * a], n, &to.Channels[c][n * b]);
      }
    }
  }
}

// The smallest rectangle holding both (x, y, width, height; an empty one holds nothing).
void UnionRect(const int a[4], const int b[4], int out[4])
{
  const bool hasA = a[2] > 0 && a[3] > 0;
  const bool hasB = b[2] > 0 && b[3] > 0;
  if (!hasA || !hasB)
  {
    std::copy(hasA ? a : b, (hasA ? a : b) + 4, out);
    return;
  }
  out[0] = std::min(a[0], b[0]);
  out[1] = std::min(a[1], b[1]);
  out[2] = std::max(a[0] + a[2], b[0] + b[2]) - out[0];
  out[3] = std::max(a[1] + a[3], b[1] + b[3]) - out[1];
}

// Keeps in `own` its pixels and, at every pixel of the union of both rectangles, `in`'s where it
// is nearer (ties: `own`, the lower process). Pixels of the union that neither holds get the
// depth 1 and zeros.
void MergePart(ChannelPart& own, ChannelPart& in, const std::vector<int>& components)
{
  if (in.Area() == 0)
  {
    return;
  }
  if (own.Area() == 0)
  {
    own = std::move(in);
    return;
  }
  ChannelPart u;
  UnionRect(own.Rect, in.Rect, u.Rect);
  u.Depth.assign(u.Area(), 1.0f);
  u.Channels.resize(components.size());
  for (size_t c = 0; c < components.size(); ++c)
  {
    u.Channels[c].assign(components[c] * u.Area(), 0.0f);
  }
  PastePart(u, own, components, false);
  PastePart(u, in, components, true);
  own = std::move(u);
}

// Whether rect lies inside a w x h image (an empty rectangle does).
bool InsideImage(const int rect[4], int w, int h)
{
  return rect[0] >= 0 && rect[1] >= 0 && rect[2] >= 0 && rect[3] >= 0 && rect[0] + rect[2] <= w &&
    rect[1] + rect[3] <= h;
}

// Replaces texels of a texture inside rect (x, y, width, height) with floats, rows bottom to
// top: a depth texture, a one-component or a four-component one.
void UploadTexels(vtkTextureObject* texture, const int rect[4], int buffer, const float* data)
{
  if (!texture || rect[2] <= 0 || rect[3] <= 0)
  {
    return;
  }
  const GLenum format = buffer == vtkStylizeGBufferPass::DEPTH_BUFFER ? GL_DEPTH_COMPONENT
    : ComponentsOf(buffer) == 1                                      ? GL_RED
                                                                     : GL_RGBA;
  texture->Activate();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, rect[0], rect[1], rect[2], rect[3], format, GL_FLOAT, data);
  texture->Deactivate();
}
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::vtkInternals::ReadPart(vtkStylizeGBufferPass* self,
  ChannelPart& part, const std::vector<int>& buffers, int w, int h, const int* rect)
{
  part = ChannelPart();
  part.Channels.resize(buffers.size());
  if (!self->FrameBufferObject || !self->DepthTexture)
  {
    return;
  }
  if (rect)
  {
    std::copy(rect, rect + 4, part.Rect);
    part.Depth.resize(part.Area());
    if (part.Area() > 0)
    {
      self->ReadBuffer(DEPTH_BUFFER, rect, part.Depth.data());
    }
  }
  else
  {
    // The rectangle where this G-buffer holds a surface.
    std::vector<float> depth(static_cast<size_t>(w) * h);
    const int whole[4] = { 0, 0, w, h };
    self->ReadBuffer(DEPTH_BUFFER, whole, depth.data());
    int lo[2] = { w, h }, hi[2] = { -1, -1 };
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        if (depth[static_cast<size_t>(y) * w + x] < 1.0f)
        {
          lo[0] = std::min(lo[0], x);
          lo[1] = std::min(lo[1], y);
          hi[0] = std::max(hi[0], x);
          hi[1] = std::max(hi[1], y);
        }
      }
    }
    if (hi[0] < 0)
    {
      return;
    }
    const int found[4] = { lo[0], lo[1], hi[0] - lo[0] + 1, hi[1] - lo[1] + 1 };
    std::copy(found, found + 4, part.Rect);
    part.Depth.resize(part.Area());
    for (int y = 0; y < found[3]; ++y)
    {
      std::copy_n(&depth[static_cast<size_t>(y + found[1]) * w + found[0]], found[2],
        &part.Depth[static_cast<size_t>(y) * found[2]]);
    }
  }
  for (size_t c = 0; c < buffers.size(); ++c)
  {
    part.Channels[c].resize(ComponentsOf(buffers[c]) * part.Area());
    if (part.Area() > 0)
    {
      self->ReadBuffer(buffers[c], part.Rect, part.Channels[c].data());
    }
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::vtkInternals::ReducePart(vtkStylizeGBufferPass* self,
  vtkMultiProcessController* controller, ChannelPart& own,
  const std::vector<int>& buffers, int w, int h)
{
  const int rank = controller->GetLocalProcessId();
  const int size = controller->GetNumberOfProcesses();
  std::vector<int> components;
  for (int buffer : buffers)
  {
    components.push_back(ComponentsOf(buffer));
  }
  // A binary tree towards process 0: at step s, process r (r mod 2s = s) sends to r - s.
  for (int step = 1; step < size; step *= 2)
  {
    if (rank % (2 * step) == step)
    {
      const int to = rank - step;
      controller->Send(own.Rect, 4, to, ChannelTag);
      if (own.Area() > 0)
      {
        controller->Send(own.Depth.data(), own.Area(), to, ChannelTag + 1);
        for (size_t c = 0; c < buffers.size(); ++c)
        {
          controller->Send(own.Channels[c].data(), components[c] * own.Area(), to,
            ChannelTag + 2 + static_cast<int>(c));
        }
      }
      return false;
    }
    if (rank + step < size)
    {
      const int from = rank + step;
      ChannelPart in;
      in.Channels.resize(buffers.size());
      controller->Receive(in.Rect, 4, from, ChannelTag);
      if (!InsideImage(in.Rect, w, h))
      {
        vtkErrorWithObjectMacro(self, "Process " << from << " sent channels outside the image.");
        std::fill(in.Rect, in.Rect + 4, 0);
      }
      if (in.Area() > 0)
      {
        in.Depth.resize(in.Area());
        controller->Receive(in.Depth.data(), in.Area(), from, ChannelTag + 1);
        for (size_t c = 0; c < buffers.size(); ++c)
        {
          in.Channels[c].resize(components[c] * in.Area());
          controller->Receive(in.Channels[c].data(), components[c] * in.Area(), from,
            ChannelTag + 2 + static_cast<int>(c));
        }
      }
      MergePart(own, in, components);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::vtkInternals::BroadcastDepth(vtkStylizeGBufferPass* self,
  vtkMultiProcessController* controller, ChannelPart& part, int w, int h)
{
  controller->Broadcast(part.Rect, 4, 0);
  if (!InsideImage(part.Rect, w, h))
  {
    vtkErrorWithObjectMacro(self, "Process 0 sent a depth outside the image.");
    std::fill(part.Rect, part.Rect + 4, 0);
    return;
  }
  part.Depth.resize(part.Area());
  if (part.Area() > 0)
  {
    controller->Broadcast(part.Depth.data(), part.Area(), 0);
  }
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::vtkInternals::ShareOpaqueDepth(vtkStylizeGBufferPass* self,
  vtkMultiProcessController* controller, vtkStylizeGBufferPass* opaque)
{
  // Every process's opaque G-buffer has process 0's size (the same view on every rank).
  const int w = opaque->GeometrySize[0];
  const int h = opaque->GeometrySize[1];
  const bool root = controller->GetLocalProcessId() == 0;
  ChannelPart part;
  if (root)
  {
    ReadPart(opaque, part, std::vector<int>(), w, h);
  }
  BroadcastDepth(self, controller, part, w, h);
  if (!root && opaque->DepthTexture)
  {
    std::vector<float> whole(static_cast<size_t>(w) * h, 1.0f);
    for (int y = 0; y < part.Rect[3]; ++y)
    {
      std::copy_n(&part.Depth[static_cast<size_t>(y) * part.Rect[2]], part.Rect[2],
        &whole[static_cast<size_t>(y + part.Rect[1]) * w + part.Rect[0]]);
    }
    const int rect[4] = { 0, 0, w, h };
    UploadTexels(opaque->DepthTexture, rect, DEPTH_BUFFER, whole.data());
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::vtkInternals::CompositeLayer(
  vtkStylizeGBufferPass* self, vtkMultiProcessController* controller, bool rendered)
{
  const int w = self->GeometrySize[0];
  const int h = self->GeometrySize[1];
  const bool root = controller->GetLocalProcessId() == 0;
  rendered = rendered && self->LayerHasSamples;
  std::vector<int> buffers; // every channel the layer holds
  for (int buffer : { COLOR_BUFFER, NORMAL_BUFFER, POSITION_BUFFER, LINEAR_DEPTH_BUFFER,
         DIRECTION_BUFFER })
  {
    if (TextureOf(self, buffer))
    {
      buffers.push_back(buffer);
    }
  }
  // 1. The other processes' layers, nearest by depth, to process 0.
  ChannelPart others;
  if (!root && rendered)
  {
    ReadPart(self, others, buffers, w, h);
  }
  ReducePart(self, controller, others, buffers, w, h);

  // 2. Process 0 lays them into its own layer where they are nearer (its own pixels read over
  // the union, its background included) and keeps the result in its textures.
  ChannelPart layer;
  if (root)
  {
    ChannelPart mine;
    if (rendered)
    {
      ReadPart(self, mine, std::vector<int>(), w, h);
    }
    int bounds[4];
    UnionRect(mine.Rect, others.Rect, bounds);
    if (bounds[2] > 0 && bounds[3] > 0 && self->DepthTexture)
    {
      ReadPart(self, layer, buffers, w, h, bounds);
      std::vector<int> components;
      for (int buffer : buffers)
      {
        components.push_back(ComponentsOf(buffer));
      }
      if (others.Area() > 0)
      {
        PastePart(layer, others, components, true);
      }
      for (size_t c = 0; c < buffers.size(); ++c)
      {
        UploadTexels(
          TextureOf(self, buffers[c]), layer.Rect, buffers[c], layer.Channels[c].data());
      }
      UploadTexels(self->DepthTexture, layer.Rect, DEPTH_BUFFER, layer.Depth.data());
    }
  }

  // 3. Every process peels the next layer behind this one: the layer's depth from process 0.
  BroadcastDepth(self, controller, layer, w, h);
  if (!root && self->DepthTexture)
  {
    UploadTexels(self->DepthTexture, layer.Rect, DEPTH_BUFFER, layer.Depth.data());
  }
  return layer.Area() > 0;
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::CompositeChannelSource(
  vtkOpenGLRenderWindow* renWin, bool rendered, int w, int h)
{
  vtkStylizeGBufferPass* source = this->ChannelSource;
  // Every process asked its source for the same channels.
  std::vector<int> buffers;
  for (auto channel : { std::make_pair(NORMAL, NORMAL_BUFFER),
         std::make_pair(POSITION, POSITION_BUFFER), std::make_pair(DIRECTION, DIRECTION_BUFFER) })
  {
    if (source->Channels & channel.first)
    {
      buffers.push_back(channel.second);
    }
  }

  // This process's part (where its source drew a surface), nearest by depth to process 0.
  ChannelPart own;
  if (rendered)
  {
    vtkInternals::ReadPart(source, own, buffers, w, h);
  }
  if (!vtkInternals::ReducePart(this, this->Controller, own, buffers, w, h) || own.Area() == 0)
  {
    return false;
  }

  // Process 0 keeps the result in textures: depth, normal, position, direction.
  std::copy(own.Rect, own.Rect + 4, this->Internals->SourceRect);
  vtkTextureObject** textures = this->Internals->Composited;
  const int slots[3] = { NORMAL_BUFFER, POSITION_BUFFER, DIRECTION_BUFFER };
  for (int i = 0; i < 4; ++i)
  {
    const float* data = i == 0 ? own.Depth.data() : nullptr;
    for (size_t c = 0; i > 0 && c < buffers.size(); ++c)
    {
      data = buffers[c] == slots[i - 1] ? own.Channels[c].data() : data;
    }
    if (!data)
    {
      vtkStylizeShaderUtilities::FreeTexture(textures[i], renWin);
      continue;
    }
    if (!textures[i])
    {
      textures[i] = vtkTextureObject::New();
    }
    textures[i]->SetContext(renWin);
    textures[i]->Create2DFromRaw(own.Rect[2], own.Rect[3], i == 0 ? 1 : 4, VTK_FLOAT,
      const_cast<float*>(data));
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Internals->CompositeQuad.Release(w);
  this->Internals->ReconstructQuad.Release(w);
  this->FreeTextures(w);
  if (this->SceneImagePass)
  {
    this->SceneImagePass->ReleaseGraphicsResources(w);
  }
  this->GeometryCameraPass->ReleaseGraphicsResources(w);
  this->AfterSequence->ReleaseGraphicsResources(w);
  this->LayerSequence->ReleaseGraphicsResources(w);
  if (this->LayerQuery && w)
  {
    // (the context is current while VTK releases graphics resources)
    glDeleteQueries(1, &this->LayerQuery);
  }
  this->LayerQuery = 0;
  this->OverlayPass->ReleaseGraphicsResources(w);
  if (this->LightingPass)
  {
    this->LightingPass->ReleaseGraphicsResources(w);
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkStylizeGBufferPass::GetShaderStageMTime()
{
  return this->ShaderStageTime.GetMTime();
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::PreReplaceShaderValues(std::string& vertexShader, std::string&,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{
  if (vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    if (this->Channels & DIRECTION)
    {
      // The direction attribute's outer product, in view coordinates (sign-free interpolation),
      // of the unit direction: a zero vector (no direction there) weighs nothing. The helpers of
      // VTK's composite data mapper upload no mapped array, only the standard attributes: there
      // the direction is the point data's tangents (VTK's tangentMC).
      const bool tangents = mapper->IsA("vtkCompositeMapperHelper2") != 0;
      const std::string attribute = tangents ? "tangentMC" : "stylizeDirectionMC";
      const std::string declaration =
        tangents ? std::string(TangentDeclaration) : "in vec3 stylizeDirectionMC;\n";
      vtkShaderProgram::Substitute(vertexShader, "//VTK::System::Dec",
        "//VTK::System::Dec\n" + declaration +
          "uniform mat3 stylizeDirectionMCVC;\n"
          "out vec3 stylizeDirDiagVSOutput;\nout vec3 stylizeDirOffVSOutput;\n",
        false);
      vtkShaderProgram::Substitute(vertexShader, "//VTK::Normal::Impl",
        "//VTK::Normal::Impl\n  vec3 stylizeDirVC = stylizeDirectionMCVC * " + attribute + ";\n"
        "  float stylizeDirLength = length(stylizeDirVC);\n"
        "  stylizeDirVC = stylizeDirLength > 0.0 && !isinf(stylizeDirLength) ?\n"
        "    stylizeDirVC / stylizeDirLength : vec3(0.0);\n"
        "  stylizeDirDiagVSOutput = stylizeDirVC * stylizeDirVC;\n"
        "  stylizeDirOffVSOutput = stylizeDirVC.xxy * stylizeDirVC.yzz;\n",
        false);
    }
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Impl",
      std::string("//VTK::Light::Impl\n  ") + GBufferTag, false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::PostReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  // The mapper declares tangentMC itself when it maps normals from a texture: not twice.
  const std::size_t own = vertexShader.find(TangentDeclaration);
  if (own != std::string::npos && vertexShader.find("in vec3 tangentMC;\n") != std::string::npos)
  {
    vertexShader.erase(own, std::strlen(TangentDeclaration));
  }
  if (fragmentShader.find(GBufferTag) == std::string::npos)
  {
    return true;
  }
  const bool surface = fragmentShader.find("normalVCVSOutput") != std::string::npos &&
    fragmentShader.find("vec4 vertexVC =") != std::string::npos;
  // The lighting pass (when it shades this shader) defines stylizeN, the normal it used.
  const bool stylizeLit =
    surface && fragmentShader.find("//VTK::StylizeLight::Impl") != std::string::npos;
  std::string normalValue, positionValue, linearDepthValue, directionValue;
  if (this->Channels & LINEAR_DEPTH)
  {
    linearDepthValue = surface ? "vec4(-vertexVC.z, 0.0, 0.0, 1.0)" : "vec4(0.0)";
  }
  if (this->Channels & NORMAL)
  {
    if (!surface)
    {
      normalValue = "vec4(0.0)";
    }
    else if (stylizeLit)
    {
      normalValue = "vec4(stylizeN, 1.0)";
    }
    else
    {
      vtkStylizeShaderUtilities::InjectCommon(fragmentShader);
      normalValue = "vec4(stylizeShadingNormal(normalVCVSOutput, stylizeFaceN, "
                    "cameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : -vertexVC.xyz), 1.0)";
    }
  }
  if (this->Channels & POSITION)
  {
    if (!surface)
    {
      positionValue = "vec4(0.0)";
    }
    else if (this->PositionSpace == OBJECT)
    {
      vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
        "//VTK::System::Dec\nuniform mat4 stylizeVCToMC;\n", false);
      positionValue = "vec4((stylizeVCToMC * vec4(vertexVC.xyz, 1.0)).xyz, 1.0)";
    }
    else
    {
      positionValue = "vec4(vertexVC.xyz, 1.0)";
    }
  }
  if (this->Channels & DIRECTION)
  {
    // (a geometry shader, for wide lines, would not pass the tensor on)
    if (!surface || !geometryShader.empty() ||
      vertexShader.find("stylizeDirDiagVSOutput") == std::string::npos)
    {
      directionValue = "vec4(0.0)";
    }
    else
    {
      vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
        std::string("//VTK::System::Dec\n") + vtkStylizeGBufferDirectionFS, false);
      directionValue = stylizeLit ? "stylizeTensorDirection(stylizeN)"
                                  : "stylizeTensorDirection(stylizeShadingNormal(normalVCVSOutput, "
                                    "stylizeFaceN, cameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : "
                                    "-vertexVC.xyz))";
      if (!stylizeLit)
      {
        vtkStylizeShaderUtilities::InjectCommon(fragmentShader);
      }
    }
  }
  // Keep the template's line for each allocated channel, with its literal attachment index.
  std::istringstream lines(vtkStylizeGBufferImpl);
  std::string line, code;
  int index = 1;
  while (std::getline(lines, line))
  {
    if (line.find("NORMAL_INDEX") != std::string::npos)
    {
      if (normalValue.empty())
      {
        continue;
      }
      vtkShaderProgram::Substitute(line, "NORMAL_INDEX", std::to_string(index++));
      vtkShaderProgram::Substitute(line, "NORMAL_VALUE", normalValue);
    }
    else if (line.find("POSITION_INDEX") != std::string::npos)
    {
      if (positionValue.empty())
      {
        continue;
      }
      vtkShaderProgram::Substitute(line, "POSITION_INDEX", std::to_string(index++));
      vtkShaderProgram::Substitute(line, "POSITION_VALUE", positionValue);
    }
    else if (line.find("LINEAR_DEPTH_INDEX") != std::string::npos)
    {
      if (linearDepthValue.empty())
      {
        continue;
      }
      vtkShaderProgram::Substitute(line, "LINEAR_DEPTH_INDEX", std::to_string(index++));
      vtkShaderProgram::Substitute(line, "LINEAR_DEPTH_VALUE", linearDepthValue);
    }
    else if (line.find("DIRECTION_INDEX") != std::string::npos)
    {
      if (directionValue.empty())
      {
        continue;
      }
      vtkShaderProgram::Substitute(line, "DIRECTION_INDEX", std::to_string(index++));
      vtkShaderProgram::Substitute(line, "DIRECTION_VALUE", directionValue);
    }
    code += line + "\n";
  }
  // The depth the G-buffer stores: the window depth (VTK's own when its shader writes one) or,
  // after VTK's depth code (//VTK::Depth::Impl), the logarithmic depth that overrides it.
  // (VTK's template names gl_FragDepth in a comment: look for an assignment)
  std::string depth = fragmentShader.find("gl_FragDepth =") != std::string::npos
    ? "gl_FragDepth"
    : "gl_FragCoord.z";
  if (this->LogarithmicDepth)
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
      "//VTK::System::Dec\nuniform vec2 stylizeLogDepthRange;\n", false);
    const std::string z = surface ? "-vertexVC.z"
                                  : "(2.0 * stylizeLogDepthRange.x * stylizeLogDepthRange.y / "
                                    "(stylizeLogDepthRange.y + stylizeLogDepthRange.x - "
                                    "(2.0 * gl_FragCoord.z - 1.0) * (stylizeLogDepthRange.y - "
                                    "stylizeLogDepthRange.x)))";
    code += "  gl_FragDepth = clamp(log(max(" + z +
      ", stylizeLogDepthRange.x) / stylizeLogDepthRange.x) / log(stylizeLogDepthRange.y / "
      "stylizeLogDepthRange.x), 0.0, 1.0);\n";
    depth = "gl_FragDepth";
  }
  if (this->LayerIndex >= 0)
  {
    // A translucent layer (RenderTranslucentLayer()): only what lies in front of the opaque
    // depth and, when peeling, behind the previous layer's.
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
      "//VTK::System::Dec\nuniform sampler2D stylizeOpaqueDepth;\n"
      "uniform sampler2D stylizePeelDepth;\nuniform int stylizePeel;\n",
      false);
    code += "  {\n"
            "    ivec2 stylizeTexel = ivec2(gl_FragCoord.xy);\n"
            "    float stylizeZ = " + depth + ";\n"
            "    if (stylizeZ > texelFetch(stylizeOpaqueDepth, stylizeTexel, 0).r ||\n"
            "      (stylizePeel == 1 && stylizeZ <= texelFetch(stylizePeelDepth, stylizeTexel, 0).r))\n"
            "    {\n"
            "      discard;\n"
            "    }\n"
            "  }\n";
  }
  vtkShaderProgram::Substitute(fragmentShader, GBufferTag, code);
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::SetDepthMappingUniforms(vtkShaderProgram* program)
{
  if (program && program->IsUniformUsed("stylizeDepthMapping"))
  {
    const float mapping[3] = { static_cast<float>(this->DepthRange[0]),
      static_cast<float>(this->DepthRange[1]), this->LogarithmicDepth ? 1.0f : 0.0f };
    program->SetUniform3f("stylizeDepthMapping", mapping);
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  if (!this->FrameBufferObject)
  {
    return true;
  }
  if (vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    this->FrameBufferObject->ActivateDrawBuffers(this->NumberOfAttachments);
  }
  else
  {
    this->FrameBufferObject->ActivateDrawBuffers(1);
  }
  if (this->LayerIndex >= 0 && program->IsUniformUsed("stylizeOpaqueDepth"))
  {
    program->SetUniformi("stylizeOpaqueDepth", this->LayerOpaqueDepth->GetTextureUnit());
    const bool peel = this->LayerIndex > 0;
    program->SetUniformi("stylizePeel", peel ? 1 : 0);
    program->SetUniformi("stylizePeelDepth",
      (peel ? this->PeelDepthTexture : this->LayerOpaqueDepth)->GetTextureUnit());
  }
  if (program->IsUniformUsed("stylizeLogDepthRange"))
  {
    const float range[2] = { static_cast<float>(this->DepthRange[0]),
      static_cast<float>(this->DepthRange[1]) };
    program->SetUniform2f("stylizeLogDepthRange", range);
  }
  vtkProp3D* prop3D = vtkProp3D::SafeDownCast(prop);
  if (program->IsUniformUsed("stylizeDirectionMCVC"))
  {
    // model -> world -> view, the 3x3 part (directions are vectors), column-major for GLSL
    vtkMatrix4x4* m = this->Internals->Product;
    m->DeepCopy(this->Internals->View);
    if (prop3D)
    {
      vtkMatrix4x4::Multiply4x4(this->Internals->View, prop3D->GetMatrix(), m);
    }
    float columns[9];
    for (int c = 0; c < 3; ++c)
    {
      for (int r = 0; r < 3; ++r)
      {
        columns[c * 3 + r] = static_cast<float>(m->GetElement(r, c));
      }
    }
    program->SetUniformMatrix3x3("stylizeDirectionMCVC", columns);
  }
  if (program->IsUniformUsed("stylizeVCToMC"))
  {
    // view -> world (inverse camera view) -> model (inverse prop matrix), in double precision
    vtkMatrix4x4* m = this->Internals->Product;
    m->DeepCopy(this->Internals->InverseView);
    if (prop3D)
    {
      vtkMatrix4x4::Invert(prop3D->GetMatrix(), this->Internals->InverseModel);
      vtkMatrix4x4::Multiply4x4(this->Internals->InverseModel, m, m);
    }
    m->Transpose(); // vtkShaderProgram uploads row-major data as GLSL columns
    program->SetUniformMatrix("stylizeVCToMC", m);
  }
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizeGBufferPass::GetTextureBytes()
{
  vtkIdType total = 0;
  for (vtkTextureObject* t : { this->ColorTexture, this->NormalTexture, this->PositionTexture,
         this->LinearDepthTexture, this->DepthTexture, this->DirectionTexture,
         this->ImageColorTexture, this->ImageDepthTexture })
  {
    total += vtkStylizeShaderUtilities::TextureBytes(t);
  }
  for (vtkTextureObject* t : this->Internals->Composited)
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
