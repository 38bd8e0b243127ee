/**
 * @class   vtkStylizeFigureWriter
 * @brief   Writes a stylized render window as a vector figure (SVG or PDF): crisp line art that
 *          journals accept, drawn from the style's own layers and settings.
 *
 * Give it a render window whose renderer renders with one of the VTK Stylize styles, a file name
 * ending in `.svg` or `.pdf`, and call Write(). The writer renders the style's layers and draws
 * them with cairo: the comic's paper, dots, hatch lines and traced outlines; pixel art's art
 * pixels as exact rectangles; the sketch's pencil layer as an image under its traced
 * silhouette; text, scalar bars and vtkContext2D items as vectors (other 2D actors are left out
 * and named by GetWarning()). One figure unit is one image pixel, so at Magnification 1 the
 * figure rasterizes back to the PNG's size. The file is written whole under a hidden name and
 * renamed, so a failure leaves the previous file; WriteToMemory keeps the bytes instead.
 *
 * What each style's figure holds, its limits and measured figures: docs/figures.md.
 *
 * @sa vtkComicPass vtkPixelArtPass vtkSketchPass
 */

#ifndef vtkStylizeFigureWriter_h
#define vtkStylizeFigureWriter_h

#include "vtkObject.h"
#include "vtkStylizeFiguresModule.h" // for export macro

#include <string> // for std::string

class vtkContext2D;
class vtkImageData;
class vtkProp;
class vtkRenderWindow;
class vtkStylizeFigureLayerSource;
class vtkStylizeStylePass;
class vtkUnsignedCharArray;
class vtkViewport;

