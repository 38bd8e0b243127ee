/**
 * @class   vtkStylizeFigureWriter
 * @brief   Writes a stylized render window as a vector figure (SVG or PDF): crisp line art that
 *          journals accept, drawn from the style's own layers and settings.
 *
 * Give it a render window whose renderer renders with one of the VTK Stylize styles, a file name
 * ending in `.svg` or `.pdf`, and call Write(). The writer renders the style's layers (the
 * style's Layer setting, restored afterwards) and draws with cairo:
 *
 * - **Comic** (vtkComicPass): the paper as filled regions of one colour each (the tint, the
 *   white paper, the background), or as an embedded image (PaperMode); the halftone dots as
 *   circles (discs clipped to their cell where the tone is darkest) and the hatch lines as line
 *   segments, generated from the pass's grid, angle, spacing, width and thresholds and from the
 *   tone the pass shaded (layer FIGURE_INPUTS), so they are exact rather than traced; the outlines
 *   traced by potrace at sub-pixel accuracy from the edge layer (bilinearly supersampled
 *   TraceSupersampling times), in the edge factor's levels (full ink and the half ink of normal
 *   edges). With the OBJECT anchor the pattern is not a screen grid: it is traced like the
 *   outlines.
 * - **Pixel art** (vtkPixelArtPass): every art pixel as an exact rectangle, runs of one colour
 *   merged (along rows, then rows of equal runs): rasterized at the image size the figure gives
 *   the PNG's pixels.
 * - **Sketch** (vtkSketchPass): the pencil layer as an embedded image, and the silhouette (the
 *   outline of the surfaces against the background) as a traced vector stroke in the pencil
 *   colour, SketchOutlineWidth points wide (0: none).
 * - **Text and scalar bars** (vtkTextActor, vtkScalarBarActor, in any renderer of the window):
 *   vector text in the actor's colour, fitted to the box VTK lays the text out in, and the
 *   bar's colour swatches as rectangles. 2D actors that paint through vtkContext2D (a
 *   vtkContextActor's scene; ParaView's vtkContext2DScalarBarActor through the plugin's view)
 *   are painted as vectors: shapes in the pen's and brush's colours, text as the glyph outlines
 *   of VTK's text renderer, a colour strip as a linear gradient (PaintContextOverlay). Other 2D
 *   actors are left out (GetWarning names them).
 *
 * The figure's unit is the image pixel: a W x H window at Magnification m gives a page of
 * mW x mH (SVG pixels, PDF points), which rasterizes back to the PNG's size at 96 dpi (SVG) or
 * 72 dpi (PDF). The file is written whole under a hidden name beside it and renamed: a failure
 * leaves no partial file and the previous file as it was. WriteToMemory keeps the bytes instead.
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

  /**
   * Sets the Layer of a comic, pixel-art or sketch pass (their enums); returns the layer it had,
   * or -1 for any other pass (left alone).
   */
  static int SetStyleLayer(vtkStylizeStylePass* style, int layer);

  /**
   * Encodes numbered PNG frames into an animation with ffmpeg (Debian: apt-get install ffmpeg):
   * `pattern` is ffmpeg's printf-style frame name (frame-%04d.png), `fps` frames per second
   * (clamped to [1, 120]), `output` ends in .gif (one palette from all the frames' colours, no
   * dithering of ffmpeg's own, looping) or .mp4 (H.264, yuv420p, CRF 18, sides padded to even).
   * The file is encoded under a hidden name beside it and renamed: a failure leaves no partial
   * file. Returns "" on success, the failure's line otherwise (the frames are left as they are).
   */
  static std::string EncodeAnimation(const char* pattern, int fps, const char* output);

protected:
  vtkStylizeFigureWriter();
  ~vtkStylizeFigureWriter() override;

  /**
   * The style pass to draw: by default the first renderer's of RenderWindow that renders with
   * one. A view that holds its style elsewhere (ParaView's) overrides it.
   */
  virtual vtkStylizeStylePass* FindStylePass();

  /**
   * Renders the frame with the style's Layer set to `layer` (the writer restores it) and reads
   * it back, RGB, Magnification times the window's size, row 0 at the bottom. With `key` set, the
   * background is that colour (flat) for this frame: what differs from it is the scene. The 2D
   * actors are hidden. Returns false when nothing could be read.
   */
  virtual bool CaptureLayer(int layer, const double* key, vtkImageData* out);

  /**
   * Renders the window once as it is, so that the 2D actors lay themselves out before they are
   * drawn as vectors: RenderWindow->Render() by default. A view that renders otherwise
   * (ParaView's) overrides it.
   */
  virtual void RenderFrame();

  /**
   * Paints a 2D actor that draws through vtkContext2D into `painter`, whose device writes the
   * figure's vector shapes (vtkStylizeCairoContextDevice2D: its coordinates are the viewport's
   * pixels, as on the screen). Returns true when it painted the actor. By default it paints a
   * vtkContextActor's scene; a view with 2D actors of its own kind (ParaView's
   * vtkContext2DScalarBarActor) overrides it. Text actors are drawn before, and a
   * vtkScalarBarActor this leaves alone is drawn from its layout afterwards.
   */
  virtual bool PaintContextOverlay(vtkProp* actor, vtkViewport* viewport, vtkContext2D* painter);

  vtkRenderWindow* RenderWindow = nullptr;
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
