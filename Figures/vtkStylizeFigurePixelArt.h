/**
 * @file    vtkStylizeFigurePixelArt.h
 * @brief   The pixel art's drawer of vtkStylizeFigureWriter (private to the module).
 */

#ifndef vtkStylizeFigurePixelArt_h
#define vtkStylizeFigurePixelArt_h

#include "vtkStylizeFigureCanvas.h"

namespace vtkStylizeFigure
{
/**
 * Draws the pixel-art image `frame` as exact rectangles: runs of one colour along the rows,
 * equal runs of consecutive rows merged, one path per colour.
 */
void DrawPixelArt(Canvas& c, const Image& frame);
}

#endif
