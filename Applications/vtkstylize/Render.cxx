// vtkstylize: rendering the window (tiled when magnified) and writing the PNG atomically.
#include "Render.h"

#include "VirtualDisplay.h"
#include "vtkstylizeCommon.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkStylizeAnimationEncoder.h"
#include "vtkStylizeAtomicFile.h"
#include "vtkStylizeFigureWriter.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeStylePass.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#ifdef VTKSTYLIZE_HAVE_X11
#include <X11/Xlib.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace vtkstylize
{
std::string Directory(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos)
  {
    return ".";
  }
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string BaseName(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

/** Fails unless OUTPUT names a file (not a directory) in an existing, writable directory. */
void CheckOutputPath(const std::string& path)
{
  const std::string what = "cannot write " + Quote(path);
  if (BaseName(path).size() <= 4)
  {
    Fail(what + ": the file name is empty");
  }
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
  {
    Fail(what + ": is a directory");
  }
  const std::string dir = Directory(path);
  if (::stat(dir.c_str(), &st) != 0)
  {
    Fail(what + ": directory " + Quote(dir) + ": " + std::strerror(errno));
  }
  if (!S_ISDIR(st.st_mode))
  {
    Fail(what + ": " + Quote(dir) + " is not a directory");
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
  {
    Fail(what + ": directory " + Quote(dir) + ": " + std::strerror(errno));
  }
}

#ifdef VTKSTYLIZE_HAVE_X11
/** VTK aborts when it cannot open the X display; check it first. */
void CheckDisplay(vtkRenderWindow* window)
{
  if (!window->IsA("vtkXOpenGLRenderWindow"))
  {
    return;
  }
  Display* display = XOpenDisplay(nullptr);
  if (!display)
  {
    const char* name = std::getenv("DISPLAY");
    Fail(std::string("cannot render: cannot open the X display ") +
      (name && *name ? Quote(name) : std::string("(DISPLAY is not set)")) +
      "; an X server is needed even for offscreen rendering");
  }
  XCloseDisplay(display);
}
#else
void CheckDisplay(vtkRenderWindow*) {}
#endif

/** The offscreen window of the requested size, holding the renderer. */
vtkSmartPointer<vtkRenderWindow> MakeWindow(vtkRenderer* ren, const Options& opt)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(opt.MultiSamples);
  window->SetSize(opt.Width, opt.Height);
  window->AddRenderer(ren);
  if (window->IsA("vtkXOpenGLRenderWindow"))
  {
    StartVirtualDisplayIfNeeded(opt.Width, opt.Height);
  }
  CheckDisplay(window);
  return window;
}

/** Renders the window into an image of the requested size and writes it to output. */
/**
 * Whether the last render drew some opaque surface, line or point: a depth between the near and
 * the far plane somewhere, in the style's G-buffer (a style writes the window's depth only where
 * it must) or in the window. (Translucent geometry writes no depth: such a scene counts as
 * drawn.)
 */
bool DrewSomething(vtkRenderWindow* window)
{
  vtkRendererCollection* renderers = window->GetRenderers();
  renderers->InitTraversal();
  vtkNew<vtkFloatArray> depth;
  bool styled = false;
  while (vtkRenderer* ren = renderers->GetNextItem())
  {
    vtkActorCollection* actors = ren->GetActors();
    actors->InitTraversal();
    while (vtkActor* actor = actors->GetNextActor())
    {
      if (actor->GetVisibility() && actor->HasTranslucentPolygonalGeometry())
      {
        return true;
      }
    }
    auto* style = vtkStylizeStylePass::SafeDownCast(ren->GetPass());
    if (style &&
      style->GetGBufferPass()->DownloadChannel(vtkStylizeGBufferPass::DEPTH_BUFFER, depth))
    {
      styled = true;
      const float* z = depth->GetPointer(0);
      if (std::any_of(z, z + depth->GetNumberOfValues(), [](float v) { return v < 1.0f; }))
      {
        return true;
      }
    }
  }
  if (styled)
  {
    return false;
  }
  const int* size = window->GetSize();
  if (window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, depth) != VTK_OK)
  {
    return true; // cannot tell
  }
  // (the title and the scalar bar, drawn over the scene, write a depth of 0; the scene lies
  // behind the near plane, which the camera sets in front of the data)
  const float* z = depth->GetPointer(0);
  return std::any_of(
    z, z + depth->GetNumberOfValues(), [](float v) { return v > 0.0f && v < 1.0f; });
}

namespace
{
/** The window's image at the requested size (magnified: tiled); fails on another size. */
vtkSmartPointer<vtkWindowToImageFilter> GrabImage(vtkRenderWindow* window, const Options& opt)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->SetScale(opt.Magnify);
  grab->Update();
  CheckVTKErrors("reading the rendered image failed");
  int dims[3];
  grab->GetOutput()->GetDimensions(dims);
  if (dims[0] != opt.Width * opt.Magnify || dims[1] != opt.Height * opt.Magnify)
  {
    Fail("rendering failed: got a " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) +
      " image instead of " + std::to_string(opt.Width * opt.Magnify) + "x" +
      std::to_string(opt.Height * opt.Magnify));
  }
  return grab;
}

