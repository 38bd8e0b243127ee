// Checks of vtkStylizeRankCompositor on any controller: the CPU compositing of G-buffer parts
// by depth. Used by TestRankCompositor (one process, vtkDummyController) and by
// TestRankCompositorMPI (2 ranks under mpiexec).
#ifndef RankCompositorChecks_h
#define RankCompositorChecks_h

#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkStylizeRankCompositor.h"

#include <cstdio>
#include <vector>

namespace rankcheck
{
using Part = vtkStylizeRankCompositor::Part;

/** A part over rect (x, y, w, h): depth from `depth(x, y)` (image coordinates), one 1-float
 * channel holding `value` and one 4-float channel holding (value, x, y, 1). */
template <typename F>
Part MakePart(int x0, int y0, int w, int h, float value, F depth)
{
  Part p;
  p.Rect[0] = x0;
  p.Rect[1] = y0;
  p.Rect[2] = w;
  p.Rect[3] = h;
  p.Channels.resize(2);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      p.Depth.push_back(depth(x0 + x, y0 + y));
      p.Channels[0].push_back(value);
      p.Channels[1].insert(p.Channels[1].end(),
        { value, static_cast<float>(x0 + x), static_cast<float>(y0 + y), 1.0f });
    }
  }
  return p;
}

/**
 * The value of `p` at image pixel (x, y): depth and channel 0 (-1 for a part without channels,
 * as a broadcast depth), or (2, -1) outside its rect.
 */
inline std::pair<float, float> At(const Part& p, int x, int y)
{
  const int lx = x - p.Rect[0], ly = y - p.Rect[1];
  if (lx < 0 || ly < 0 || lx >= p.Rect[2] || ly >= p.Rect[3])
  {
    return { 2.0f, -1.0f };
  }
  const size_t i = static_cast<size_t>(ly) * p.Rect[2] + lx;
  return { p.Depth[i], p.Channels.empty() ? -1.0f : p.Channels[0][i] };
}

/**
 * Runs the checks on `controller` (1 or 2 processes); returns the number of failures.
 * Process 0 holds a 4 x 4 square at (0, 0), depth 0.5, value 1; process 1 (when there is one)
 * a 4 x 4 square at (2, 2) of an 8 x 8 image, depth 0.25 left of x = 4 and 0.75 from there,
 * value 2. After Reduce(), process 0 holds their union (0, 0, 6, 6): the nearer of the two where
 * both are, each alone where one is, depth 1 and zeros elsewhere.
 */
