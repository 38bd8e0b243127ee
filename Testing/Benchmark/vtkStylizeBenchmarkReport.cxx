// vtkStylizeBenchmark: the report's formatting, its header, the median, ratio and slope
// tables, the per-stage table, the CSV and the files. The tables of what each configuration
// adds over plain (issue 15's targets, flatness) are in vtkStylizeBenchmarkReportCosts.cxx.

#include "vtkStylizeBenchmarkReport.h"

#include "vtkVersion.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tuple>

namespace vtkstylizebenchmark
{
std::string Fixed(double v, int digits)
{
  if (!std::isfinite(v))
  {
    return "n/a";
  }
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

std::string FormatCount(vtkIdType n)
{
  std::string s = std::to_string(n);
  for (int i = static_cast<int>(s.size()) - 3; i > 0; i -= 3)
  {
    s.insert(static_cast<size_t>(i), ",");
  }
  return s;
}

std::string SceneLabel(const std::string& name)
{
  if (name == "bunny")
  {
    return "bunny (scan)";
  }
  if (name == "iso970k")
  {
    return "iso970k (isosurface)";
  }
  if (name == "headsq")
  {
    return "headsq (CT volume)";
  }
  return "sphere " + name;
}

void SortResults(const Options& opt, std::vector<Result>& results)
{
  auto rank = [&opt](const Result& r)
  {
    size_t s = 0, l = 0, c = 0;
    while (s < opt.Scenes.size() && opt.Scenes[s].Name != r.Scene)
    {
      ++s;
    }
    while (l < opt.Lights.size() && opt.Lights[l] != r.Lights)
    {
      ++l;
    }
    while (c < opt.Configs.size() && opt.Configs[c] != r.Config)
    {
      ++c;
    }
    return std::make_tuple(s, l, c);
  };
  std::stable_sort(results.begin(), results.end(),
    [&rank](const Result& a, const Result& b) { return rank(a) < rank(b); });
}

namespace
{
std::string Now()
{
  const std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof(buf), "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return buf;
}
}

std::string ReportHeader(const Options& opt, const RunInfo& info)
{
  std::ostringstream header;
  header << "## VTK Stylize benchmark\n\n";
  header << "- Renderer: " << info.Renderer << " (OpenGL " << info.GLVersion << "), VTK "
         << vtkVersion::GetVTKVersion() << "\n";
  header << "- " << opt.Width << "x" << opt.Height << ", offscreen, multisampling off; per case "
         << opt.Warmup << " warm-up frames (shader compilation excluded), then the median of "
         << opt.Frames
         << " timed frames, each a 0.5° camera azimuth step, Render() + glFinish, wall clock; "
            "one window per configuration, timed frames interleaved across configurations\n";
  header << "- Scenes: spheres (vtkSphereSource with point normals), a scanned mesh (bunny: "
            "the real-data set's, normals by vtkPolyDataNormals) and a wavelet isosurface "
            "(vtkRTAnalyticSource extent +-120, vtkContourFilter at 160 with normals), each "
            "moved into the unit sphere's box; one actor (Phong, specular 0.3), framed by "
            "ResetCamera() as the unit sphere, which covers about "
         << Fixed(info.CoveredPixels / 1000.0, 0) << "k pixels ("
         << Fixed(100.0 * info.CoveredPixels / opt.Width / opt.Height, 1) << "% of the image)";
  if (std::any_of(
        opt.Scenes.begin(), opt.Scenes.end(), [](const SceneSpec& s) { return s.Volume; }))
  {
    header << "; the volume scene headsq: VTK's CT of a head (" << opt.Volume
           << ") drawn by vtkGPUVolumeRayCastMapper with MedicalDemo4's transfer functions, "
              "shaded, seen from the front at 30 degrees (no mesh: its triangle count is 0)";
  }
  header << "\n";
  header << "- Lights: 1 = VTK's default headlight; more = scene lights on a golden-angle "
            "spiral around the object (1/3 directional, 1/3 point, 1/3 spot), white, "
            "intensity 1.5 / count; the same for every configuration\n";
  header << "- Configurations:\n";
  for (const auto& c : opt.Configs)
  {
    auto it = info.Descriptions.find(c);
    header << "  - `" << c << "`: " << (it == info.Descriptions.end() ? "" : it->second) << "\n";
  }
  header << "- Run time: " << Fixed(info.Seconds, 0) << " s, " << Now() << "\n";
  return header.str();
}

void WriteStageTable(std::ostream& md, const std::vector<StageResult>& stages)
{
  if (stages.empty())
  {
    return;
  }
  md << "\n### Per-stage cost\n\n"
     << "Median ms of each stage over 3 frames with stage timing on "
        "(vtkStylizeStylePass::StageTimingOn(): glFinish before and after each stage). "
        "SCENE: the lighting and G-buffer render of the geometry; BACKGROUND: the background "
        "written around the scene's rectangle; OUTPUT: a final stage without a name; AFTER: "
        "what follows the stylized image; xN: the stage ran N times (summed). Memory: bytes "
        "per pixel of the style's textures (G-buffer, intermediate targets, direction field; "
        "vtkStylizeStylePass::GetTextureBytes()).\n\n"
     << "| scene | lights | configuration | frame (timed) | memory (B/pixel) | stages |\n"
     << "| --- | ---: | --- | ---: | ---: | --- |\n";
  for (const auto& sr : stages)
  {
    md << "| " << SceneLabel(sr.Scene) << " | " << sr.Lights << " | " << sr.Config << " | "
       << Fixed(sr.Frame, 1) << " | " << Fixed(sr.BytesPerPixel, 1) << " |";
    const char* sep = " ";
    for (const auto& st : sr.Stages)
    {
      md << sep << st.first << " " << Fixed(st.second, 1);
      sep = ", ";
    }
    md << " |\n";
  }
}

//------------------------------------------------------------------------------------------------
// Report

namespace
{
std::string Key(const std::string& scene, int lights, const std::string& config)
{
  return scene + "|" + std::to_string(lights) + "|" + config;
}
}

Report::Report(const Options& opt, std::vector<Result> results)
  : Opt(opt)
  , Results(std::move(results))
{
  for (const auto& r : this->Results)
  {
    this->Index[Key(r.Scene, r.Lights, r.Config)] = &r;
    this->TriangleCount[r.Scene] = r.Triangles;
  }
}

const Result* Report::Find(const std::string& scene, int lights, const std::string& config) const
{
  auto it = this->Index.find(Key(scene, lights, config));
  return it == this->Index.end() ? nullptr : it->second;
}

double Report::MedianOf(const std::string& scene, int lights, const std::string& config) const
{
  const Result* r = this->Find(scene, lights, config);
  return r ? r->Median : NAN;
}

vtkIdType Report::Triangles(const std::string& scene) const
{
  auto it = this->TriangleCount.find(scene);
  return it == this->TriangleCount.end() ? 0 : it->second;
}

bool Report::Has(const std::string& config) const
{
  const auto& cfgs = this->Opt.Configs;
  return std::find(cfgs.begin(), cfgs.end(), config) != cfgs.end();
}

void Report::Fit(
  const std::string& scene, const std::string& config, double& slope, double& intercept) const
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (int lights : this->Opt.Lights)
  {
    const double y = this->MedianOf(scene, lights, config);
    if (!std::isfinite(y))
    {
      continue;
    }
    sx += lights;
    sy += y;
    sxx += double(lights) * lights;
    sxy += lights * y;
    ++n;
  }
  const double den = n * sxx - sx * sx;
  if (n < 2 || den == 0)
  {
    slope = intercept = NAN;
    return;
  }
  slope = (n * sxy - sx * sy) / den;
  intercept = (sy - slope * sx) / n;
}

void Report::Write(std::ostream& os, const std::string& header) const
{
  os << header;
  this->WriteMedians(os);
  const bool hasPlain = this->Has("plain");
  if (hasPlain)
  {
    this->WriteRatios(os);
    this->WriteTargets(os);
  }
  if (hasPlain && this->Has("sobel") && this->Has("comic") && this->Has("gbuf-comic-lin"))
  {
    this->WriteComic(os);
  }
  if (hasPlain && this->Has("pixel-fast-4"))
  {
    this->WritePixelTarget(os);
  }
  if (hasPlain && this->Has("ssao") && this->Has("sketch-8"))
  {
    this->WriteSketch(os);
  }
  if (this->Opt.Lights.size() >= 2)
  {
    this->WriteSlopes(os);
  }
  if (hasPlain && this->Opt.Scenes.size() >= 2)
  {
    this->WriteFlatness(os);
  }
}

void Report::WriteMedians(std::ostream& os) const
{
  const auto& cfgs = this->Opt.Configs;
  os << "\n### Median ms per frame\n\n";
  os << "| scene | triangles | lights |";
  for (const auto& c : cfgs)
  {
    os << " " << c << " |";
  }
  os << "\n| --- | ---: | ---: |";
  for (size_t i = 0; i < cfgs.size(); ++i)
  {
    os << " ---: |";
  }
  os << "\n";
  for (const auto& sc : this->Opt.Scenes)
  {
    for (int n : this->Opt.Lights)
    {
      os << "| " << SceneLabel(sc.Name) << " | " << FormatCount(this->Triangles(sc.Name)) << " | "
         << n << " |";
      for (const auto& c : cfgs)
      {
        os << " " << Fixed(this->MedianOf(sc.Name, n, c), 1) << " |";
      }
      os << "\n";
    }
  }
}

void Report::WriteRatios(std::ostream& os) const
{
  const auto& cfgs = this->Opt.Configs;
  os << "\n### Ratio to plain (same scene, same lights, same run)\n\n";
  os << "light-standard / plain compares our lighting pass with VTK's own equivalent "
        "(the same Phong model, VTK's generated per-light shader vs. our light buffer).\n\n";
  os << "| scene | lights |";
  for (const auto& c : cfgs)
  {
    if (c != "plain")
    {
      os << " " << c << " |";
    }
  }
  os << "\n| --- | ---: |";
  for (size_t i = 1; i < cfgs.size(); ++i)
  {
    os << " ---: |";
  }
  os << "\n";
  for (const auto& sc : this->Opt.Scenes)
  {
    for (int n : this->Opt.Lights)
    {
      const double plain = this->MedianOf(sc.Name, n, "plain");
      os << "| " << SceneLabel(sc.Name) << " | " << n << " |";
      for (const auto& c : cfgs)
      {
        if (c != "plain")
        {
          os << " " << Fixed(this->MedianOf(sc.Name, n, c) / plain, 2) << " |";
        }
      }
      os << "\n";
    }
  }
}

void Report::WriteSlopes(std::ostream& os) const
{
  os << "\n### Light-count slope (ms per light)\n\n";
  os << "Least-squares fit of median ms against light count (";
  for (size_t i = 0; i < this->Opt.Lights.size(); ++i)
  {
    os << (i ? ", " : "") << this->Opt.Lights[i];
  }
  os << " lights) per scene and configuration; the intercept is in parentheses.\n\n";
  os << "| configuration |";
  for (const auto& sc : this->Opt.Scenes)
  {
    os << " " << SceneLabel(sc.Name) << " |";
  }
  os << "\n| --- |";
  for (size_t i = 0; i < this->Opt.Scenes.size(); ++i)
  {
    os << " ---: |";
  }
  os << "\n";
  for (const auto& c : this->Opt.Configs)
  {
    os << "| " << c << " |";
    for (const auto& sc : this->Opt.Scenes)
    {
      double slope = NAN, intercept = NAN;
      this->Fit(sc.Name, c, slope, intercept);
      os << " " << Fixed(slope, 3) << " (" << Fixed(intercept, 1) << ") |";
    }
    os << "\n";
  }
}

void Report::WriteCsv(std::ostream& os) const
{
  os << "scene,triangles,lights,configuration,median_ms,min_ms,max_ms,frames\n";
  for (const auto& r : this->Results)
  {
    os << "sphere-" << r.Scene << "," << r.Triangles << "," << r.Lights << "," << r.Config << ","
       << Fixed(r.Median, 3) << "," << Fixed(r.Min, 3) << "," << Fixed(r.Max, 3) << "," << r.Frames
       << "\n";
  }
}

bool WriteReportFiles(const Options& opt, const Report& report, const std::string& md)
{
  bool ok = true;
  {
    std::ofstream csv(opt.Csv);
    report.WriteCsv(csv);
    csv.close();
    if (!csv)
    {
      std::cerr << "Could not write " << opt.Csv << "\n";
      ok = false;
    }
  }
  {
    std::ofstream out(opt.Markdown);
    out << md;
    out.close();
    if (!out)
    {
      std::cerr << "Could not write " << opt.Markdown << "\n";
      ok = false;
    }
  }
  return ok;
}
}
