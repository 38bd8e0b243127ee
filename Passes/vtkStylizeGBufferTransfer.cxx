#include "vtkStylizeGBufferTransfer.h"

#include "vtkStylizeGBufferPass.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>

namespace vtkStylizeGBufferTransfer
{
//------------------------------------------------------------------------------
int ComponentsOf(int buffer)
{
  return buffer == vtkStylizeGBufferPass::LINEAR_DEPTH_BUFFER ? 1 : 4;
}

//------------------------------------------------------------------------------
std::vector<int> ComponentsOf(const std::vector<int>& buffers)
{
  std::vector<int> components;
  for (int buffer : buffers)
  {
    components.push_back(ComponentsOf(buffer));
  }
  return components;
}

//------------------------------------------------------------------------------
void ReadPart(vtkStylizeGBufferPass* gbuffer, vtkStylizeRankCompositor::Part& part,
  const std::vector<int>& buffers, int w, int h, const int* rect)
{
  part = vtkStylizeRankCompositor::Part();
  part.Channels.resize(buffers.size());
  if (!gbuffer->GetFrameBufferObject() || !gbuffer->GetDepthTexture())
  {
    return;
  }
  const int depthBuffer = vtkStylizeGBufferPass::DEPTH_BUFFER;
  if (rect)
  {
    std::copy(rect, rect + 4, part.Rect);
    part.Depth.resize(part.Area());
    if (part.Area() > 0)
    {
      gbuffer->ReadBuffer(depthBuffer, rect, part.Depth.data());
    }
  }
  else
  {
    // The rectangle where this G-buffer holds a surface.
    std::vector<float> depth(static_cast<size_t>(w) * h);
    const int whole[4] = { 0, 0, w, h };
    gbuffer->ReadBuffer(depthBuffer, whole, depth.data());
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
      gbuffer->ReadBuffer(buffers[c], part.Rect, part.Channels[c].data());
    }
  }
}

//------------------------------------------------------------------------------
void UploadTexels(vtkTextureObject* texture, const int rect[4], int buffer, const float* data)
{
  if (!texture || rect[2] <= 0 || rect[3] <= 0)
  {
    return;
  }
  const GLenum format = buffer == vtkStylizeGBufferPass::DEPTH_BUFFER ? GL_DEPTH_COMPONENT
    : ComponentsOf(buffer) == 1                                       ? GL_RED
                                                                      : GL_RGBA;
  texture->Activate();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, rect[0], rect[1], rect[2], rect[3], format, GL_FLOAT, data);
  texture->Deactivate();
}
}
