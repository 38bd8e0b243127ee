/**
 * vtkStylizeBenchmark: what a run prints and writes. The Markdown report (the run's header,
 * median ms, ratios to plain, issue 15's targets, the styles' added costs, light-count slopes,
 * flatness in triangle count, per-stage costs) and the CSV with one row per case. The tables
 * of added cost over plain are defined in vtkStylizeBenchmarkReportCosts.cxx, the rest in
 * vtkStylizeBenchmarkReport.cxx.
 */
#ifndef vtkStylizeBenchmarkReport_h
#define vtkStylizeBenchmarkReport_h

#include "vtkStylizeBenchmarkOptions.h"
#include "vtkStylizeBenchmarkTypes.h"

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace vtkstylizebenchmark
{
/** @p v with @p digits decimals, "n/a" when not finite. */
std::string Fixed(double v, int digits);

/** @p n with thousands separators: 1,000,000. */
std::string FormatCount(vtkIdType n);

/** How a scene is named in the reports: "sphere 10k", "bunny (scan)", "iso970k (isosurface)". */
std::string SceneLabel(const std::string& name);

/** Sorts @p results into report order: scene, light count, configuration (as in @p opt). */
void SortResults(const Options& opt, std::vector<Result>& results);

/** What the report's header says about the run beside the options. */
struct RunInfo
{
  std::string Renderer;                            // GL_RENDERER
  std::string GLVersion;                           // GL_VERSION
  double CoveredPixels = 0.0;                      // pixels the unit sphere covers (Framing)
  double Seconds = 0.0;                            // the run's wall-clock time
  std::map<std::string, std::string> Descriptions; // configuration -> its passes in words
};

/** The Markdown header: renderer, size and frames, scenes, lights, configurations, run time. */
std::string ReportHeader(const Options& opt, const RunInfo& info);

/** The per-stage cost table of the styles; nothing when @p stages is empty. */
void WriteStageTable(std::ostream& os, const std::vector<StageResult>& stages);

/** The tables of median frame times and what is derived from them, and the CSV. */
class Report
{
public:
  Report(const Options& opt, std::vector<Result> results);

  /** @p header, then every table the options' scenes, lights and configurations allow. */
  void Write(std::ostream& os, const std::string& header) const;

  void WriteCsv(std::ostream& os) const;

private:
  const Result* Find(const std::string& scene, int lights, const std::string& config) const;
  double MedianOf(const std::string& scene, int lights, const std::string& config) const;
  vtkIdType Triangles(const std::string& scene) const;
  bool Has(const std::string& config) const;
  void Fit(
    const std::string& scene, const std::string& config, double& slope, double& intercept) const;
  std::string TargetRatio(
    const std::string& scene, int n, const char* a, const char* b, bool added) const;

  void WriteMedians(std::ostream& os) const;
  void WriteRatios(std::ostream& os) const;
  void WriteTargets(std::ostream& os) const;
  void WriteComic(std::ostream& os) const;
  void WritePixelTarget(std::ostream& os) const;
  void WriteSketch(std::ostream& os) const;
  void WriteSlopes(std::ostream& os) const;
  void WriteFlatness(std::ostream& os) const;

  const Options& Opt;
  std::vector<Result> Results;
  std::map<std::string, const Result*> Index;
  std::map<std::string, vtkIdType> TriangleCount;
};

/**
 * Writes the CSV and the Markdown text @p md to the options' files. False (and a line on
 * stderr for each) when one could not be written.
 */
bool WriteReportFiles(const Options& opt, const Report& report, const std::string& md);
}

#endif
