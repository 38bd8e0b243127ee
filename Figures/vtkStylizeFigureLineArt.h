/**
 * @file    vtkStylizeFigureLineArt.h
 * @brief   The line art's drawer of vtkStylizeFigureWriter (private to the module).
 *
 * Draws the paper (its captured PAPER layer: regions of one colour each, or an image) and over
 * it the feature lines as stroked vector paths from the geometry (vtkLineArtPass::
 * ComputeFigureStrokes(): hidden parts removed by ray casting), simplified to within
 * Tolerance page units, each run of nearly equal width one path with round caps and joins.
 */

#ifndef vtkStylizeFigureLineArt_h
#define vtkStylizeFigureLineArt_h

#include "vtkStylizeFigureCanvas.h"

class vtkLineArtPass;

namespace vtkStylizeFigure
{
/**
 * Draws `lines`' figure on `c`. `paperMode` and `maximumPaperColors` are the writer's. Returns
 * false when the paper could not be captured.
 */
bool DrawLineArt(Canvas& c, vtkLineArtPass* lines, int paperMode, int maximumPaperColors);
}

#endif
