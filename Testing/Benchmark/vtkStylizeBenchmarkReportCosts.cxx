// vtkStylizeBenchmark: the report's tables of what a configuration adds over plain: issue 15's
// speed targets, the comic, pixel art and sketch costs next to VTK's screen-space passes, and
// whether the added cost is flat in triangle count.

#include "vtkStylizeBenchmarkReport.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

namespace vtkstylizebenchmark
{
std::string Report::TargetRatio(
  const std::string& scene, int n, const char* a, const char* b, bool added) const
{
  if (!this->Has(a) || !this->Has(b))
  {
    return std::string("—");
  }
  const double plain = this->MedianOf(scene, n, "plain");
  const double x = this->MedianOf(scene, n, a) - (added ? plain : 0.0);
  const double y = this->MedianOf(scene, n, b) - (added ? plain : 0.0);
  // An added cost within the frame-to-frame noise (under 2 ms or 2% of the frame) makes
  // no ratio: say what it was instead.
  if (added && !(y > std::max(2.0, 0.02 * plain)))
  {
    return std::string("n/a (") + b + " adds " + Fixed(y, 1) + " ms)";
  }
  return Fixed(x / y, 2);
}

// The speed targets of issue 15, per scene and light count: each style against the VTK pass
// that does comparable work, measured in the same run.
void Report::WriteTargets(std::ostream& os) const
{
  os << "\n### Targets (issue 15)\n\n";
  os << "Lighting: light-standard / plain (target <= 1.10 at 1 and 8 lights). Comic: what comic "
        "adds over plain / what sobel adds (target <= 1.0). Sketch: what sketch-8 adds / what "
        "ssao adds (target <= 0.75). Pixel art: pixel-fast-4 / plain (target <= 0.8 on the "
        "scan, <= 1.0 on the isosurface).\n\n";
  os << "| scene | lights | lighting / plain | comic added / sobel added | sketch-8 added / "
        "ssao added | pixel-fast-4 / plain |\n";
  os << "| --- | ---: | ---: | ---: | ---: | ---: |\n";
  for (const auto& sc : this->Opt.Scenes)
  {
    for (int n : this->Opt.Lights)
    {
      os << "| " << SceneLabel(sc.Name) << " | " << n << " | "
         << this->TargetRatio(sc.Name, n, "light-standard", "plain", false) << " | "
         << this->TargetRatio(sc.Name, n, "comic", "sobel", true) << " | "
         << this->TargetRatio(sc.Name, n, "sketch-8", "ssao", true) << " | "
         << this->TargetRatio(sc.Name, n, "pixel-fast-4", "plain", false) << " |\n";
    }
  }
}

// Comic: the screen-space stage next to VTK's own screen-space passes.
void Report::WriteComic(std::ostream& os) const
{
  os << "\n### Comic: added cost per frame next to VTK's screen-space passes (ms)\n\n";
  os << "Added = configuration − plain. Comic stage = comic − gbuf-comic-lin: the comic "
        "pass's screen-space stage (edges, dots, hatching) over its own G-buffer, the cost "
        "the target compares with VTK's single colour Sobel pass (sobel − plain, which "
        "includes its own render to a texture).\n\n";
  os << "| scene | lights | sobel added | ssao added | comic added | comic stage | "
        "comic-geometric stage | comic stage / sobel added |\n";
  os << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const auto& sc : this->Opt.Scenes)
  {
    for (int n : this->Opt.Lights)
    {
      const double plain = this->MedianOf(sc.Name, n, "plain");
      const double base = this->MedianOf(sc.Name, n, "gbuf-comic-lin");
      const double sobel = this->MedianOf(sc.Name, n, "sobel") - plain;
      const double ssao = this->Has("ssao") ? this->MedianOf(sc.Name, n, "ssao") - plain : NAN;
      const double comic = this->MedianOf(sc.Name, n, "comic");
      const double geo =
        this->Has("comic-geometric") ? this->MedianOf(sc.Name, n, "comic-geometric") - base : NAN;
      os << "| " << SceneLabel(sc.Name) << " | " << n << " | " << Fixed(sobel, 1) << " | "
         << Fixed(ssao, 1) << " | " << Fixed(comic - plain, 1) << " | " << Fixed(comic - base, 1)
         << " | " << Fixed(geo, 1) << " | " << Fixed((comic - base) / sobel, 2) << " |\n";
    }
  }
}

// Pixel art: the target, read from the ratio table.
void Report::WritePixelTarget(std::ostream& os) const
{
  os << "\n### Pixel art target\n\n";
  os << "pixel-fast-4 / plain must be <= 0.5 at 10k triangles and <= 1 at 2M (1 light); the "
        "ratios of every pixel configuration are in the ratio table above.\n\n";
  for (const auto& sc : this->Opt.Scenes)
  {
    const int n = this->Opt.Lights.front();
    os << "- " << SceneLabel(sc.Name) << ", " << n << " light(s): pixel-fast-4 / plain = "
       << Fixed(this->MedianOf(sc.Name, n, "pixel-fast-4") / this->MedianOf(sc.Name, n, "plain"), 2)
       << "\n";
  }
}