inline int Run(vtkMultiProcessController* controller)
{
  int failures = 0;
  auto check = [&](bool ok, const char* what, int x = -1, int y = -1)
  {
    if (!ok)
    {
      std::fprintf(stderr, "FAIL (process %d): %s at (%d, %d)\n",
        controller ? controller->GetLocalProcessId() : 0, what, x, y);
      ++failures;
    }
  };
  const std::vector<int> components = { 1, 4 };
  const int rank = controller ? controller->GetLocalProcessId() : 0;
  const int size = controller ? controller->GetNumberOfProcesses() : 1;
  vtkNew<vtkStylizeRankCompositor> compositor;
  compositor->SetController(controller);

  // Pure functions, on every process.
  int u[4];
  const int a[4] = { 0, 0, 4, 4 }, b[4] = { 2, 2, 4, 4 }, empty[4] = { 5, 5, 0, 0 };
  vtkStylizeRankCompositor::UnionRect(a, b, u);
  check(u[0] == 0 && u[1] == 0 && u[2] == 6 && u[3] == 6, "UnionRect of two squares");
  vtkStylizeRankCompositor::UnionRect(a, empty, u);
  check(u[0] == 0 && u[1] == 0 && u[2] == 4 && u[3] == 4, "UnionRect with an empty rect");
  check(vtkStylizeRankCompositor::InsideImage(b, 8, 8), "InsideImage inside");
  // InFront: two slabs of a partition along z sharing a layer of cells, seen from above and
  // below (perspective: the eye's side of the plane between them; parallel: the direction),
  // side by side along x, and a box inside another (the nearer centre)
  using C = vtkStylizeRankCompositor;
  const double lower[6] = { 0, 1, 0, 1, 0, 0.55 }, upper[6] = { 0, 1, 0, 1, 0.5, 1 };
  const double above[3] = { 0.5, 0.5, 5 }, below[3] = { 0.5, 0.5, -5 };
  const double down[3] = { 0, 0, -1 }, up[3] = { 0, 0, 1 };
  check(
    C::InFront(upper, lower, false, above, down) && !C::InFront(lower, upper, false, above, down),
    "InFront: the upper slab first from above");
  check(C::InFront(lower, upper, false, below, up) && !C::InFront(upper, lower, false, below, up),
    "InFront: the lower slab first from below");
  check(C::InFront(upper, lower, true, below, down) && C::InFront(lower, upper, true, above, up),
    "InFront: parallel projection follows the direction, not the position");
  const double left[6] = { 0, 1, 0, 1, 0, 1 }, right[6] = { 1, 2, 0, 1, 0, 1 };
  const double side[3] = { 5, 0.5, 0.5 }, west[3] = { -1, 0, 0 };
  check(C::InFront(right, left, false, side, west), "InFront: side by side, the eye's side");
  const double outer[6] = { 0, 4, 0, 4, 0, 4 }, inner[6] = { 1, 3, 1, 3, 0, 2.5 };
  check(C::InFront(inner, outer, false, below, up) && !C::InFront(inner, outer, false, above, down),
    "InFront: overlapping boxes, the nearer centre");
  const int out[4] = { 6, 0, 4, 4 }, negative[4] = { -1, 0, 2, 2 };
  check(!vtkStylizeRankCompositor::InsideImage(out, 8, 8), "InsideImage past the width");
  check(!vtkStylizeRankCompositor::InsideImage(negative, 8, 8), "InsideImage negative origin");
  {
    Part own = MakePart(0, 0, 4, 4, 1.0f, [](int, int) { return 0.5f; });
    Part in = MakePart(2, 2, 4, 4, 2.0f, [](int x, int) { return x < 4 ? 0.25f : 0.75f; });
    vtkStylizeRankCompositor::Merge(own, in, components);
    check(own.Rect[2] == 6 && own.Rect[3] == 6, "Merge's rectangle");
    check(At(own, 3, 3) == std::make_pair(0.25f, 2.0f), "Merge keeps the nearer", 3, 3);
    check(At(own, 1, 1) == std::make_pair(0.5f, 1.0f), "Merge keeps its own alone", 1, 1);
    check(At(own, 5, 5) == std::make_pair(0.75f, 2.0f), "Merge takes the other alone", 5, 5);
    check(At(own, 0, 5) == std::make_pair(1.0f, 0.0f), "Merge leaves the rest empty", 0, 5);
    const size_t i = 3 * 6 + 5; // (5, 3): the other's, 4 components carried whole
    check(own.Channels[1][4 * i + 1] == 5.0f && own.Channels[1][4 * i + 2] == 3.0f,
      "Merge carries every component", 5, 3);
    Part tie = MakePart(0, 0, 4, 4, 3.0f, [](int, int) { return 0.5f; });
    Part first = MakePart(0, 0, 4, 4, 1.0f, [](int, int) { return 0.5f; });
    vtkStylizeRankCompositor::Merge(first, tie, components);
    check(At(first, 2, 2).second == 1.0f, "Merge keeps its own on a tie", 2, 2);
  }

  // The collective calls.
  Part mine = rank == 0 ? MakePart(0, 0, 4, 4, 1.0f, [](int, int) { return 0.5f; })
    : rank == 1 ? MakePart(2, 2, 4, 4, 2.0f, [](int x, int) { return x < 4 ? 0.25f : 0.75f; })
                : Part();
  mine.Channels.resize(2);
  const bool root = compositor->Reduce(mine, components, 8, 8);
  check(root == (rank == 0), "Reduce is true on process 0 alone");
  if (rank == 0)
  {
    if (size == 1)
    {
      check(mine.Rect[2] == 4 && At(mine, 3, 3) == std::make_pair(0.5f, 1.0f),
        "Reduce on one process keeps the part", 3, 3);
    }
    else
    {
      check(mine.Rect[2] == 6 && mine.Rect[3] == 6, "Reduce's rectangle");
      check(At(mine, 3, 3) == std::make_pair(0.25f, 2.0f), "Reduce keeps the nearer", 3, 3);
      check(At(mine, 1, 1) == std::make_pair(0.5f, 1.0f), "Reduce keeps process 0's", 1, 1);
      check(At(mine, 5, 5) == std::make_pair(0.75f, 2.0f), "Reduce takes process 1's", 5, 5);
      check(At(mine, 5, 0) == std::make_pair(1.0f, 0.0f), "Reduce leaves the rest", 5, 0);
    }
  }
  Part depth;
  if (rank == 0)
  {
    depth = mine;
  }
  compositor->BroadcastDepth(depth, 8, 8);
  const int expected = size == 1 ? 4 : 6;
  check(depth.Rect[2] == expected && depth.Rect[3] == expected &&
      static_cast<int>(depth.Depth.size()) == expected * expected,
    "BroadcastDepth's rectangle");
  check(size == 1 || At(depth, 3, 3).first == 0.25f, "BroadcastDepth's depth", 3, 3);
  // A process whose part lies outside the image (issue 53): refused with an error, and the next
  // frame composites as if it had not happened (the refused part's data was sent all the same,
  // and process 0 took it for the next frame's).
  for (int frame = 0; frame < 2; ++frame)
  {
    Part part = rank == 0       ? MakePart(0, 0, 4, 4, 1.0f, [](int, int) { return 0.5f; })
      : rank == 1 && frame == 0 ? MakePart(6, 6, 4, 4, 9.0f, [](int, int) { return 0.125f; })
      : rank == 1 ? MakePart(2, 2, 4, 4, 2.0f, [](int x, int) { return x < 4 ? 0.25f : 0.75f; })
                  : Part();
    part.Channels.resize(2);
    compositor->Reduce(part, components, 8, 8);
    if (rank == 0 && size > 1)
    {
      if (frame == 0)
      {
        check(part.Rect[2] == 4 && At(part, 3, 3) == std::make_pair(0.5f, 1.0f),
          "a part outside the image is refused", 3, 3);
      }
      else
      {
        check(part.Rect[2] == 6 && At(part, 3, 3) == std::make_pair(0.25f, 2.0f) &&
            At(part, 5, 5) == std::make_pair(0.75f, 2.0f),
          "the frame after a refused part", 5, 5);
      }
    }
  }

  Part outside;
  const int bad[4] = { 6, 6, 4, 4 };
  std::copy(bad, bad + 4, outside.Rect);
  outside.Depth.assign(16, 0.5f);
  compositor->SetController(nullptr); // the refusal of a part outside the image, locally
  compositor->BroadcastDepth(outside, 8, 8);
  check(outside.Area() == 0, "a depth outside the image is dropped");
  return failures;
}
}

#endif
