// Test driver: `vtkStylizeCxxTests NAME [args]` runs one test function.
#include <cstdio>
#include <cstring>

int TestLightingRegression(int argc, char* argv[]);
int TestStandardMatchesVTK(int argc, char* argv[]);
int TestLightCountNoRebuild(int argc, char* argv[]);
int TestLightingReference(int argc, char* argv[]);
int TestLightingExtremes(int argc, char* argv[]);
int TestLightingModelSwitch(int argc, char* argv[]);
int TestGBuffer(int argc, char* argv[]);
int TestSceneImage(int argc, char* argv[]);
int TestRankCompositor(int argc, char* argv[]);
int TestComicRegression(int argc, char* argv[]);
int TestComicScale(int argc, char* argv[]);
int TestComicMagnify(int argc, char* argv[]);
int TestComicExtremes(int argc, char* argv[]);
int TestComicMotion(int argc, char* argv[]);
int TestComicTone(int argc, char* argv[]);
int TestComicHatchOrientation(int argc, char* argv[]);
int TestComicEdgeAccuracy(int argc, char* argv[]);
int TestPixelArtRegression(int argc, char* argv[]);
int TestPixelArtDither(int argc, char* argv[]);
int TestPixelArtCanny(int argc, char* argv[]);
int TestPixelArtStability(int argc, char* argv[]);
int TestPixelArtFidelity(int argc, char* argv[]);
int TestPixelArtMagnify(int argc, char* argv[]);
int TestPixelArtExtremes(int argc, char* argv[]);
int TestPrincipalCurvatures(int argc, char* argv[]);
int TestSketchRegression(int argc, char* argv[]);
int TestSketchNoise(int argc, char* argv[]);
int TestSketchExtremes(int argc, char* argv[]);
int TestSketchCylinders(int argc, char* argv[]);

namespace
{
struct Entry
{
  const char* Name;
  int (*Function)(int, char*[]);
};
const Entry Tests[] = {
  { "TestLightingRegression", TestLightingRegression },
  { "TestStandardMatchesVTK", TestStandardMatchesVTK },
  { "TestLightCountNoRebuild", TestLightCountNoRebuild },
  { "TestLightingReference", TestLightingReference },
  { "TestLightingExtremes", TestLightingExtremes },
  { "TestLightingModelSwitch", TestLightingModelSwitch },
  { "TestGBuffer", TestGBuffer },
  { "TestSceneImage", TestSceneImage },
  { "TestRankCompositor", TestRankCompositor },
  { "TestComicRegression", TestComicRegression },
  { "TestComicScale", TestComicScale },
  { "TestComicMagnify", TestComicMagnify },
  { "TestComicExtremes", TestComicExtremes },
  { "TestComicMotion", TestComicMotion },
  { "TestComicTone", TestComicTone },
  { "TestComicHatchOrientation", TestComicHatchOrientation },
  { "TestComicEdgeAccuracy", TestComicEdgeAccuracy },
  { "TestPixelArtRegression", TestPixelArtRegression },
  { "TestPixelArtDither", TestPixelArtDither },
  { "TestPixelArtCanny", TestPixelArtCanny },
  { "TestPixelArtStability", TestPixelArtStability },
  { "TestPixelArtFidelity", TestPixelArtFidelity },
  { "TestPixelArtMagnify", TestPixelArtMagnify },
  { "TestPixelArtExtremes", TestPixelArtExtremes },
  { "TestPrincipalCurvatures", TestPrincipalCurvatures },
  { "TestSketchRegression", TestSketchRegression },
  { "TestSketchNoise", TestSketchNoise },
  { "TestSketchExtremes", TestSketchExtremes },
  { "TestSketchCylinders", TestSketchCylinders },
};
}

int main(int argc, char* argv[])
{
  if (argc >= 2)
  {
    for (const Entry& e : Tests)
    {
      if (std::strcmp(argv[1], e.Name) == 0)
      {
        return e.Function(argc - 1, argv + 1);
      }
    }
  }
  std::fprintf(stderr, "usage: %s TEST [args]; tests:", argv[0]);
  for (const Entry& e : Tests)
  {
    std::fprintf(stderr, " %s", e.Name);
  }
  std::fprintf(stderr, "\n");
  return 2;
}
