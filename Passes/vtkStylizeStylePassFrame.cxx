// The style base's frame (vtkStylizeStylePass): its size and origin, the full image it belongs
// to, a tile's guard band and an interactive frame's reduced size.
#include "vtkStylizeStylePass.h"

#include "vtkCamera.h"
#include "vtkMultiProcessController.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkStylizeStylePassInternals.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
double vtkStylizeStylePass::PointSize(const Frame& frame)
{
  // Points -> pixels of the full (possibly tiled, magnified) image.
  const double reference = this->GetPointReferenceHeight();
  return reference > 0.0 ? frame.FullSize[1] / reference : frame.TileScale[1] / frame.Reduction;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::BeginFrame(const vtkRenderState* s, Frame& frame)
{
  vtkOpenGLClearErrorMacro();
  vtkStylizeStageRunner* runner = this->Internals->Runner;
  if (runner->Timing)
  {
    runner->ClearTimes();
  }
  this->NumberOfRenderedProps = 0;
  runner->ResetFailure();
  vtkRenderer* ren = s->GetRenderer();
  frame.Renderer = ren;
  frame.Window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  runner->SetWindow(frame.Window);
  if (!frame.Window)
  {
    return false;
  }
  ren->GetTiledSizeAndOrigin(&frame.Size[0], &frame.Size[1], &frame.Origin[0], &frame.Origin[1]);
  if (frame.Size[0] < 1 || frame.Size[1] < 1)
  {
    this->RenderScene(s, SceneRequest()); // draws the rest of the scene and finishes
    return false;
  }
  const vtkStylizeShaderUtilities::FullImage full =
    vtkStylizeShaderUtilities::GetFullImage(ren, frame.Origin[0], frame.Origin[1]);
  for (int a = 0; a < 2; ++a)
  {
    frame.FullSize[a] = full.Size[a];
    frame.FullOffset[a] = full.Offset[a];
    frame.TileScale[a] = full.TileScale[a] * this->WindowScale[a];
  }
  frame.Camera = ren->GetActiveCamera();
  frame.Parallel = frame.Camera->GetParallelProjection() != 0;
  frame.PixelWorld =
    vtkStylizeShaderUtilities::PixelWorldSize(frame.Camera, frame.Size[0], frame.Size[1]);
  const double rate = frame.Window->GetDesiredUpdateRate();
  frame.Interactive =
    this->InteractiveUpdateRate > 0.0 && std::isfinite(rate) && rate >= this->InteractiveUpdateRate;
  this->PlanGuardBand(frame);
  this->PlanReduction(frame);
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::PlanGuardBand(Frame& frame)
{
  vtkInternals& in = *this->Internals;
  in.Guarded = false;
  // A tile's borders inside the full image (an untiled render has none); a scene from an
  // image (IceT's tile) holds nothing beyond the tile.
  const double before[2] = { frame.FullOffset[0], frame.FullOffset[1] };
  const double after[2] = { frame.FullSize[0] - frame.FullOffset[0] - frame.Size[0],
    frame.FullSize[1] - frame.FullOffset[1] - frame.Size[1] };
  const bool tile = before[0] >= 1.0 || before[1] >= 1.0 || after[0] >= 1.0 || after[1] >= 1.0;
  if (this->DelegatePass || !tile)
  {
    return;
  }
  const double reach = this->GetReach(frame);
  if (!(reach > 0.0))
  {
    return;
  }
  const int align = std::max(1, this->GetGuardAlignment(frame));
  // At most this many pixels per side in all (a larger reach leaves a seam possible rather
  // than render textures many times the tile's size).
  constexpr double MaxSize = 8192.0;
  const int band = static_cast<int>(std::ceil(std::min(reach, MaxSize)));
  int guard[4], size[2];
  for (int a = 0; a < 2; ++a)
  {
    // The band stays inside the full image; its lower corner on the alignment grid.
    const long long offset = std::llround(before[a]);
    long long lo = std::min<long long>(band, offset);
    lo = offset - (offset - lo) / align * align;
    const long long hi = std::max(0LL, std::min<long long>(band, std::llround(after[a])));
    const long long total = frame.Size[a] + lo + hi;
    if (total > MaxSize)
    {
      return;
    }
    guard[a] = static_cast<int>(lo);
    guard[a + 2] = static_cast<int>(hi);
    size[a] = static_cast<int>(total);
  }
  for (int a = 0; a < 2; ++a)
  {
    // The viewport's NDC [-1, 1] onto its pixels inside the band.
    const double lo = guard[a], hi = guard[a + 2];
    frame.Guard[a] = guard[a];
    frame.Guard[a + 2] = guard[a + 2];
    frame.GuardTransform[a] = frame.Size[a] / static_cast<double>(size[a]);
    frame.GuardTransform[a + 2] = (lo - hi) / size[a];
    frame.Origin[a] -= frame.Guard[a];
    frame.FullOffset[a] -= frame.Guard[a];
    frame.Size[a] = size[a];
    in.GuardSize[a] = size[a];
  }
  std::copy(frame.GuardTransform, frame.GuardTransform + 4, in.GuardTransform);
  in.Guarded = true;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::PlanReduction(Frame& frame)
{
  // Interactive frames of an untiled, opaque, erasing renderer on one process. (A scene from an
  // image, ParaView's, is rendered into the G-buffer's image at the reduced size.)
  vtkInternals& in = *this->Internals;
  const int k = this->InteractiveImageReduction;
  vtkRenderer* ren = frame.Renderer;
  vtkMultiProcessController* controller = in.GBuffer->GetController();
  const bool ranks = controller && controller->GetNumberOfProcesses() > 1;
  if (!frame.Interactive || k < 2 || !this->AcceptsImageReduction() || in.Guarded || ranks ||
    ren->Transparent() || !ren->GetErase() || !frame.Window->GetErase() ||
    frame.FullSize[0] != frame.Size[0] || frame.FullSize[1] != frame.Size[1])
  {
    return;
  }
  const int size[2] = { (frame.Size[0] + k - 1) / k, (frame.Size[1] + k - 1) / k };
  const int viewport[4] = { frame.Origin[0], frame.Origin[1], frame.Size[0], frame.Size[1] };
  if (!in.Reduced.Begin(frame.Window, size[0], size[1], viewport))
  {
    return;
  }
  frame.Reduction = frame.Size[1] / static_cast<double>(size[1]);
  for (int a = 0; a < 2; ++a)
  {
    frame.Size[a] = frame.FullSize[a] = in.GuardSize[a] = size[a];
    frame.Origin[a] = 0;
    frame.FullOffset[a] = 0.0;
  }
  frame.PixelWorld = vtkStylizeShaderUtilities::PixelWorldSize(frame.Camera, size[0], size[1]);
  std::fill(in.GuardTransform, in.GuardTransform + 4, 0.0);
  in.GuardTransform[0] = in.GuardTransform[1] = 1.0;
  in.Guarded = true; // the geometry renders at the reduced size
}
