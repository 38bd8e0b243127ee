#include "vtkStylizePlainVolumes.h"

#include "vtkCamera.h"
#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderPass.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkStylizeCompositeFS.h"
#include "vtkStylizeDepthFS.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace
{
const int LayerTag = 735350; // and the next 2
using Part = vtkStylizeRankCompositor::Part;

/** The union of the props' bounds (an invalid box when none has any). */
std::array<double, 6> BoxOf(const std::vector<vtkProp*>& props)
{
  std::array<double, 6> box = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  for (vtkProp* prop : props)
  {
    const double* b = prop ? prop->GetBounds() : nullptr;
    if (!b || b[0] > b[1])
    {
      continue;
    }
    const bool first = box[0] > box[1];
    for (int i = 0; i < 3; ++i)
    {
      box[2 * i] = first ? b[2 * i] : std::min(box[2 * i], b[2 * i]);
      box[2 * i + 1] = first ? b[2 * i + 1] : std::max(box[2 * i + 1], b[2 * i + 1]);
    }
  }
  return box;
}

/** Keeps, of w x h RGBA, the smallest rectangle holding every pixel with any colour. */
void Crop(const std::vector<float>& rgba, int w, int h, Part& part)
{
  int x0 = w, y0 = h, x1 = -1, y1 = -1;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const float* p = &rgba[4 * (static_cast<size_t>(y) * w + x)];
      if (p[0] > 0.0f || p[1] > 0.0f || p[2] > 0.0f || p[3] > 0.0f)
      {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
    }
  }
  part.Channels.assign(1, std::vector<float>());
  if (x1 < 0)
  {
    std::fill(part.Rect, part.Rect + 4, 0);
    return;
  }
  part.Rect[0] = x0;
  part.Rect[1] = y0;
  part.Rect[2] = x1 - x0 + 1;
  part.Rect[3] = y1 - y0 + 1;
  part.Channels[0].resize(4 * part.Area());
  for (int y = 0; y < part.Rect[3]; ++y)
  {
    std::copy_n(&rgba[4 * (static_cast<size_t>(y + y0) * w + x0)], 4 * part.Rect[2],
      &part.Channels[0][4 * static_cast<size_t>(y) * part.Rect[2]]);
  }
}
}

vtkStandardNewMacro(vtkStylizePlainVolumes);

//------------------------------------------------------------------------------
vtkStylizePlainVolumes::~vtkStylizePlainVolumes()
{
  this->ReleaseGraphicsResources(nullptr);
}

//------------------------------------------------------------------------------
void vtkStylizePlainVolumes::Render(const vtkRenderState* s, const std::vector<vtkProp*>& volumes,
  vtkRenderPass* volumePass, vtkMultiProcessController* controller)
{
  int local = volumes.empty() ? 0 : 1;
  int any = 0;
  controller->AllReduce(&local, &any, 1, vtkCommunicator::MAX_OP);
  vtkRenderer* ren = s->GetRenderer();
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!any || !renWin)
  {
    return;
  }
  int* v = this->Viewport;
  ren->GetTiledSizeAndOrigin(&v[2], &v[3], &v[0], &v[1]);
  this->ShareDepth(renWin, controller);
  VolumeLayer own;
  this->DrawLayer(s, volumes, volumePass);
  Crop(this->Pixels, v[2], v[3], own.Pixels);
  own.Box = BoxOf(volumes);
  if (this->CompositeLayers(ren, own, controller))
  {
    this->BlendOver(renWin);
  }
}

//------------------------------------------------------------------------------
void vtkStylizePlainVolumes::ShareDepth(
  vtkOpenGLRenderWindow* renWin, vtkMultiProcessController* controller)
{
  const int* v = this->Viewport;
  Part& depth = this->Shared;
  std::fill(depth.Rect, depth.Rect + 4, 0);
  if (controller->GetLocalProcessId() == 0)
  {
    const int rect[4] = { 0, 0, v[2], v[3] };
    std::copy(rect, rect + 4, depth.Rect);
    depth.Depth.resize(depth.Area());
    GLint draw = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    vtkOpenGLState* ostate = renWin->GetState();
    ostate->PushReadFramebufferBinding();
    ostate->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, draw);
    glReadPixels(v[0], v[1], v[2], v[3], GL_DEPTH_COMPONENT, GL_FLOAT, depth.Depth.data());
    ostate->PopReadFramebufferBinding();
  }
  this->Compositor->SetController(controller);
  this->Compositor->BroadcastDepth(depth, v[2], v[3]);
  this->Compositor->SetController(nullptr);
  this->Depths.assign(static_cast<size_t>(v[2]) * v[3], 1.0f);
  for (int y = 0; y < depth.Rect[3]; ++y)
  {
    std::copy_n(&depth.Depth[static_cast<size_t>(y) * depth.Rect[2]], depth.Rect[2],
      &this->Depths[static_cast<size_t>(y + depth.Rect[1]) * v[2] + depth.Rect[0]]);
  }
}

