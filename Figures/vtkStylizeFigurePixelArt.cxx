#include "vtkStylizeFigurePixelArt.h"

#include <map>
#include <vector>

namespace vtkStylizeFigure
{
//------------------------------------------------------------------------------
void DrawPixelArt(Canvas& c, const Image& frame)
{
  const int W = frame.W, H = frame.H;
  // rows of runs of one colour, equal runs of consecutive rows merged into one rectangle
  struct Run
  {
    int X0, X1, Y0, Y1;
    unsigned Key;
  };
  std::vector<Run> done, open;
  for (int row = 0; row < H; ++row)
  {
    const int y = H - 1 - row; // page rows top down
    std::vector<Run> runs;
    for (int x = 0; x < W;)
    {
      const unsigned key = frame.Key(x, y);
      int x1 = x + 1;
      while (x1 < W && frame.Key(x1, y) == key)
      {
        ++x1;
      }
      runs.push_back({ x, x1, row, row + 1, key });
      x = x1;
    }
    std::vector<Run> next;
    size_t j = 0;
    for (Run& r : runs)
    {
      while (j < open.size() && open[j].X0 < r.X0)
      {
        done.push_back(open[j++]);
      }
      if (j < open.size() && open[j].X0 == r.X0 && open[j].X1 == r.X1 && open[j].Key == r.Key)
      {
        Run merged = open[j++];
        merged.Y1 = row + 1;
        next.push_back(merged);
      }
      else
      {
        next.push_back(r);
      }
    }
    while (j < open.size())
    {
      done.push_back(open[j++]);
    }
    open.swap(next);
  }
  done.insert(done.end(), open.begin(), open.end());
  std::map<unsigned, std::vector<const Run*>> byColor;
  for (const Run& r : done)
  {
    byColor[r.Key].push_back(&r);
  }
  for (const auto& kv : byColor)
  {
    cairo_new_path(c.Cr);
    for (const Run* r : kv.second)
    {
      cairo_rectangle(c.Cr, r->X0, r->Y0, r->X1 - r->X0, r->Y1 - r->Y0);
    }
    SetColor(c.Cr, kv.first);
    cairo_fill(c.Cr);
    c.Rectangles += static_cast<long long>(kv.second.size());
  }
}
}