class VTKSTYLIZEFIGURES_EXPORT vtkStylizeFigureWriter : public vtkObject
{
public:
  static vtkStylizeFigureWriter* New();
  vtkTypeMacro(vtkStylizeFigureWriter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The file format. */
  enum Formats
  {
    AUTO = 0, ///< from the file name's extension: .svg or .pdf
    SVG = 1,  ///< Scalable Vector Graphics
    PDF = 2   ///< Portable Document Format
  };

  /** How the comic's paper (the tint under the ink, the white paper, the background) is drawn. */
  enum PaperModes
  {
    REGIONS = 0, ///< filled regions of one colour each (an image beyond MaximumPaperColors)
    IMAGE = 1    ///< one embedded image
  };

  ///@{
  /** The render window to draw (its renderers, passes and 2D actors). */
  void SetRenderWindow(vtkRenderWindow* window);
  vtkGetObjectMacro(RenderWindow, vtkRenderWindow);

  ///@{
  /**
   * Where the style's layers come from: by default (none set) the render window
   * (vtkStylizeFigureLayerSource on RenderWindow); an application that renders otherwise
   * (ParaView's stylized view) gives a source of its own.
   */
  void SetLayerSource(vtkStylizeFigureLayerSource* source);
  vtkGetObjectMacro(LayerSource, vtkStylizeFigureLayerSource);
  ///@}
  ///@}

  ///@{
  /** The output file, ending in .svg or .pdf (with Format AUTO). */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * File format: AUTO (default), SVG or PDF. Values: AUTO, from the file name's extension: .svg or
   * .pdf; SVG, Scalable Vector Graphics; PDF, Portable Document Format.
   */
  vtkSetClampMacro(Format, int, AUTO, PDF);
  vtkGetMacro(Format, int);
  ///@}

  ///@{
  /**
   * The figure is Magnification times the window's size, its layers rendered in tiles as a
   * magnified screenshot (vtkWindowToImageFilter), so that it shows the magnified PNG's
   * picture. From 1 to 16; default 1.
   */
  vtkSetClampMacro(Magnification, int, 1, 16);
  vtkGetMacro(Magnification, int);
  ///@}

  ///@{
  /**
   * Comic paper: REGIONS (default) or IMAGE. Values: REGIONS, filled regions of one colour each
   * (an image beyond MaximumPaperColors); IMAGE, one embedded image.
   */
  vtkSetClampMacro(PaperMode, int, REGIONS, IMAGE);
  vtkGetMacro(PaperMode, int);
  ///@}

  ///@{
  /**
   * The most colours the comic's paper is drawn as filled regions with; a paper of more colours
   * (a smooth tint, a gradient background) is embedded as an image. From 1 to 4096; default 64.
   */
  vtkSetClampMacro(MaximumPaperColors, int, 1, 4096);
  vtkGetMacro(MaximumPaperColors, int);
  ///@}

  ///@{
  /**
   * Outlines and regions are traced from their layer bilinearly supersampled this many times in
   * x and y, so that their edges fall between pixels where the layer's anti-aliased values say
   * (sub-pixel accuracy). From 1 to 8; default 4 (lowered for images beyond 64 megapixels
   * supersampled).
   */
  vtkSetClampMacro(TraceSupersampling, int, 1, 8);
  vtkGetMacro(TraceSupersampling, int);
  ///@}

  ///@{
  /**
   * Width of the sketch's silhouette stroke, in points of the comic's and sketch's scale (one
   * pixel of an image ReferenceHeight pixels tall); 0 draws none. From 0 to 16; default 1.
   */
  vtkSetClampMacro(SketchOutlineWidth, double, 0.0, 16.0);
  vtkGetMacro(SketchOutlineWidth, double);
  ///@}

  ///@{
  /** Keep the file's bytes in GetResult() instead of writing FileName. Default off. */
  vtkSetMacro(WriteToMemory, bool);
  vtkGetMacro(WriteToMemory, bool);
  vtkBooleanMacro(WriteToMemory, bool);
  ///@}

  /** The last figure's bytes (WriteToMemory on). */
  vtkUnsignedCharArray* GetResult();

  /**
   * Renders the layers and writes the figure. Returns 1 on success; 0 on failure, with a
   * one-line GetErrorMessage() and one vtkErrorMacro, and no file written.
   */
  int Write();

  /** One line on the last failure ("" after a success). */
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

  /** One line on what the last figure left out or drew otherwise ("" when nothing). */
  const char* GetWarning() const { return this->Warning.c_str(); }

  ///@{
  /** What the last figure holds (for reports and tests). */
  vtkGetMacro(NumberOfDots, long long);
  vtkGetMacro(NumberOfHatchSegments, long long);
  vtkGetMacro(NumberOfTracedPaths, long long);
  vtkGetMacro(NumberOfRectangles, long long);
  vtkGetMacro(NumberOfImages, long long);
  vtkGetMacro(NumberOfTexts, long long);
  ///@}

  /**
   * One call: writes `window` to `fileName` (.svg or .pdf) with the default settings. Returns
   * "" on success, the error's line otherwise.
   */
  static std::string WriteFigure(vtkRenderWindow* window, const char* fileName);

protected:
  vtkStylizeFigureWriter();
  ~vtkStylizeFigureWriter() override;

  vtkRenderWindow* RenderWindow = nullptr;
  vtkStylizeFigureLayerSource* LayerSource = nullptr;
  char* FileName = nullptr;
  int Format = AUTO;
  int Magnification = 1;
  int PaperMode = REGIONS;
  int MaximumPaperColors = 64;
  int TraceSupersampling = 4;
  double SketchOutlineWidth = 1.0;
  bool WriteToMemory = false;

  std::string ErrorMessage;
  std::string Warning;
  long long NumberOfDots = 0;
  long long NumberOfHatchSegments = 0;
  long long NumberOfTracedPaths = 0;
  long long NumberOfRectangles = 0;
  long long NumberOfImages = 0;
  long long NumberOfTexts = 0;

private:
  vtkStylizeFigureWriter(const vtkStylizeFigureWriter&) = delete;
  void operator=(const vtkStylizeFigureWriter&) = delete;

  struct Internals;
  Internals* Internal;
};

#endif
