/**
 * @file    vtkStylizeFigureComic.h
 * @brief   The comic's drawer of vtkStylizeFigureWriter (private to the module).
 *
 * Draws the comic from its layers: the paper (filled regions of one colour each, or an image),
 * the halftone dots and hatch lines from the pass's settings and the tone it shaded (the
 * pattern's formulas of vtkComicPatterns.h), painted through the traced outline of the surfaces,
 * and the edges traced in the edge factor's levels.
 */

#ifndef vtkStylizeFigureComic_h
#define vtkStylizeFigureComic_h

#include "vtkStylizeFigureCanvas.h"

class vtkComicPass;

namespace vtkStylizeFigure
{
/**
 * Draws `comic`'s figure on `c`, capturing its layers PAPER, FIGURE_INPUTS, EDGES (and PATTERN
 * where the pattern is not a screen grid). `paperMode` and `maximumPaperColors` are the
 * writer's. Returns false when a layer could not be captured.
 */
bool DrawComic(Canvas& c, vtkComicPass* comic, int paperMode, int maximumPaperColors);
}

#endif
