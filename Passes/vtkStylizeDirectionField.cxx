#include "vtkStylizeDirectionField.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkStylizeFieldFS.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkStylizeDirectionField);

//------------------------------------------------------------------------------
vtkStylizeDirectionField::~vtkStylizeDirectionField()
{
  this->Free(nullptr);
}

//------------------------------------------------------------------------------
void vtkStylizeDirectionField::AddStages(
  std::string& source, std::string& mainCall, std::vector<vtkStylizeStage>& stages)
{
  source = std::string(vtkStylizeFieldFS) + source;
  mainCall = "#ifdef STYLIZE_FIELD_STAGE\n  stylizeFieldMain();\n#else\n" + mainCall + "#endif\n";
  this->FirstStage = static_cast<int>(stages.size());
  for (const char* define : { "FIELD_STAGE_ESTIMATE", "FIELD_STAGE_SMOOTH", "FIELD_STAGE_RESOLVE" })
  {
    stages.push_back({ static_cast<int>(stages.size()), define, define });
  }
}

//------------------------------------------------------------------------------
std::string vtkStylizeDirectionField::Defines(const Settings& s)
{
  std::string defines;
  vtkStylizeStylePass::AddDefine(defines, true, "FIELD_NEIGHBORS " + std::to_string(s.Neighbors));
  vtkStylizeStylePass::AddDefine(defines, s.Model, "FIELD_MODEL");
  vtkStylizeStylePass::AddDefine(defines, true, "FIELD_DIRECTION " + std::to_string(s.Direction));
  return defines;
}

//------------------------------------------------------------------------------
double vtkStylizeDirectionField::FocalPixelWorld(const Frame& frame)
{
  const double focal =
    frame.Parallel ? frame.PixelWorld : frame.PixelWorld * frame.Camera->GetDistance();
  return focal > 0.0 && std::isfinite(focal) ? focal : 1.0;
}

//------------------------------------------------------------------------------
vtkStylizeDirectionField::Plan vtkStylizeDirectionField::MakePlan(
  const Frame& frame, const Settings& s, double pointSize)
{
  Plan plan;
  const double focalPixel = FocalPixelWorld(frame);

  // The estimate's neighbour spacing in world units: NeighborSpacing points at the focal
  // distance, at least ObjectScale times the scene's diagonal; the smoothing radius grows by the
  // same factor (at most 256 points).
  double spacingWorld = s.NeighborSpacing * pointSize * focalPixel;
  double scale = 1.0;
  if (s.ObjectScale > 0.0 && spacingWorld > 0.0)
  {
    auto valid = [](const double* b)
    {
      return std::all_of(b, b + 6, [](double v) { return std::isfinite(v); }) && b[0] <= b[1] &&
        b[2] <= b[3] && b[4] <= b[5];
    };
    double b[6];
    std::copy(s.SceneBounds, s.SceneBounds + 6, b);
    if (!valid(b))
    {
      frame.Renderer->ComputeVisiblePropBounds(b);
    }
    if (valid(b))
    {
      const double diagonal = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) +
        (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
      const double object = s.ObjectScale * diagonal;
      if (std::isfinite(object) && object > spacingWorld)
      {
        scale = object / spacingWorld;
        spacingWorld = object;
      }
    }
  }
  plan.SpacingWorld = spacingWorld;
  // The grid: TexelSize points per texel, aligned with the full image's multiples of the scale
  // (a tile's or guard band's offset), so that tiles share one grid.
  plan.Scale = s.TexelSize > 0.0 && std::isfinite(s.TexelSize)
    ? std::max(1, static_cast<int>(std::lround(std::min(s.TexelSize * pointSize, 64.0))))
    : 1;
  for (int i = 0; i < 2; ++i)
  {
    const int offset = static_cast<int>(std::lround(frame.FullOffset[i]));
    plan.GridOrigin[i] = ((offset % plan.Scale) + plan.Scale) % plan.Scale;
    plan.GridSize[i] =
      std::max(1, (frame.Size[i] + plan.GridOrigin[i] + plan.Scale - 1) / plan.Scale);
  }
  const double smoothingRadius = std::min(s.SmoothingRadius * scale, 256.0) * pointSize;
  plan.MaxStride = std::max(1, static_cast<int>(std::lround(s.MaxStride * pointSize)));
  plan.GradientStride = std::max(1, static_cast<int>(std::lround(2.0 * pointSize)));
  const double fillRadius = s.FillRadius > 0.0 ? std::max(1.0, s.FillRadius * pointSize) : -1.0;

  // Smoothing (all texels, 3x3 at tap distances 1, 2, 4, ... points up to the smoothing
  // radius, then at distance 1 texel), then filling (undefined texels, distances 1, 2, 4, ...).
  // The taps are in points (at least a texel), so that a magnified image is smoothed over the
  // same part of the picture; a distance the grid rounds to the previous one is run once.
  // A smoothing pass fills undefined texels as it smooths (they take their neighbours'
  // directions), so the fill iterations start beyond the pyramid's largest tap distance: the
  // ones below it would repeat its work at the cost of a smoothing pass each.
  int pyramid = 0;
  for (double pt = 1.0; pt <= smoothingRadius / pointSize; pt *= 2.0)
  {
    const int r = std::max(1, static_cast<int>(std::lround(pt * pointSize / plan.Scale)));
    if (r > pyramid)
    {
      pyramid = r;
      plan.Iterations.emplace_back(pyramid, 0);
    }
  }
  for (int i = 0; i < s.SmoothingIterations; ++i)
  {
    plan.Iterations.emplace_back(1, 0);
  }
  for (int r = 1; fillRadius > 0.0 && r * plan.Scale <= fillRadius; r *= 2)
  {
    if (r > pyramid)
    {
      plan.Iterations.emplace_back(r, 1);
    }
  }
  return plan;
}