// Sketch: the target against SSAO.
void Report::WriteSketch(std::ostream& os) const
{
  os << "\n### Sketch against SSAO: added cost per frame (ms)\n\n";
  os << "Added = configuration − plain. Target: sketch-8 (8 neighbours, 10 LIC steps) adds at "
        "most 0.75 × what ssao adds. sketch-8 − sketch-8-stage is the screen-space sketch stage "
        "over its own G-buffer.\n\n";
  os << "| scene | lights | ssao added | sketch-2 added | sketch-4 added | sketch-8 added | "
        "sketch-8 stage | sketch-8 added / ssao added |\n";
  os << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const auto& sc : this->Opt.Scenes)
  {
    for (int n : this->Opt.Lights)
    {
      const double plain = this->MedianOf(sc.Name, n, "plain");
      const double ssao = this->MedianOf(sc.Name, n, "ssao") - plain;
      auto added = [&](const char* config)
      { return this->Has(config) ? this->MedianOf(sc.Name, n, config) - plain : NAN; };
      const double stage = this->Has("sketch-8-stage")
        ? this->MedianOf(sc.Name, n, "sketch-8") - this->MedianOf(sc.Name, n, "sketch-8-stage")
        : NAN;
      os << "| " << SceneLabel(sc.Name) << " | " << n << " | " << Fixed(ssao, 1) << " | "
         << Fixed(added("sketch-2"), 1) << " | " << Fixed(added("sketch-4"), 1) << " | "
         << Fixed(added("sketch-8"), 1) << " | " << Fixed(stage, 1) << " | "
         << Fixed(added("sketch-8") / ssao, 2) << " |\n";
    }
  }
}

// Flatness in triangle count: the added cost at the smallest and the largest mesh scene (a
// volume scene has no triangles).
void Report::WriteFlatness(std::ostream& os) const
{
  auto fewer = [this](const SceneSpec& a, const SceneSpec& b)
  { return this->Triangles(a.Name) < this->Triangles(b.Name); };
  std::vector<SceneSpec> scenes;
  std::copy_if(this->Opt.Scenes.begin(), this->Opt.Scenes.end(), std::back_inserter(scenes),
    [](const SceneSpec& s) { return !s.Volume; });
  if (scenes.size() < 2)
  {
    return;
  }
  const SceneSpec& small = *std::min_element(scenes.begin(), scenes.end(), fewer);
  const SceneSpec& large = *std::max_element(scenes.begin(), scenes.end(), fewer);
  os << "\n### Is the added cost flat in triangle count?\n\n";
  os << "Added cost = configuration − plain (median ms, same lights), at " << SceneLabel(small.Name)
     << " (" << FormatCount(this->Triangles(small.Name)) << " triangles) and "
     << SceneLabel(large.Name) << " (" << FormatCount(this->Triangles(large.Name))
     << " triangles). Verdict \"flat\" when the added cost changes by less than "
     << Fixed(this->Opt.FlatTolerance, 0) << "% of the larger of the two, or by less than "
     << Fixed(this->Opt.FlatFloor, 0)
     << " ms (timing noise); \"grows\" or \"shrinks\" otherwise.\n\n";
  os << "Read the verdict at 1 light for the overhead of the pass itself. With many lights the "
        "added cost is dominated by the difference in lighting cost (negative: cheaper than "
        "VTK's lighting), which is paid per shaded fragment. On a software rasterizer such as "
        "llvmpipe the number of shaded fragments grows with the triangle count (sub-pixel "
        "triangles are shaded in 2x2 quads), so per-fragment work in the geometry pass (a "
        "heavier lighting shader, extra G-buffer targets) grows with triangles too; full-screen "
        "post-processing does not.\n\n";
  os << "| configuration | lights | added @ " << small.Name << " | added @ " << large.Name
     << " | change | verdict |\n";
  os << "| --- | ---: | ---: | ---: | ---: | --- |\n";
  for (const auto& c : this->Opt.Configs)
  {
    if (c == "plain")
    {
      continue;
    }
    for (int n : this->Opt.Lights)
    {
      const double a = this->MedianOf(small.Name, n, c) - this->MedianOf(small.Name, n, "plain");
      const double b = this->MedianOf(large.Name, n, c) - this->MedianOf(large.Name, n, "plain");
      const double change = b - a;
      const double ref = std::max(std::abs(a), std::abs(b));
      std::string verdict = "n/a";
      std::string pct = "n/a";
      if (std::isfinite(change))
      {
        if (ref > 0)
        {
          pct = (change >= 0 ? "+" : "") + Fixed(100.0 * change / ref, 0) + "%";
        }
        const bool flat = std::abs(change) < this->Opt.FlatFloor ||
          std::abs(change) < this->Opt.FlatTolerance / 100.0 * ref;
        verdict = flat ? "flat" : (change > 0 ? "grows" : "shrinks");
      }
      os << "| " << c << " | " << n << " | " << Fixed(a, 1) << " | " << Fixed(b, 1) << " | "
         << (std::isfinite(change) ? (change >= 0 ? "+" : "") + Fixed(change, 1) : "n/a") << " ms ("
         << pct << ") | " << verdict << " |\n";
    }
  }
}
}