/**
 * The file's bytes: a vector figure drawn from the style's layers (.svg, .pdf), else the PNG of
 * the grabbed image. `what` starts the failure message.
 */
vtkSmartPointer<vtkUnsignedCharArray> Encode(vtkRenderWindow* window, vtkWindowToImageFilter* grab,
  const Options& opt, const std::string& output, const std::string& what)
{
  const std::string ext = Lower(output.substr(output.size() - 4));
  if (ext == ".svg" || ext == ".pdf")
  {
    vtkNew<vtkStylizeFigureWriter> figure;
    figure->SetRenderWindow(window);
    figure->SetFormat(ext == ".svg" ? vtkStylizeFigureWriter::SVG : vtkStylizeFigureWriter::PDF);
    figure->SetMagnification(opt.Magnify);
    figure->WriteToMemoryOn();
    if (!figure->Write())
    {
      Fail(what + ": " + figure->GetErrorMessage());
    }
    ClearVTKErrors();
    if (*figure->GetWarning())
    {
      Warn(std::string("figure: ") + figure->GetWarning());
    }
    return figure->GetResult();
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->WriteToMemoryOn();
  writer->Write();
  CheckVTKErrors(what);
  vtkSmartPointer<vtkUnsignedCharArray> encoded = writer->GetResult();
  if (writer->GetErrorCode() != vtkErrorCode::NoError || !encoded)
  {
    const char* code = vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode());
    Fail(what + ": " + (code ? code : "PNG encoding failed"));
  }
  return encoded;
}
}

bool RenderAndWrite(vtkRenderWindow* window, const Options& opt, const std::string& output,
  const std::string& emptyFailure)
{
  ClearVTKErrors();
  window->Render();
  CheckVTKErrors("rendering failed");
  const bool drawn = DrewSomething(window);
  if (!drawn && !emptyFailure.empty())
  {
    Fail(emptyFailure);
  }
  vtkSmartPointer<vtkWindowToImageFilter> grab = GrabImage(window, opt);

  // Encoded, then written whole and renamed over the output (vtkStylizeAtomicFile): never a
  // partial output file, and nothing left behind even by SIGKILL where the file system has
  // O_TMPFILE (elsewhere a hidden named file beside the output, removed on failure and, by the
  // crash handler, on catchable signals).
  const std::string what = "cannot write " + Quote(output);
  vtkSmartPointer<vtkUnsignedCharArray> encoded = Encode(window, grab, opt, output, what);
  const int error = vtkStylizeAtomicFile::Write(output.c_str(), encoded);
  if (error != 0)
  {
    Fail(what + ": " + std::strerror(error));
  }
  return drawn;
}

void EncodeAnimation(const std::string& pattern, int fps, const std::string& output)
{
  const std::string error =
    vtkStylizeAnimationEncoder::Encode(pattern.c_str(), fps, output.c_str());
  if (!error.empty())
  {
    Fail(error);
  }
}
}
