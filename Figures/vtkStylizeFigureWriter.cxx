#include "vtkStylizeFigureWriter.h"

#include "vtkComicPass.h"
#include "vtkImageData.h"
#include "vtkLineArtPass.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPixelArtPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSketchPass.h"
#include "vtkStylizeFigureCanvas.h"
#include "vtkStylizeFigureComic.h"
#include "vtkStylizeFigureLayerSource.h"
#include "vtkStylizeFigureLineArt.h"
#include "vtkStylizeFigureOverlays.h"
#include "vtkStylizeFigurePixelArt.h"
#include "vtkStylizeFigureSink.h"
#include "vtkStylizeFigureSketch.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

vtkStandardNewMacro(vtkStylizeFigureWriter);
vtkCxxSetObjectMacro(vtkStylizeFigureWriter, RenderWindow, vtkRenderWindow);
vtkCxxSetObjectMacro(vtkStylizeFigureWriter, LayerSource, vtkStylizeFigureLayerSource);

using namespace vtkStylizeFigure;

namespace
{
/**
 * The format to write: `format` itself, or for AUTO the one the file name's extension names.
 * AUTO (with `error` set) when there is none.
 */
int ResolveFormat(int format, const std::string& name, bool toMemory, std::string& error)
{
  if (format != vtkStylizeFigureWriter::AUTO)
  {
    return format;
  }
  auto endsWith = [&](const char* ext)
  {
    const size_t n = std::strlen(ext);
    if (name.size() < n)
    {
      return false;
    }
    std::string tail = name.substr(name.size() - n);
    std::transform(tail.begin(), tail.end(), tail.begin(), ::tolower);
    return tail == ext;
  };
  format = endsWith(".svg")
    ? vtkStylizeFigureWriter::SVG
    : (endsWith(".pdf") ? vtkStylizeFigureWriter::PDF : vtkStylizeFigureWriter::AUTO);
  if (format == vtkStylizeFigureWriter::AUTO)
  {
    error = name.empty() && toMemory
      ? "no format: set Format (SVG or PDF) or a file name ending in .svg or .pdf"
      : "cannot write a figure to '" + name + "': the name must end in .svg or .pdf";
  }
  return format;
}

/** The largest supersampling up to `requested` that keeps a w x h bitmap within 64 megapixels. */
int BoundedSupersampling(int requested, int w, int h)
{
  int s = requested;
  while (s > 1 && static_cast<double>(w) * h * s * s > 64.0e6)
  {
    --s;
  }
  return s;
}

/**
 * Draws the style's picture with its drawer, from `frame` (its final layer) and the layers it
 * captures. Returns false when a layer could not be captured.
 */
bool DrawStyle(
  Canvas& c, const Image& frame, vtkStylizeStylePass* style, vtkStylizeFigureWriter* writer)
{
  if (vtkPixelArtPass::SafeDownCast(style))
  {
    DrawPixelArt(c, frame);
    return true;
  }
  if (auto* sketch = vtkSketchPass::SafeDownCast(style))
  {
    return DrawSketch(c, frame, sketch, writer->GetSketchOutlineWidth(), writer->GetPaperMode(),
      writer->GetMaximumPaperColors());
  }
  if (auto* lines = vtkLineArtPass::SafeDownCast(style))
  {
    return DrawLineArt(c, lines, writer->GetPaperMode(), writer->GetMaximumPaperColors());
  }
  return DrawComic(
    c, vtkComicPass::SafeDownCast(style), writer->GetPaperMode(), writer->GetMaximumPaperColors());
}
}

//------------------------------------------------------------------------------
struct vtkStylizeFigureWriter::Internals
{
  vtkNew<vtkUnsignedCharArray> Result;
  /** The layer source on RenderWindow, when none is set. */
  vtkNew<vtkStylizeFigureLayerSource> WindowSource;
  /** The 2D actors hidden while the layers render, with their visibility. */
  std::vector<std::pair<vtkProp*, int>> Hidden;
};

//------------------------------------------------------------------------------
vtkStylizeFigureWriter::vtkStylizeFigureWriter()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkStylizeFigureWriter::~vtkStylizeFigureWriter()
{
  this->SetRenderWindow(nullptr);
  this->SetLayerSource(nullptr);
  this->SetFileName(nullptr);
  delete this->Internal;
}

//------------------------------------------------------------------------------
vtkUnsignedCharArray* vtkStylizeFigureWriter::GetResult()
{
  return this->Internal->Result;
}

//------------------------------------------------------------------------------
std::string vtkStylizeFigureWriter::WriteFigure(vtkRenderWindow* window, const char* fileName)
{
  vtkNew<vtkStylizeFigureWriter> writer;
  writer->SetRenderWindow(window);
  writer->SetFileName(fileName);
  writer->Write();
  return writer->GetErrorMessage();
}

