/**
 * @file    vtkStylizeFigureLineArt.h
 * @brief   The line art's drawer of vtkStylizeFigureWriter (private to the module), and the
 *          strokes' drawer the comic's shares.
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
class vtkPolyData;

namespace vtkStylizeFigure
{
/**
 * Draws `lines`' figure on `c`. `paperMode` and `maximumPaperColors` are the writer's. Returns
 * false when the paper could not be captured.
 */
bool DrawLineArt(Canvas& c, vtkLineArtPass* lines, int paperMode, int maximumPaperColors);

/**
 * Draws strokes (a style's ComputeFigureStrokes(): polylines in the figure's pixels, row 0 at the
 * bottom, with point data StrokeWidth) as paths of colour `ink`: simplified to within Tolerance
 * page units, each run of nearly equal width one path with round caps and joins. The line art's
 * lines, the comic's feature lines and iso-lines.
 */
void DrawStrokes(Canvas& c, vtkPolyData* strokes, const double ink[3]);
}

#endif