//------------------------------------------------------------------------------
double vtkStylizeDirectionField::Reach(const Frame& frame, const Settings& s, double pointSize)
{
  const Plan plan = MakePlan(frame, s, pointSize);
  double reach = plan.MaxStride + plan.GradientStride + 2 * plan.Scale;
  for (const auto& it : plan.Iterations)
  {
    reach += it.first * plan.Scale;
  }
  return reach;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeDirectionField::GridDepth(
  vtkStylizeStylePass* style, const Frame& frame, const Plan& plan)
{
  vtkTextureObject* depth = style->GetSceneTexture(vtkStylizeGBufferPass::DEPTH_BUFFER);
  if (plan.Scale == 1 || !depth || !style->GetBackgroundCulling())
  {
    vtkStylizeShaderUtilities::FreeTexture(this->Textures[3], frame.Window);
    return nullptr;
  }
  const int k = plan.Scale, gw = plan.GridSize[0], gh = plan.GridSize[1];
  vtkTextureObject*& grid = this->Textures[3];
  vtkStylizeShaderUtilities::EnsureScreenTexture(grid, frame.Window, gw, gh, GL_DEPTH_COMPONENT32F);
  // Nearest: the texel of destination pixel t samples source pixel t k + k / 2 - origin, the
  // pixel fieldGridPixel() reads.
  vtkOpenGLState* ostate = frame.Window->GetState();
  ostate->PushFramebufferBindings();
  GLuint fbos[2];
  glGenFramebuffers(2, fbos);
  ostate->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, fbos[0]);
  glFramebufferTexture2D(
    GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth->GetHandle(), 0);
  ostate->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbos[1]);
  glFramebufferTexture2D(
    GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, grid->GetHandle(), 0);
  const int o0 = plan.GridOrigin[0], o1 = plan.GridOrigin[1];
  glBlitFramebuffer(
    -o0, -o1, gw * k - o0, gh * k - o1, 0, 0, gw, gh, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  ostate->PopFramebufferBindings();
  glDeleteFramebuffers(2, fbos);
  return grid;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeDirectionField::Render(
  vtkStylizeStylePass* style, const Frame& frame, const Settings& s, double pointSize)
{
  if (this->FirstStage < 0)
  {
    return nullptr;
  }
  this->Window = frame.Window;
  const int w = frame.Size[0], h = frame.Size[1];
  const Plan plan = MakePlan(frame, s, pointSize);
  const int gw = plan.GridSize[0], gh = plan.GridSize[1];
  auto gridUniforms = [&](vtkStylizeUniforms& u)
  {
    style->SetFieldUniforms(u, frame);
    u.Int("fieldScale", plan.Scale)
      .Int2("fieldGridOrigin", plan.GridOrigin[0], plan.GridOrigin[1])
      .Int2("fieldGridSize", gw, gh);
  };
  const double fallback = vtkMath::RadiansFromDegrees(s.FallbackAngle);

  // Every stage computes only the surface's pixels (vtkStylizeStylePass::SURFACE_PIXELS; on a
  // grid coarser than the pixels, against the G-buffer's depth taken on the grid): the
  // background is zero, "no direction", in every texture of the field.
  // 1. Raw directions, on the grid.
  vtkTextureObject* gridDepth = this->GridDepth(style, frame, plan);
  vtkTextureObject*& raw0 = this->Textures[0];
  vtkStylizeShaderUtilities::EnsureScreenTexture(raw0, frame.Window, gw, gh, GL_RGBA16F);
  style->RenderStage(
    this->FirstStage, { raw0 }, gw, gh,
    [&](vtkStylizeUniforms& u)
    {
      gridUniforms(u);
      u.Float("fieldSpacing", plan.SpacingWorld)
        .Int("fieldMaxStride", plan.MaxStride)
        .Float("fieldPlanar", s.PlanarTolerance)
        .Float("fieldUmbilic", s.UmbilicTolerance);
    },
    vtkStylizeStylePass::SURFACE_PIXELS, gridDepth);

  // 2. Smoothing and filling (MakePlan()).
  const std::vector<std::pair<int, int>>& iterations = plan.Iterations;
  int current = 0;
  if (iterations.empty())
  {
    vtkStylizeShaderUtilities::FreeTexture(this->Textures[1], frame.Window);
  }
  else
  {
    vtkStylizeShaderUtilities::EnsureScreenTexture(
      this->Textures[1], frame.Window, gw, gh, GL_RGBA16F);
  }
  for (const auto& it : iterations)
  {
    const int next = 1 - current;
    style->RenderStage(
      this->FirstStage + 1, { this->Textures[next] }, gw, gh,
      [&](vtkStylizeUniforms& u)
      {
        gridUniforms(u);
        u.Texture("fieldInput", this->Textures[current])
          .Int("fieldRadius", it.first)
          .Int("fieldFillOnly", it.second);
      },
      vtkStylizeStylePass::SURFACE_PIXELS, gridDepth);
    current = next;
  }

  // 3. Upsampling to the pixels, fallbacks and the requested direction.
  vtkTextureObject*& resolved = this->Textures[2];
  vtkStylizeShaderUtilities::EnsureScreenTexture(resolved, frame.Window, w, h, GL_RGBA32F);
  style->RenderStage(
    this->FirstStage + 2, { resolved }, w, h,
    [&](vtkStylizeUniforms& u)
    {
      gridUniforms(u);
      u.Texture("fieldInput", this->Textures[current])
        .Int("fieldGradientStride", plan.GradientStride)
        .Float2("fieldScreenDirection", std::cos(fallback), std::sin(fallback));
    },
    vtkStylizeStylePass::SURFACE_PIXELS);
  this->Resolved = 2;
  return resolved;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeDirectionField::GetTexture()
{
  return this->Resolved >= 0 ? this->Textures[this->Resolved] : nullptr;
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizeDirectionField::GetTextureBytes()
{
  vtkIdType total = 0;
  for (vtkTextureObject* t : this->Textures)
  {
    total += vtkStylizeShaderUtilities::TextureBytes(t);
  }
  return total;
}

//------------------------------------------------------------------------------
void vtkStylizeDirectionField::Free(vtkWindow* w)
{
  for (vtkTextureObject*& t : this->Textures)
  {
    vtkStylizeShaderUtilities::FreeTexture(t, w);
  }
  this->Resolved = -1;
}
