/**
 * vtkstylize: the render window, and rendering it into the output PNG. The PNG is written to a
 * temporary file and renamed over the output (vtkStylizeAtomicFile), so a failure never leaves
 * a partial file.
 */
#ifndef vtkstylizeRender_h
#define vtkstylizeRender_h

#include "Options.h"

#include "vtkSmartPointer.h"

#include <string>

class vtkRenderWindow;
class vtkRenderer;

namespace vtkstylize
{
/** The folder of a path ("." when it has none) and its last component. */
std::string Directory(const std::string& path);
std::string BaseName(const std::string& path);

/** Fails unless OUTPUT names a file (not a directory) in an existing, writable directory. */
void CheckOutputPath(const std::string& path);

/** An offscreen window of the requested size and multisampling, holding the renderer. */
vtkSmartPointer<vtkRenderWindow> MakeWindow(vtkRenderer* ren, const Options& opt);

/**
 * Renders the window into an image of the requested size and writes it to `output`: a PNG, or
 * a vector figure (.svg, .pdf: vtkStylizeFigureWriter). Returns
 * whether the render drew some opaque surface, line or point; when it drew none and
 * emptyFailure is not empty, fails with that message instead of writing the image.
 */
bool RenderAndWrite(vtkRenderWindow* window, const Options& opt, const std::string& output,
  const std::string& emptyFailure);

/**
 * Encodes the numbered PNG frames `pattern` (printf style, e.g. "orbit-%04d.png") into `output`
 * (.gif: a palette of the frames' own colours, no dithering; .mp4: H.264) with ffmpeg, at fps
 * frames per second, written whole and renamed. Fails with one line when ffmpeg is missing or
 * fails.
 */
void EncodeAnimation(const std::string& pattern, int fps, const std::string& output);
}

#endif