//------------------------------------------------------------------------------
void vtkStylizePlainVolumes::DrawLayer(
  const vtkRenderState* s, const std::vector<vtkProp*>& volumes, vtkRenderPass* volumePass)
{
  const int* v = this->Viewport;
  std::vector<float>& rgba = this->Pixels;
  rgba.assign(4 * static_cast<size_t>(v[2]) * v[3], 0.0f);
  if (volumes.empty())
  {
    return;
  }
  const std::vector<float>& depth = this->Depths;
  vtkRenderer* ren = s->GetRenderer();
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  using Utilities = vtkStylizeShaderUtilities;
  const int w = v[0] + v[2];
  const int h = v[1] + v[3];
  Utilities::EnsureScreenTexture(this->Color, renWin, w, h, GL_RGBA32F);
  const int format = renWin->GetStencilCapable() ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT32F;
  Utilities::EnsureScreenTexture(this->Depth, renWin, w, h, format, format != this->DepthFormat);
  this->DepthFormat = format;
  this->Depth->Activate();
  if (format == GL_DEPTH24_STENCIL8)
  {
    std::vector<GLuint>& packed = this->Packed;
    packed.resize(depth.size());
    for (size_t i = 0; i < depth.size(); ++i)
    {
      const double d = std::min(std::max(static_cast<double>(depth[i]), 0.0), 1.0);
      packed[i] = static_cast<GLuint>(d * 16777215.0 + 0.5) << 8;
    }
    glTexSubImage2D(GL_TEXTURE_2D, 0, v[0], v[1], v[2], v[3], GL_DEPTH_STENCIL,
      GL_UNSIGNED_INT_24_8, packed.data());
  }
  else
  {
    glTexSubImage2D(
      GL_TEXTURE_2D, 0, v[0], v[1], v[2], v[3], GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  }
  this->Depth->Deactivate();
  if (!this->FrameBuffer)
  {
    this->FrameBuffer = vtkOpenGLFramebufferObject::New();
    this->FrameBuffer->SetContext(renWin);
  }
  vtkOpenGLFramebufferObject* fbo = this->FrameBuffer;
  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  fbo->AddColorAttachment(0, this->Color);
  fbo->ActivateDrawBuffers(1);
  fbo->AddDepthAttachment(this->Depth);
  {
    vtkStylizeScopedOutputState saved(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
    vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
    ostate->vtkglViewport(v[0], v[1], v[2], v[3]);
    ostate->vtkglScissor(v[0], v[1], v[2], v[3]);
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_LEQUAL);
    vtkRenderState state(ren);
    std::vector<vtkProp*> props(volumes);
    state.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
    state.SetFrameBuffer(fbo);
    volumePass->Render(&state);
    glReadPixels(v[0], v[1], v[2], v[3], GL_RGBA, GL_FLOAT, rgba.data());
  }
  fbo->RestorePreviousBindingsAndBuffers();
}

//------------------------------------------------------------------------------
bool vtkStylizePlainVolumes::CompositeLayers(
  vtkRenderer* ren, VolumeLayer& own, vtkMultiProcessController* controller)
{
  const int vw = this->Viewport[2];
  const int vh = this->Viewport[3];
  if (controller->GetLocalProcessId() != 0)
  {
    controller->Send(own.Pixels.Rect, 4, 0, LayerTag);
    controller->Send(own.Box.data(), 6, 0, LayerTag + 1);
    if (own.Pixels.Area() > 0)
    {
      controller->Send(own.Pixels.Channels[0].data(), 4 * own.Pixels.Area(), 0, LayerTag + 2);
    }
    return false;
  }
  std::vector<VolumeLayer> layers;
  layers.push_back(std::move(own));
  for (int from = 1; from < controller->GetNumberOfProcesses(); ++from)
  {
    VolumeLayer in;
    controller->Receive(in.Pixels.Rect, 4, from, LayerTag);
    controller->Receive(in.Box.data(), 6, from, LayerTag + 1);
    const vtkIdType area = in.Pixels.Area();
    if (area > 0)
    {
      in.Pixels.Channels.assign(1, std::vector<float>(4 * area));
      controller->Receive(in.Pixels.Channels[0].data(), 4 * area, from, LayerTag + 2);
    }
    if (!vtkStylizeRankCompositor::InsideImage(in.Pixels.Rect, vw, vh))
    {
      vtkErrorMacro("Process " << from << " sent a volume layer outside the image.");
      continue;
    }
    layers.push_back(std::move(in));
  }
  layers.erase(std::remove_if(layers.begin(), layers.end(),
                 [](const VolumeLayer& l) { return l.Pixels.Area() == 0; }),
    layers.end());
  if (layers.empty())
  {
    return false;
  }
  vtkCamera* camera = ren->GetActiveCamera();
  const bool parallel = camera->GetParallelProjection() != 0;
  double eye[3], direction[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(direction);
  // (insertion: front first; a partition's boxes order consistently)
  for (size_t i = 1; i < layers.size(); ++i)
  {
    for (size_t j = i; j > 0 &&
         vtkStylizeRankCompositor::InFront(
           layers[j].Box.data(), layers[j - 1].Box.data(), parallel, eye, direction);
         --j)
    {
      std::swap(layers[j], layers[j - 1]);
    }
  }
  // premultiplied colours, front to back: what lies behind shows through what is in front
  std::vector<float>& over = this->Over;
  over.assign(4 * static_cast<size_t>(vw) * vh, 0.0f);
  for (const VolumeLayer& layer : layers)
  {
    const Part& p = layer.Pixels;
    for (int y = 0; y < p.Rect[3]; ++y)
    {
      for (int x = 0; x < p.Rect[2]; ++x)
      {
        const float* c = &p.Channels[0][4 * (static_cast<size_t>(y) * p.Rect[2] + x)];
        float* o = &over[4 * (static_cast<size_t>(y + p.Rect[1]) * vw + x + p.Rect[0])];
        const float behind = 1.0f - std::min(std::max(o[3], 0.0f), 1.0f);
        for (int k = 0; k < 4; ++k)
        {
          o[k] += behind * c[k];
        }
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizePlainVolumes::BlendOver(vtkOpenGLRenderWindow* renWin)
{
  const int* v = this->Viewport;
  vtkOpenGLState* ostate = renWin->GetState();
  vtkStylizeShaderUtilities::EnsureScreenTexture(this->Layer, renWin, v[2], v[3], GL_RGBA32F);
  this->Layer->Activate();
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, v[2], v[3], GL_RGBA, GL_FLOAT, this->Over.data());
  static const std::string declarations = std::string(vtkStylizeDepthFS) + vtkStylizeCompositeFS;
  vtkShaderProgram* program =
    this->Quad.Prepare(renWin, declarations, "  stylizeCompositeLayer();\n");
  if (program)
  {
    vtkStylizeScopedOutputState saved(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
    ostate->vtkglViewport(v[0], v[1], v[2], v[3]);
    ostate->vtkglScissor(v[0], v[1], v[2], v[3]);
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ostate->vtkglDepthMask(GL_FALSE);
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    program->SetUniformi("stylizeColorTexture", this->Layer->GetTextureUnit());
    this->Quad.Render();
  }
  else
  {
    vtkErrorMacro("Could not build the volume layer's shader.");
  }
  this->Layer->Deactivate();
}

//------------------------------------------------------------------------------
void vtkStylizePlainVolumes::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkStylizeShaderUtilities::FreeTexture(this->Color, w);
  vtkStylizeShaderUtilities::FreeTexture(this->Depth, w);
  vtkStylizeShaderUtilities::FreeTexture(this->Layer, w);
  this->DepthFormat = 0;
  if (this->FrameBuffer)
  {
    if (w)
    {
      this->FrameBuffer->ReleaseGraphicsResources(w);
    }
    this->FrameBuffer->Delete();
    this->FrameBuffer = nullptr;
  }
  if (w)
  {
    this->Quad.Release(w);
  }
}
