/**
 * @class   vtkStylizeFeatureStrokes
 * @brief   Feature lines drawn as strokes (private to the module): the lines an illustrator
 *          draws on the renderer's surfaces (vtkStylizeFeatureLines), their hidden parts removed
 *          (vtkStylizeLineVisibility), as polylines of varying width in the image's pixels, and
 *          their ink coverage as a texture the styles' final stages read.
 *
 * A style that draws feature lines (vtkLineArtPass; the comic's and the sketch's line phase)
 * owns one. Per frame, Build() finds the lines of every visible opaque actor drawn as a surface
 * (its data through the actor's matrix: polygonal data, the leaves of composite data, other
 * datasets through vtkDataSetSurfaceFilter; an actor drawn as wireframe gives its edges), tests
 * them against the scene's depth (the G-buffer's linear depth: every actor hides lines) or, with
 * no depth, by ray casting against the same surfaces (the exact path of vector figures), and
 * turns the visible runs into strokes. What does not depend on the view (curvature, creases,
 * ridges, valleys) is kept per dataset between frames.
 *
 * On several processes (ParaView's ranks, each with its own pieces) process 0's composited depth
 * is sent to every process, whose lines are tested against it, with thresholds and taper from
 * the whole data's bounds; their ink is combined on process 0: 1 and N processes draw alike.
 *
 * Widths are in points, each kind its own, thinned with depth across the scene (DepthTaper)
 * and with the line's strength (StrengthTaper). The ink is the union of round-capped segments,
 * anti-aliased over one pixel, so a tile of a magnified screenshot draws what the full image
 * draws there (the style gives it a guard band of Reach() pixels).
 */
#ifndef vtkStylizeFeatureStrokes_h
#define vtkStylizeFeatureStrokes_h

#include "vtkObject.h"
#include "vtkSmartPointer.h"        // for vtkSmartPointer
#include "vtkStylizePassesModule.h" // for export macro
#include "vtkStylizeStylePass.h"    // for vtkStylizeStylePass::Frame

#include <algorithm> // for std::max
#include <array>     // for std::array
#include <memory>    // for std::unique_ptr
#include <vector>    // for std::vector

class vtkDataSet;
class vtkFloatArray;
class vtkMultiProcessController;
class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

class VTKSTYLIZEPASSES_NO_EXPORT vtkStylizeFeatureStrokes : public vtkObject
{
public:
  static vtkStylizeFeatureStrokes* New();
  vtkTypeMacro(vtkStylizeFeatureStrokes, vtkObject);

  /** The number of kinds of line (vtkStylizeFeatureLines::Kinds). */
  static constexpr int Kinds = 7;

  /** What to draw and how (the owning style's settings). */
  struct Settings
  {
    /** Stroke width per kind (vtkStylizeFeatureLines::Kinds), points; 0: the kind is off. */
    double Widths[Kinds] = { 2.5, 2.5, 1.5, 1.0, 1.0, 1.2, 0.0 };
    /** Iso-lines of the coloured data (vtkStylizeStylePass::IsoLines, IsoLineSpacing): their
     * most levels, 0 for none, and how they are placed. */
    int IsoLines = 0;
    int IsoLineSpacing = 0;
    /** Share of the width lost from the scene's nearest to its farthest point, [0, 1]. */
    double DepthTaper = 0.5;
    /** Share of the width that follows the line's strength (FeatureStrength), [0, 1]. */
    double StrengthTaper = 1.0;
    /** vtkStylizeFeatureLines' thresholds. */
    double CreaseAngle = 40.0;
    double RidgeThreshold = 40.0;
    double SuggestiveThreshold = 2000.0;
    /** The lines of the translucent surfaces (opacity below 1: a translucent layer's, seen
     * against that layer's depth) instead of the opaque ones'. */
    bool Translucent = false;

    /**
     * The default proportions between the kinds (those of vtkLineArtPass), the contours
     * `width` points wide: what the comic's and the sketch's line phase draw.
     */
    static Settings Proportional(double width)
    {
      Settings s;
      const double scale = width / s.Widths[0];
      for (double& w : s.Widths)
      {
        w *= scale;
      }
      return s;
    }

    /** The style's iso-line settings (vtkStylizeStylePass::IsoLines, IsoLineWidth and
     * IsoLineSpacing). */
    Settings& WithIsoLines(int isoLines, double width, int spacing)
    {
      this->IsoLines = isoLines;
      this->IsoLineSpacing = spacing;
      this->Widths[Kinds - 1] = isoLines > 0 ? width : 0.0;
      return *this;
    }

    /**
     * What the comic's and the sketch's line phase draw: the feature lines (when on) in the
     * default proportions, the contours `width` points wide, and the style's iso-lines.
     */
    static Settings ForStyle(
      bool featureLines, double width, int isoLines, double isoWidth, int spacing)
    {
      return Proportional(featureLines ? width : 0.0).WithIsoLines(isoLines, isoWidth, spacing);
    }
  };

