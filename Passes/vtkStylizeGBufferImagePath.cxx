#include "vtkStylizeGBufferImagePath.h"

#include "vtkCamera.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeGBufferTransfer.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkStylizeDepthFS.h"
#include "vtkStylizeReconstructFS.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

class vtkStylizeGBufferImagePath::vtkInternals
{
public:
  vtkStylizeScreenQuad ReconstructQuad;
};

vtkStandardNewMacro(vtkStylizeGBufferImagePath);

using Part = vtkStylizeRankCompositor::Part;

//------------------------------------------------------------------------------
vtkStylizeGBufferImagePath::vtkStylizeGBufferImagePath()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkStylizeGBufferImagePath::~vtkStylizeGBufferImagePath()
{
  this->FreeTextures(nullptr);
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferImagePath::FreeTextures(vtkWindow* w)
{
  for (vtkTextureObject** tex : { &this->ColorTexture, &this->DepthTexture })
  {
    vtkStylizeShaderUtilities::FreeTexture(*tex, w);
  }
  for (vtkTextureObject*& tex : this->Composited)
  {
    vtkStylizeShaderUtilities::FreeTexture(tex, w);
  }
  if (this->FrameBuffer)
  {
    if (w)
    {
      this->FrameBuffer->ReleaseGraphicsResources(w);
    }
    this->FrameBuffer->Delete();
    this->FrameBuffer = nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferImagePath::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Internals->ReconstructQuad.Release(w);
  this->FreeTextures(w);
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizeGBufferImagePath::GetTextureBytes()
{
  vtkIdType total = vtkStylizeShaderUtilities::TextureBytes(this->ColorTexture) +
    vtkStylizeShaderUtilities::TextureBytes(this->DepthTexture);
  for (vtkTextureObject* t : this->Composited)
  {
    total += vtkStylizeShaderUtilities::TextureBytes(t);
  }
  return total;
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferImagePath::Render(const vtkRenderState* s, vtkStylizeGBufferPass* gbuffer,
  vtkOpenGLRenderWindow* renWin, int gw, int gh, vtkMatrix4x4* inverseView)
{
  const int w = gbuffer->GetViewport()[2];
  const int h = gbuffer->GetViewport()[3];
  this->RenderImage(s, gbuffer, renWin, w, h);
  this->Reconstruct(s, gbuffer, renWin, gw, gh, inverseView);
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferImagePath::RenderImage(const vtkRenderState* s,
  vtkStylizeGBufferPass* gbuffer, vtkOpenGLRenderWindow* renWin, int w, int h)
{
  vtkRenderer* ren = s->GetRenderer();
  using Utilities = vtkStylizeShaderUtilities;
  Utilities::EnsureScreenTexture(this->ColorTexture, renWin, w, h,
    gbuffer->GetPrecision() == vtkStylizeGBufferPass::FULL ? GL_RGBA32F : GL_RGBA16F);
  // The depth in the window's own format: VTK's GPU ray caster (ParaView's VTK) blits the bound
  // depth into a texture of that format, and a blit between depth formats fails (its rays then
  // pass through opaque geometry: a volume the style leaves plain, drawn into this image).
  const int depthFormat = renWin->GetStencilCapable() ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT32F;
  Utilities::EnsureScreenTexture(
    this->DepthTexture, renWin, w, h, depthFormat, depthFormat != this->DepthFormat);
  this->DepthFormat = depthFormat;
  if (!this->FrameBuffer)
  {
    this->FrameBuffer = vtkOpenGLFramebufferObject::New();
    this->FrameBuffer->SetContext(renWin);
  }

  // The scene pass renders into colour and depth at the viewport's size.
  vtkOpenGLFramebufferObject* image = this->FrameBuffer;
  vtkOpenGLState* ostate = renWin->GetState();
  image->SaveCurrentBindingsAndBuffers();
  image->Bind();
  image->AddColorAttachment(0, this->ColorTexture);
  image->ActivateDrawBuffers(1);
  image->AddDepthAttachment(this->DepthTexture);
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
  // with the G-buffer's channels.
  vtkStylizeGBufferPass* source = gbuffer->GetChannelSource();
  const vtkTypeUInt64 sourceRenders = source ? source->GeometryRenders : 0;
  const int sourceChannels = gbuffer->GetChannels() &
    (vtkStylizeGBufferPass::NORMAL | vtkStylizeGBufferPass::POSITION |
      vtkStylizeGBufferPass::LINEAR_DEPTH | vtkStylizeGBufferPass::DIRECTION);
  if (source)
  {
    source->SetChannels(sourceChannels);
    source->SetPositionSpace(gbuffer->GetPositionSpace());
    source->SetNormalPrecision(gbuffer->GetPrecision() == vtkStylizeGBufferPass::FULL
        ? vtkStylizeGBufferPass::FULL
        : gbuffer->GetNormalPrecision());
    source->SetGeometryResolution(0, 0);
    source->SetGeometryScreenTransform(1.0, 1.0, 0.0, 0.0);
  }
  vtkRenderPass* scene = gbuffer->GetSceneImagePass();
  scene->Render(&simage);
  gbuffer->NumberOfRenderedProps += scene->GetNumberOfRenderedProps();
  image->UnBind();
  image->RestorePreviousBindingsAndBuffers();
  const bool sourceRendered = source && source->GeometryRenders != sourceRenders &&
    source->GetGeometrySize()[0] == w && source->GetGeometrySize()[1] == h &&
    source->GetChannels() == sourceChannels;
  vtkMultiProcessController* controller = gbuffer->GetController();
  const bool composited = controller && controller->GetNumberOfProcesses() > 1;
  gbuffer->ChannelSourceUsed = false;
  if (source && composited)
  {
    gbuffer->ChannelSourceUsed =
      this->CompositeChannelSource(gbuffer, renWin, sourceRendered, w, h);
  }
  else if (sourceRendered)
  {
    gbuffer->ChannelSourceUsed = true;
    const int whole[4] = { 0, 0, w, h };
    std::copy(whole, whole + 4, this->SourceRect);
  }
  std::fill(this->SourceTextures, this->SourceTextures + SourceSlots, nullptr);
  if (gbuffer->ChannelSourceUsed)
  {
    vtkTextureObject* const own[SourceSlots] = { source->GetDepthTexture(),
      source->GetNormalTexture(), source->GetPositionTexture(), source->GetDirectionTexture(),
      source->GetLinearDepthTexture() };
    for (int i = 0; i < SourceSlots; ++i)
    {
      this->SourceTextures[i] = composited ? this->Composited[i] : own[i];
    }
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferImagePath::CompositeChannelSource(
  vtkStylizeGBufferPass* gbuffer, vtkOpenGLRenderWindow* renWin, bool rendered, int w, int h)
{
  vtkStylizeGBufferPass* source = gbuffer->GetChannelSource();
  // Every process asked its source for the same channels.
  std::vector<int> buffers;
  for (auto channel :
    { std::make_pair(vtkStylizeGBufferPass::NORMAL, vtkStylizeGBufferPass::NORMAL_BUFFER),
      std::make_pair(vtkStylizeGBufferPass::POSITION, vtkStylizeGBufferPass::POSITION_BUFFER),
      std::make_pair(vtkStylizeGBufferPass::DIRECTION, vtkStylizeGBufferPass::DIRECTION_BUFFER),
      std::make_pair(
        vtkStylizeGBufferPass::LINEAR_DEPTH, vtkStylizeGBufferPass::LINEAR_DEPTH_BUFFER) })
  {
    if (source->GetChannels() & channel.first)
    {
      buffers.push_back(channel.second);
    }
  }

  // This process's part (where its source drew a surface), nearest by depth to process 0.
  Part own;
  if (rendered)
  {
    vtkStylizeGBufferTransfer::ReadPart(source, own, buffers, w, h);
  }
  this->Compositor->SetController(gbuffer->GetController());
  const bool root =
    this->Compositor->Reduce(own, vtkStylizeGBufferTransfer::ComponentsOf(buffers), w, h);
  this->Compositor->SetController(nullptr);
  if (!root || own.Area() == 0)
  {
    return false;
  }

  // Process 0 keeps the result in textures: depth, normal, position, direction, linear depth.
  std::copy(own.Rect, own.Rect + 4, this->SourceRect);
  const int slots[SourceSlots - 1] = { vtkStylizeGBufferPass::NORMAL_BUFFER,
    vtkStylizeGBufferPass::POSITION_BUFFER, vtkStylizeGBufferPass::DIRECTION_BUFFER,
    vtkStylizeGBufferPass::LINEAR_DEPTH_BUFFER };
  for (int i = 0; i < SourceSlots; ++i)
  {
    const float* data = i == 0 ? own.Depth.data() : nullptr;
    for (size_t c = 0; i > 0 && c < buffers.size(); ++c)
    {
      data = buffers[c] == slots[i - 1] ? own.Channels[c].data() : data;
    }
    vtkTextureObject*& texture = this->Composited[i];
    if (!data)
    {
      vtkStylizeShaderUtilities::FreeTexture(texture, renWin);
      continue;
    }
    if (!texture)
    {
      texture = vtkTextureObject::New();
    }
    texture->SetContext(renWin);
    const int components =
      i == 0 || slots[i - 1] == vtkStylizeGBufferPass::LINEAR_DEPTH_BUFFER ? 1 : 4;
    texture->Create2DFromRaw(
      own.Rect[2], own.Rect[3], components, VTK_FLOAT, const_cast<float*>(data));
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferImagePath::Reconstruct(const vtkRenderState* s,
  vtkStylizeGBufferPass* gbuffer, vtkOpenGLRenderWindow* renWin, int gw, int gh,
  vtkMatrix4x4* inverseView)
{
  vtkRenderer* ren = s->GetRenderer();
  const int w = gbuffer->GetViewport()[2];
  const int h = gbuffer->GetViewport()[3];
  // The requested channels, in attachment order, with literal gl_FragData indices.
  std::ostringstream body;
  body << "  stylizeReconstruct();\n  gl_FragData[0] = stylizeOutColor;\n";
  int index = 1;
  for (auto channel : { std::make_pair(gbuffer->GetNormalTexture(), "stylizeOutNormal"),
         std::make_pair(gbuffer->GetPositionTexture(), "stylizeOutPosition"),
         std::make_pair(gbuffer->GetLinearDepthTexture(), "stylizeOutLinearDepth"),
         std::make_pair(gbuffer->GetDirectionTexture(), "stylizeOutDirection") })
  {
    if (channel.first)
    {
      body << "  gl_FragData[" << index++ << "] = " << channel.second << ";\n";
    }
  }
  std::string defines = gbuffer->GetPositionSpace() == vtkStylizeGBufferPass::OBJECT
    ? "#define STYLIZE_POSITION_WORLD\n"
    : "";
  if (gbuffer->ChannelSourceUsed)
  {
    defines += "#define STYLIZE_CHANNEL_SOURCE\n";
    const char* const names[SourceSlots] = { nullptr, "NORMAL", "POSITION", "DIRECTION",
      "LINEAR_DEPTH" };
    for (int i = 1; i < SourceSlots; ++i)
    {
      if (this->SourceTextures[i])
      {
        defines += std::string("#define STYLIZE_SOURCE_") + names[i] + "\n";
      }
    }
  }
  vtkShaderProgram* program = this->Internals->ReconstructQuad.Prepare(
    renWin, defines + vtkStylizeDepthFS + vtkStylizeReconstructFS, body.str());
  if (!program)
  {
    vtkErrorWithObjectMacro(gbuffer, "Could not build the G-buffer reconstruction shader.");
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
  vtkMatrix4x4* upload = this->Upload;
  vtkMatrix4x4::Invert(
    ren->GetActiveCamera()->GetProjectionTransformMatrix(aspectRatio, -1.0, 1.0), upload);
  upload->Transpose();
  program->SetUniformMatrix("stylizeInverseProjection", upload);
  vtkMatrix4x4::Transpose(inverseView, upload);
  program->SetUniformMatrix("stylizeInverseView", upload);

  vtkOpenGLState* ostate = renWin->GetState();
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
  const double* t = gbuffer->GeometryScreenTransform;
  vtkStylizeUniforms uniforms(program);
  uniforms.Texture("stylizeImageColor", this->ColorTexture)
    .Texture("stylizeImageDepth", this->DepthTexture)
    .Float4("stylizeScreenTransform", t[0], t[1], t[2], t[3])
    .Float2("stylizeImageSize", w, h);
  const double* bg = gbuffer->GetImageBackground();
  const double* current = ren->GetBackground();
  gbuffer->ImageBackgroundApplied = gbuffer->GetUseImageBackground() &&
    (std::abs(current[0] - bg[0]) > 1e-6 || std::abs(current[1] - bg[1]) > 1e-6 ||
      std::abs(current[2] - bg[2]) > 1e-6);
  uniforms.Float4(
    "stylizeImageBackground", bg[0], bg[1], bg[2], gbuffer->ImageBackgroundApplied ? 1 : 0);
  if (gbuffer->ChannelSourceUsed)
  {
    const int* r = this->SourceRect;
    uniforms.Texture("stylizeSourceDepth", this->SourceTextures[0])
      .Texture("stylizeSourceNormal", this->SourceTextures[1])
      .Texture("stylizeSourcePosition", this->SourceTextures[2])
      .Texture("stylizeSourceDirection", this->SourceTextures[3])
      .Texture("stylizeSourceLinearDepth", this->SourceTextures[4])
      .Float4("stylizeSourceRect", r[0], r[1], r[2], r[3]);
    gbuffer->GetChannelSource()->SetDepthMappingUniforms(program);
  }
  this->Internals->ReconstructQuad.Render();
}
