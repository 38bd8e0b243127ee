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
 * stroked in the pencil colour. Returns false when that layer could not be captured.
 */
bool DrawSketch(Canvas& c, const Image& frame, vtkSketchPass* sketch, double outlineWidth);
}

#endif