  /** The image the strokes are drawn in (a style's frame). */
  struct View
  {
    vtkRenderer* Renderer = nullptr;
    /** The pixels drawn (the depth image's size). */
    int Size[2] = { 0, 0 };
    /**
     * The viewport the camera projects onto (a tile of a magnified screenshot, where VTK narrows
     * the camera to the tile), pixels; its aspect is the projection's.
     */
    double ViewportSize[2] = { 1.0, 1.0 };
    /** The lower-left corner of the drawn pixels in that viewport, pixels (< 0 in a guard band). */
    double ViewportOffset[2] = { 0.0, 0.0 };
    /** Pixels per point. */
    double PointSize = 1.0;
    /** The cheap variant: contours, boundaries and creases only (no curvature). */
    bool Interactive = false;
    /** The narrowest stroke, pixels: 1 in a rendered frame (reduced or not), so that thin
     * strokes stay whole lines; 0 (the default) for a vector figure, which has no pixels. */
    double MinimumWidth = 0.0;
    /** The scene's bounds for the depth taper; invalid (the default): the renderer's props'. */
    double SceneBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
    /**
     * Per actor (in the renderer's order, among those drawn): the bounds of its whole data, that
     * the lines' thresholds are relative to (vtkStylizeFeatureLines::SetObjectBounds()); empty
     * (the default): each dataset's own.
     */
    std::vector<std::array<double, 6>> ObjectBounds;
    /**
     * Per actor (in the same order): the data whose lines are drawn in its place, null for the
     * actor's own; empty (the default): every actor's own (BuildFigure() gives the whole data
     * gathered from several processes).
     */
    std::vector<vtkSmartPointer<vtkDataSet>> Surfaces;
  };

  /**
   * Finds the visible lines of `view`'s renderer as strokes. `linearDepth`: the scene's
   * -z in view space per pixel of view.Size (0 where nothing was drawn), as the G-buffer's
   * LINEAR_DEPTH; nullptr: visibility by ray casting against the surfaces. Returns the number
   * of strokes.
   */
  vtkIdType Build(const View& view, const Settings& settings, vtkFloatArray* linearDepth);

  /**
   * Build() for a vector figure: visibility by ray casting. Over several processes (controller
   * with more than one), each holding pieces of the actors' data, the pieces go to process 0,
   * which joins each actor's pieces into one surface (ghost cells left out, the points two pieces
   * share merged, so that no line is drawn along the cuts) and finds the lines of the whole
   * scene against all of it; the other processes are left with no strokes. Collective: every
   * process calls it. Returns the number of strokes.
   */
  vtkIdType BuildFigure(
    const View& view, const Settings& settings, vtkMultiProcessController* controller);

  /**
   * Build() for a style's frame: the lines against the style's G-buffer (its linear depth,
   * which the frame must have rendered), in the frame's pixels (its guard band included), lengths
   * at the frame's pixels per point, the interactive variant in an interactive frame; then
   * Upload(). Returns the ink texture.
   */
  vtkTextureObject* RenderFrame(
    vtkStylizeStylePass* style, const vtkStylizeStylePass::Frame& frame, const Settings& settings);

  /**
   * BuildFigure() for a style's vector figure: the strokes of `renderer`'s scene (the style's
   * last) in an image `width` x `height` pixels drawn in `tiles` x `tiles` tiles, lengths at the
   * style's pixels per point there, the scene's volumes as the style draws them, over the
   * style's G-buffer's processes. Returns GetStrokes().
   */
  vtkPolyData* RenderFigure(vtkStylizeStylePass* style, vtkRenderer* renderer,
    const Settings& settings, int width, int height, int tiles);

  /** The renderer of the last RenderFrame() (null before one, or once it is gone). */
  vtkRenderer* GetLastRenderer();

  /**
   * The strokes of the last Build() as polylines: points (x, y, 0) in the drawn pixels (row 0
   * at the bottom), point data StrokeWidth (float, pixels) and cell data FeatureKind.
   */
  vtkPolyData* GetStrokes();

  /**
   * The ink coverage of the last Build()'s strokes in [0, 1], one float per pixel of
   * view.Size, rows bottom to top, uploaded as a float texture with nearest filtering: its red
   * channel the ink, its green channel (when the strokes hold iso-lines) their halo.
   */
  vtkTextureObject* Upload(vtkOpenGLRenderWindow* window);

  /** The texture of the last Upload() (nullptr before it). */
  vtkTextureObject* GetTexture();

  /**
   * The ink coverage on the CPU (what Upload() sends): one float per pixel, or two (the ink,
   * and the iso-lines' halo) when the last Build() drew iso-lines.
   */
  void Rasterize(std::vector<float>& coverage);

  /**
   * The half width of the halo an iso-line of half width r pixels clears in the patterns beside
   * it, pixels, at `pointSize` pixels per point: r plus the line's width, at least 3 points, so
   * that the line reads over hatching, dots and pencil (in points: a magnified screenshot keeps
   * its proportions).
   */
  static double HaloRadius(double r, double pointSize)
  {
    return r + std::max(3.0 * pointSize, 2.0 * r);
  }

  /** How far a stroke reaches from its line, pixels: half the widest stroke, plus one. */
  static double Reach(const Settings& settings, double pointSize);

  /** Frees the texture (the window's context current). */
  void Free(vtkWindow* w);

  /** Forgets the surfaces' cached lines. */
  void ClearCache();

  /** Bytes of the texture. */
  vtkIdType GetTextureBytes();

protected:
  vtkStylizeFeatureStrokes();
  ~vtkStylizeFeatureStrokes() override;

private:
  vtkStylizeFeatureStrokes(const vtkStylizeFeatureStrokes&) = delete;
  void operator=(const vtkStylizeFeatureStrokes&) = delete;

  /** Uploads the coverage of the last Rasterize() into the texture. */
  vtkTextureObject* UploadCoverage(vtkOpenGLRenderWindow* window);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
