/**
 * @class   vtkStylizeRankCompositor
 * @brief   Composites G-buffer channels across processes by depth, on the CPU.
 *
 * Each process holds a part: the rectangle where it drew a surface and, inside it, the stored
 * depth and each channel. Reduce() sends every process's part to process 0, which keeps the
 * nearest surface at every pixel (a binary tree, log2(N) steps; ties go to the lower process);
 * BroadcastDepth() gives process 0's rectangle and depth to every process. The G-buffer's own
 * textures are read into parts and written back from them by vtkStylizeGBufferPass. InFront()
 * orders the processes' pieces of a volume for compositing them over each other
 * (vtkStylizePlainVolumes).
 */

#ifndef vtkStylizeRankCompositor_h
#define vtkStylizeRankCompositor_h

#include "vtkObject.h"
#include "vtkStylizePassesModule.h" // for export macro

#include <vector> // for std::vector

class vtkMultiProcessController;

class VTKSTYLIZEPASSES_EXPORT vtkStylizeRankCompositor : public vtkObject
{
public:
  static vtkStylizeRankCompositor* New();
  vtkTypeMacro(vtkStylizeRankCompositor, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * One process's part of a composite by depth: the rectangle (x, y, width, height) where it
   * drew a surface and, inside it row by row, the depth and each channel (its number of floats
   * per pixel given by the components passed with it).
   */
  struct Part
  {
    int Rect[4] = { 0, 0, 0, 0 };
    std::vector<float> Depth;
    std::vector<std::vector<float>> Channels;

    vtkIdType Area() const { return static_cast<vtkIdType>(this->Rect[2]) * this->Rect[3]; }
  };

  /** The processes that composite (collective calls). No controller: one process. */
  virtual void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);

  /**
   * Sends every process's part to process 0, which keeps the nearest by depth at every pixel of
   * a w x h image. Returns true on process 0 (`own` then holds the union of all parts), false on
   * the others (`own` was sent). Every process passes the same w x h. A part outside the
   * image, or with fewer values than its rectangle holds, is not sent (an error on its process),
   * so that the frames after it composite as if it had not been there.
   */
  bool Reduce(Part& own, const std::vector<int>& components, int w, int h);

  /** Process 0's rectangle and depth to every process (a part outside the image: emptied). */
  void BroadcastDepth(Part& part, int w, int h);

  /**
   * Copies `from`'s pixels into `to`, whose rectangle holds `from`'s: all of them or, with
   * `nearer`, only those nearer than what `to` holds.
   */
  static void Paste(Part& to, const Part& from, const std::vector<int>& components, bool nearer);

  /**
   * Keeps in `own` its pixels and, over the union of both rectangles, `in`'s where nearer (ties:
   * `own`). Pixels of the union that neither holds get the depth 1 and zeros.
   */
  static void Merge(Part& own, Part& in, const std::vector<int>& components);

  /** The smallest rectangle holding both (x, y, width, height; an empty one holds nothing). */
  static void UnionRect(const int a[4], const int b[4], int out[4]);

  /** Whether rect lies inside a w x h image (an empty rectangle does). */
  static bool InsideImage(const int rect[4], int w, int h);

  /**
   * Whether the box `a` (xmin, xmax, ymin, ymax, zmin, zmax) lies in front of `b` seen from a
   * camera at `eye` (perspective) or looking along `direction` (parallel): on the camera's side
   * of the plane between them along the axis where they are farthest apart, or, where they
   * overlap on every axis by more than a quarter of their sizes, the nearer by its centre.
   */
  static bool InFront(const double a[6], const double b[6], bool parallel, const double eye[3],
    const double direction[3]);

protected:
  vtkStylizeRankCompositor() = default;
  ~vtkStylizeRankCompositor() override;

  vtkMultiProcessController* Controller = nullptr;

private:
  vtkStylizeRankCompositor(const vtkStylizeRankCompositor&) = delete;
  void operator=(const vtkStylizeRankCompositor&) = delete;
};

#endif