//------------------------------------------------------------------------------
int vtkStylizeFigureWriter::Write()
{
  this->ErrorMessage.clear();
  this->Warning.clear();
  this->NumberOfDots = this->NumberOfHatchSegments = this->NumberOfTracedPaths = 0;
  this->NumberOfRectangles = this->NumberOfImages = this->NumberOfTexts = 0;
  this->Internal->Result->Initialize();
  auto fail = [this](const std::string& message)
  {
    this->ErrorMessage = message;
    vtkErrorMacro(<< message);
    return 0;
  };

  // ---- format and style
  const std::string name = this->FileName ? this->FileName : "";
  std::string error;
  const int format = ResolveFormat(this->Format, name, this->WriteToMemory, error);
  if (format == AUTO)
  {
    return fail(error);
  }
  if (!this->WriteToMemory && name.empty())
  {
    return fail("no file name: set FileName (ending in .svg or .pdf)");
  }
  vtkStylizeFigureLayerSource* source = this->LayerSource;
  if (!source)
  {
    source = this->Internal->WindowSource;
    source->SetRenderWindow(this->RenderWindow);
  }
  vtkStylizeStylePass* style = source->FindStylePass();
  if (!style)
  {
    return fail("no VTK Stylize style to draw: the window's renderers render without a comic, "
                "pixel-art, sketch or line-art pass");
  }
  auto* comic = vtkComicPass::SafeDownCast(style);
  auto* pixelArt = vtkPixelArtPass::SafeDownCast(style);
  auto* sketch = vtkSketchPass::SafeDownCast(style);
  auto* lineArt = vtkLineArtPass::SafeDownCast(style);
  if (!comic && !pixelArt && !sketch && !lineArt)
  {
    return fail(std::string("cannot draw the style ") + style->GetClassName() + " as a figure");
  }

  // ---- capture: the 2D actors hidden while the layers render, drawn as vectors afterwards
  std::vector<Overlay> overlays;
  std::vector<vtkRenderer*> sceneOverlays;
  if (vtkRenderWindow* window = source->GetRenderWindow())
  {
    // one render with the 2D actors in place, so that they lay themselves out
    source->RenderFrame();
    overlays = HideOverlays(window, this->Internal->Hidden);
    sceneOverlays = SceneOverlayRenderers(window, source->FindStyleRenderer());
  }
  struct Restore
  {
    Internals* I;
    std::vector<vtkRenderer*>& Renderers;
    ~Restore()
    {
      for (auto& h : I->Hidden)
      {
        h.first->SetVisibility(h.second);
      }
      I->Hidden.clear();
      for (vtkRenderer* ren : this->Renderers)
      {
        ren->DrawOn();
      }
    }
  } restore{ this->Internal, sceneOverlays };

  Canvas c;
  const int magnification = this->Magnification;
  c.Capture = [source, magnification](int layer, const double* key, Image& image)
  {
    vtkNew<vtkImageData> data;
    return source->CaptureLayer(layer, key, magnification, data) && ToImage(data, image);
  };
  // the frame as the PNG shows it (without the 2D actors)
  Image frame, withSceneOverlays;
  const int frameLayer = comic ? static_cast<int>(vtkComicPass::COMIC)
    : pixelArt                 ? static_cast<int>(vtkPixelArtPass::PIXEL_ART)
    : sketch                   ? static_cast<int>(vtkSketchPass::SKETCH)
                               : static_cast<int>(vtkLineArtPass::LINE_ART);
  // the unstylized renderers' 3D props (orientation axes) out of the style's layers
  if (!sceneOverlays.empty() && !c.Capture(frameLayer, nullptr, withSceneOverlays))
  {
    return fail("rendering the figure's layers failed");
  }
  for (vtkRenderer* ren : sceneOverlays)
  {
    ren->DrawOff();
  }
  if (!c.Capture(frameLayer, nullptr, frame))
  {
    return fail("rendering the figure's layers failed");
  }

  // ---- drawing: the style's drawer, then the overlays
  Sink sink(format == SVG, frame.W, frame.H);
  c.Cr = sink.Context();
  c.W = frame.W;
  c.H = frame.H;
  c.Magnification = this->Magnification;
  c.Supersampling = BoundedSupersampling(this->TraceSupersampling, c.W, c.H);
  const bool ok = DrawStyle(c, frame, style, this);
  if (!sceneOverlays.empty())
  {
    DrawOverlayPixels(c, withSceneOverlays, frame);
  }
  DrawOverlays(c, overlays,
    [source](vtkProp* actor, vtkViewport* viewport, vtkContext2D* painter)
    { return source->PaintContextOverlay(actor, viewport, painter); });
  this->Warning = c.Warning;
  if (!this->Warning.empty())
  {
    this->Warning.resize(this->Warning.size() - 2);
  }

  // ---- output
  const cairo_status_t status = sink.Finish();
  this->NumberOfDots = c.Dots;
  this->NumberOfHatchSegments = c.Segments;
  this->NumberOfTracedPaths = c.Paths;
  this->NumberOfRectangles = c.Rectangles;
  this->NumberOfImages = c.Images;
  this->NumberOfTexts = c.Texts;
  if (!ok)
  {
    return fail("rendering the figure's layers failed");
  }
  if (status != CAIRO_STATUS_SUCCESS)
  {
    return fail(std::string("cairo could not draw the figure: ") + cairo_status_to_string(status));
  }
  const std::vector<unsigned char>& bytes = sink.GetBytes();
  if (this->WriteToMemory)
  {
    this->Internal->Result->SetNumberOfValues(static_cast<vtkIdType>(bytes.size()));
    std::copy(bytes.begin(), bytes.end(), this->Internal->Result->GetPointer(0));
    return 1;
  }
  const std::string written = Sink::WriteFile(name, bytes);
  return written.empty() ? 1 : fail(written);
}

//------------------------------------------------------------------------------
void vtkStylizeFigureWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderWindow: " << this->RenderWindow << "\n";
  os << indent << "LayerSource: " << this->LayerSource << "\n";
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Format: " << this->Format << "\n";
  os << indent << "Magnification: " << this->Magnification << "\n";
  os << indent << "PaperMode: " << this->PaperMode << "\n";
  os << indent << "MaximumPaperColors: " << this->MaximumPaperColors << "\n";
  os << indent << "TraceSupersampling: " << this->TraceSupersampling << "\n";
  os << indent << "SketchOutlineWidth: " << this->SketchOutlineWidth << "\n";
  os << indent << "WriteToMemory: " << this->WriteToMemory << "\n";
}
