/**
 * @file    vtkStylizeGBufferTransfer.h
 * @brief   Moves G-buffer channels between textures and the CPU parts that
 *          vtkStylizeRankCompositor composites across processes.
 */

#ifndef vtkStylizeGBufferTransfer_h
#define vtkStylizeGBufferTransfer_h

#include "vtkStylizePassesModule.h" // for export macro
#include "vtkStylizeRankCompositor.h"

#include <vector>

class vtkStylizeGBufferPass;
class vtkTextureObject;

namespace vtkStylizeGBufferTransfer
{
/** Floats per pixel of a G-buffer buffer (vtkStylizeGBufferPass::Buffers). */
VTKSTYLIZEPASSES_NO_EXPORT int ComponentsOf(int buffer);

/** The components of each buffer, in order. */
VTKSTYLIZEPASSES_NO_EXPORT std::vector<int> ComponentsOf(const std::vector<int>& buffers);

/**
 * Reads `gbuffer`'s depth and `buffers` inside rect or, when rect is null, inside the rectangle
 * where its depth is below 1 (empty where it holds no surface); w x h is its size.
 */
VTKSTYLIZEPASSES_NO_EXPORT void ReadPart(vtkStylizeGBufferPass* gbuffer,
  vtkStylizeRankCompositor::Part& part, const std::vector<int>& buffers, int w, int h,
  const int* rect = nullptr);

/**
 * Replaces the texels of a texture inside rect (x, y, width, height) with floats, rows bottom
 * to top, in the format of `buffer`.
 */
VTKSTYLIZEPASSES_NO_EXPORT void UploadTexels(
  vtkTextureObject* texture, const int rect[4], int buffer, const float* data);
}

#endif
