// vtkstylize: rendering the window (tiled when magnified) and writing the PNG atomically.
#include "Render.h"

#include "vtkstylizeCommon.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPNGWriter.h"
#include "vtkStylizeFigureWriter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeStylePass.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#ifdef VTKSTYLIZE_HAVE_X11
#include <X11/Xlib.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace vtkstylize
{
char TemporaryPath[4096] = { 0 };

namespace
{
/** Removes the temporary file on scope exit unless released. */
class TemporaryFileGuard
{
public:
  TemporaryFileGuard() = default;
  ~TemporaryFileGuard() { this->Remove(); }
  TemporaryFileGuard(const TemporaryFileGuard&) = delete;
  TemporaryFileGuard& operator=(const TemporaryFileGuard&) = delete;

  void Set(const std::string& path)
  {
    this->Path = path;
    std::snprintf(TemporaryPath, sizeof(TemporaryPath), "%s", path.c_str());
  }
  void Release()
  {
    this->Path.clear();
    TemporaryPath[0] = 0;
  }
  void Remove()
  {
    if (!this->Path.empty())
    {
      ::unlink(this->Path.c_str());
    }
    this->Release();
  }
  const std::string& Get() const { return this->Path; }

private:
  std::string Path;
};

}

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
    if (style && style->GetGBufferPass()->DownloadChannel(vtkStylizeGBufferPass::DEPTH_BUFFER, depth))
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

bool RenderAndWrite(
  vtkRenderWindow* window, const Options& opt, const std::string& output, const std::string& emptyFailure)
{
  ClearVTKErrors();
  window->Render();
  CheckVTKErrors("rendering failed");
  const bool drawn = DrewSomething(window);
  if (!drawn && !emptyFailure.empty())
  {
    Fail(emptyFailure);
  }

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

  // Encode (a PNG, or a vector figure drawn from the style's layers), then write into a file
  // that has no name until it is complete, and rename that over the output: never a partial
  // output file, and nothing left behind even by SIGKILL (an O_TMPFILE file vanishes with the
  // process; where the file system has none, a hidden named file beside the output, removed on
  // failure and on catchable signals).
  const std::string what = "cannot write " + Quote(output);
  const std::string ext = Lower(output.substr(output.size() - 4));
  vtkSmartPointer<vtkUnsignedCharArray> encoded;
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
    encoded = figure->GetResult();
  }
  else
  {
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    writer->WriteToMemoryOn();
    writer->Write();
    CheckVTKErrors(what);
    encoded = writer->GetResult();
    if (writer->GetErrorCode() != vtkErrorCode::NoError || !encoded)
    {
      const char* code = vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode());
      Fail(what + ": " + (code ? code : "PNG encoding failed"));
    }
  }
  const unsigned char* bytes = encoded->GetPointer(0);
  const std::size_t size = static_cast<std::size_t>(encoded->GetNumberOfValues());
  const auto writeAll = [&](int fd) {
    for (std::size_t done = 0; done < size;)
    {
      const ssize_t n = ::write(fd, bytes + done, size - done);
      if (n < 0 && errno == EINTR)
      {
        continue;
      }
      if (n <= 0)
      {
        return false;
      }
      done += static_cast<std::size_t>(n);
    }
    return true;
  };
  const mode_t mask = ::umask(0);
  ::umask(mask);
  const std::string hidden = Directory(output) + "/." + BaseName(output) + ".XXXXXX";
  TemporaryFileGuard temporary;
  int fd = ::open(Directory(output).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (fd >= 0)
  {
    if (!writeAll(fd))
    {
      const int error = errno;
      ::close(fd);
      Fail(what + ": " + std::strerror(error));
    }
    // A name for it now: a unique hidden one (linkat cannot replace the output), then rename.
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    bool linked = false;
    for (int attempt = 0; attempt < 100 && !linked; ++attempt)
    {
      std::vector<char> name(hidden.begin(), hidden.end());
      name.push_back(0);
      const int probe = ::mkstemp(name.data()); // a unique name, given back at once
      if (probe < 0)
      {
        break;
      }
      ::close(probe);
      ::unlink(name.data());
      if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, name.data(), AT_SYMLINK_FOLLOW) == 0)
      {
        temporary.Set(name.data());
        linked = true;
      }
      else if (errno != EEXIST)
      {
        break;
      }
    }
    ::close(fd);
    fd = -1;
    if (!linked)
    {
      fd = -2; // no /proc or no link: write it again under a name
    }
  }
  if (fd != -1)
  {
    std::vector<char> name(hidden.begin(), hidden.end());
    name.push_back(0);
    fd = ::mkstemp(name.data());
    if (fd < 0)
    {
      Fail(what + ": " + std::strerror(errno));
    }
    temporary.Set(name.data());
    ::fchmod(fd, 0666 & ~mask);
    const bool written = writeAll(fd);
    const int error = errno;
    ::close(fd);
    if (!written)
    {
      Fail(what + ": " + std::strerror(error));
    }
  }
  if (std::rename(temporary.Get().c_str(), output.c_str()) != 0)
  {
    Fail(what + ": " + std::strerror(errno));
  }
  temporary.Release();
  return drawn;
}

void EncodeAnimation(const std::string& pattern, int fps, const std::string& output)
{
  const std::string error =
    vtkStylizeFigureWriter::EncodeAnimation(pattern.c_str(), fps, output.c_str());
  if (!error.empty())
  {
    Fail(error);
  }
}
}
