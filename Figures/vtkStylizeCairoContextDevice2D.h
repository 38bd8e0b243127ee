/**
 * @class   vtkStylizeCairoContextDevice2D
 * @brief   A vtkContextDevice2D that draws with cairo: what a vtkContext2D paints (a
 *          vtkContextActor's scene, ParaView's vtkContext2DScalarBarActor) as vector shapes.
 *
 * vtkStylizeFigureWriter paints the 2D actors that draw through vtkContext2D with it, so that
 * they come out as vectors in the SVG or PDF figure: polylines, lines, points and markers as
 * strokes in the pen's colour, width and dashes; quads, polygons, rectangles and ellipse wedges
 * filled with the brush's colour; text as the glyph outlines VTK's text renderer gives for the
 * text property (font, size at the window's DPI, justification, rotation), measured with the same
 * renderer as on the screen, so that the layout is the screen's; an image one pixel wide or tall
 * (a scalar bar's colour strip) as a linear gradient through its pixels' colours, any other image
 * embedded. Device coordinates are the viewport's pixels, y up; the target page is `height`
 * units tall, y down, with `scale` units per pixel.
 *
 * Private to the Figures module (its header names cairo).
 */

#ifndef vtkStylizeCairoContextDevice2D_h
#define vtkStylizeCairoContextDevice2D_h

#include "vtkContextDevice2D.h"
#include "vtkVersionMacros.h" // for VTK_MINOR_VERSION

#include <array>  // for the matrix stack
#include <vector> // for the matrix stack

#include <cairo.h> // for cairo_t

class vtkUnicodeString;

class vtkStylizeCairoContextDevice2D : public vtkContextDevice2D
{
public:
  static vtkStylizeCairoContextDevice2D* New();
  vtkTypeMacro(vtkStylizeCairoContextDevice2D, vtkContextDevice2D);

  /**
   * Where to draw: cairo's context (not owned; its state is saved and restored around every
   * shape), the page's height in its units (y down) and its units per device pixel.
   */
  void SetTarget(cairo_t* cr, double height, double scale);

  ///@{
  /** What was drawn since SetTarget: shapes (strokes and fills), texts, images. */
  long long GetNumberOfShapes() const { return this->Shapes; }
  long long GetNumberOfTexts() const { return this->Texts; }
  long long GetNumberOfImages() const { return this->Images; }
  ///@}

  void Begin(vtkViewport* viewport) override;

  void DrawPoly(float* points, int n, unsigned char* colors = nullptr, int nc = 0) override;
  void DrawLines(float* f, int n, unsigned char* colors = nullptr, int nc = 0) override;
  void DrawPoints(float* points, int n, unsigned char* colors = nullptr, int nc = 0) override;
  void DrawPointSprites(vtkImageData* sprite, float* points, int n, unsigned char* colors = nullptr,
    int nc = 0) override;
  void DrawMarkers(int shape, bool highlight, float* points, int n, unsigned char* colors = nullptr,
    int nc = 0) override;
  void DrawQuad(float* points, int n) override;
  void DrawQuadStrip(float* points, int n) override;
  void DrawPolygon(float* points, int n) override;
  void DrawColoredPolygon(
    float* points, int n, unsigned char* colors = nullptr, int nc = 0) override;
  void DrawEllipseWedge(float x, float y, float outRx, float outRy, float inRx, float inRy,
    float startAngle, float stopAngle) override;
  void DrawEllipticArc(
    float x, float y, float rX, float rY, float startAngle, float stopAngle) override;
  void DrawString(float* point, const vtkStdString& string) override;
  void ComputeStringBounds(const vtkStdString& string, float bounds[4]) override;
  void ComputeJustifiedStringBounds(const char* string, float bounds[4]) override;
  void DrawMathTextString(float* point, const vtkStdString& string) override;
  void DrawImage(float p[2], float scale, vtkImageData* image) override;
  void DrawImage(const vtkRectf& pos, vtkImageData* image) override;
#if VTK_MAJOR_VERSION == 9 && VTK_MINOR_VERSION < 2
  // VTK 9.1's deprecated UTF-16 overloads, still pure virtual there
  void DrawString(float* point, const vtkUnicodeString& string) override;
  void ComputeStringBounds(const vtkUnicodeString& string, float bounds[4]) override;
#endif
  void SetColor4(unsigned char color[4]) override;
  void SetTexture(vtkImageData* image, int properties) override;
  void SetPointSize(float size) override;
  void SetLineWidth(float width) override;
  void SetLineType(int type) override;
  void SetMatrix(vtkMatrix3x3* m) override;
  void GetMatrix(vtkMatrix3x3* m) override;
  void MultiplyMatrix(vtkMatrix3x3* m) override;
  void PushMatrix() override;
  void PopMatrix() override;
  void SetClipping(int* x) override;
  void EnableClipping(bool enable) override;

protected:
  vtkStylizeCairoContextDevice2D();
  ~vtkStylizeCairoContextDevice2D() override;

private:
  vtkStylizeCairoContextDevice2D(const vtkStylizeCairoContextDevice2D&) = delete;
  void operator=(const vtkStylizeCairoContextDevice2D&) = delete;

  using Matrix = std::array<double, 6>; // x' = m0 x + m1 y + m2, y' = m3 x + m4 y + m5

  /** Page coordinates of device point (x, y) through the current matrix. */
  void ToPage(double x, double y, double& px, double& py) const;
  /** Saves cairo's state and clips to the clipping rectangle when it is on. */
  void Open();
  void Close();
  /** Strokes the current path with the pen (nothing with NO_PEN); `rgba` overrides its colour. */
  void StrokePen(const unsigned char* rgba = nullptr);
  /** Fills the current path with the brush. */
  void FillBrush();
  /** A path through n points (closed or not), placed as a line or as a fill's edge. */
  void PathThrough(const float* points, int n, bool closed, bool line = false);
  /** Draws an RGB(A) image into the page rectangle (x, y) .. (x + w, y + h), device y up. */
  void PaintImage(vtkImageData* image, double x, double y, double w, double h);
  int Dpi() const;

  cairo_t* Cr = nullptr;
  double PageHeight = 0.0;
  double Scale = 1.0;
  int DotsPerInch = 72;
  Matrix Current = { 1, 0, 0, 0, 1, 0 };
  double Origin[2] = { 0, 0 }; // the viewport's origin in the window (pixels)
  std::vector<Matrix> Stack;
  bool Clipping = false;
  int ClipRect[4] = { 0, 0, 0, 0 };
  float PointSize = 1.0f;
  long long Shapes = 0, Texts = 0, Images = 0;
};

#endif
