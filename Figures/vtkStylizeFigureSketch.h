/**
 * @file    vtkStylizeFigureSketch.h
 * @brief   The pencil sketch's drawer of vtkStylizeFigureWriter (private to the module).
 */

#ifndef vtkStylizeFigureSketch_h
#define vtkStylizeFigureSketch_h

#include "vtkStylizeFigureCanvas.h"

class vtkSketchPass;

namespace vtkStylizeFigure
{
/**
 * Draws the sketch: the pencil layer `frame` as an embedded image and, for a positive
 * `outlineWidth` (points), the silhouette traced from the layer rendered on a key background,
 * stroked in the pencil colour. With the sketch's VectorFigureStrokes on, DrawVectorSketch()
 * instead. Returns false when a layer could not be captured.
 */
bool DrawSketch(Canvas& c, const Image& frame, vtkSketchPass* sketch, double outlineWidth,
  int paperMode, int maximumPaperColors);

/**
 * The sketch as vectors: the paper (regions, DrawPaper()), the pencil strokes as polylines
 * traced along the pass's direction field (its DIRECTIONS layer) from seeds whose density and
 * darkness follow its tone (its TONE layer), crossed below its CrossThreshold, and its feature
 * lines traced from the layer drawn without strokes, filled in the pencil colour. Returns false
 * when a layer could not be captured.
 */
bool DrawVectorSketch(Canvas& c, vtkSketchPass* sketch, int paperMode, int maximumPaperColors);
}

#endif
