// Styles over an image (vtkStylizeStylePass with a delegate; vtkStylizeGBufferPass with a
// SceneImagePass), the path ParaView's IceT compositing takes: the G-buffer channels
// reconstructed from the image's depth against those rendered from the geometry, and each style
// over an image against the same style over the geometry.
#include "vtkCameraPass.h"
#include "vtkComicPass.h"
#include "vtkFloatArray.h"
#include "vtkPixelArtPass.h"
#include "vtkSketchPass.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeTestUtilities.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

using namespace stylizetest;

namespace
{
double Percentile(std::vector<double> v, double p)
{
  if (v.empty())
  {
    return -1.0;
  }
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(p * (v.size() - 1)));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

struct Channels
{
  vtkNew<vtkFloatArray> Normal;
  vtkNew<vtkFloatArray> Position;
  vtkNew<vtkFloatArray> LinearDepth;
};

void Download(vtkStylizeGBufferPass* gbuffer, Channels& c, const char* what)
{
  STYLIZE_CHECK(gbuffer->DownloadChannel(vtkStylizeGBufferPass::NORMAL_BUFFER, c.Normal) &&
      gbuffer->DownloadChannel(vtkStylizeGBufferPass::POSITION_BUFFER, c.Position) &&
      gbuffer->DownloadChannel(vtkStylizeGBufferPass::LINEAR_DEPTH_BUFFER, c.LinearDepth),
    "%s: channels missing", what);
  CheckFinite(c.Normal, std::string(what) + " normals");
  CheckFinite(c.Position, std::string(what) + " positions");
  CheckFinite(c.LinearDepth, std::string(what) + " linear depth");
}

// The channels from the image against the channels from the geometry.
void CompareChannels(bool parallel)
{
  const char* projection = parallel ? "parallel" : "perspective";
  TestScene scene = MakeTestScene(640, 480, parallel);
  vtkNew<vtkStylizeLightingPass> lighting;
  vtkNew<vtkStylizeGBufferPass> gbuffer;
  gbuffer->SetLightingPass(lighting);
  gbuffer->SetPrecision(vtkStylizeGBufferPass::FULL);
  gbuffer->SetChannels(vtkStylizeGBufferPass::NORMAL | vtkStylizeGBufferPass::POSITION |
    vtkStylizeGBufferPass::LINEAR_DEPTH);
  scene.Renderer->SetPass(gbuffer);
  scene.Window->Render();
  Channels geometry;
  Download(gbuffer, geometry, "geometry");
  vtkSmartPointer<vtkImageData> geometryImage = Capture(scene.Window);

  gbuffer->SetSceneImagePass(lighting); // lighting renders its delegate (vtkRenderStepsPass)
  scene.Window->Render();
  Channels image;
  Download(gbuffer, image, "image");
  vtkSmartPointer<vtkImageData> imageImage = Capture(scene.Window);

  // Angular error of the normals and relative error of the linear depth where both see a
  // surface; surfaces must agree pixel for pixel (the same rasterization).
  std::vector<double> angles;
  std::vector<double> depthErrors;
  vtkIdType onlyOne = 0;
  const vtkIdType n = geometry.Normal->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const float* a = geometry.Normal->GetPointer(4 * i);
    const float* b = image.Normal->GetPointer(4 * i);
    if ((a[3] > 0.5f) != (b[3] > 0.5f))
    {
      ++onlyOne;
      continue;
    }
    if (a[3] < 0.5f)
    {
      continue;
    }
    const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    STYLIZE_CHECK(std::abs(lb - 1.0) < 1e-3, "image normal not unit: %g", lb);
    const double c = std::max(-1.0, std::min(1.0, (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / lb));
    angles.push_back(std::acos(c) * 180.0 / M_PI);
    const double la = geometry.LinearDepth->GetValue(i);
    const double li = image.LinearDepth->GetValue(i);
    depthErrors.push_back(std::abs(la - li) / std::max(la, 1e-30));
  }
  const double median = Percentile(angles, 0.5);
  const double p90 = Percentile(angles, 0.9);
  const double depthMedian = Percentile(depthErrors, 0.5);
  const double depthMax = Percentile(depthErrors, 1.0);
  std::printf("%s: %zu surface pixels, %lld on one side only; normal error median %.3f deg, "
              "90th percentile %.3f deg; linear depth relative error median %.2e, max %.2e\n",
    projection, angles.size(), static_cast<long long>(onlyOne), median, p90, depthMedian, depthMax);
  STYLIZE_CHECK(angles.size() > 30000, "%s: too few surface pixels", projection);
  STYLIZE_CHECK(onlyOne == 0, "%s: coverage differs", projection);
  // Tolerances: the test objects are tessellated and shaded with interpolated normals, while the
  // depth only knows the facets: measured 2.45 deg at the median and 5.5 deg at the 90th
  // percentile (perspective; 2.35 and 5.2 parallel).
  STYLIZE_CHECK(median < 4.0, "%s: normal median %.3f deg >= 4", projection, median);
  STYLIZE_CHECK(p90 < 10.0, "%s: normal 90th percentile %.3f deg >= 10", projection, p90);
  STYLIZE_CHECK(depthMedian < 1e-5 && depthMax < 1e-3, "%s: linear depth differs", projection);
  // The colour comes through unchanged (the same lighting): strict equality up to rounding.
  StrictCompare(geometryImage, imageImage, 2, 0.001, 8, std::string(projection) + " colour");
}

// A style over the image (lit by the style's own lighting pass) against the style over the
// geometry: the same picture up to the normals' reconstruction.
template <class Pass>
void CompareStyle(const char* name, double minimumSSIM)
{
  TestScene scene = MakeTestScene(640, 480);
  vtkNew<Pass> style;
  scene.Renderer->SetPass(style);
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> geometry = Capture(scene.Window);

  vtkNew<vtkCameraPass> camera;
  camera->SetDelegatePass(style->GetLightingPass());
  style->SetDelegatePass(camera);
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> image = Capture(scene.Window);

  // The lit image alone (no style), to show that the style ran over the image.
  scene.Renderer->SetPass(camera);
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> lit = Capture(scene.Window);
  scene.Renderer->SetPass(nullptr);
  scene.Window->Render();

  const double ssim = vtkStylizeImageMetrics::SSIM(geometry, image, 255.0);
  const double litSSIM = vtkStylizeImageMetrics::SSIM(lit, image, 255.0);
  std::printf("%s: SSIM image vs geometry %.4f (limit %.2f); SSIM image vs lit scene %.4f\n", name,
    ssim, minimumSSIM, litSSIM);
  STYLIZE_CHECK(ssim >= minimumSSIM, "%s: SSIM %.4f below %.2f", name, ssim, minimumSSIM);
  STYLIZE_CHECK(litSSIM < ssim, "%s: the image looks like the unstylized scene", name);
  const double white[3] = { 1, 1, 1 };
  const vtkIdType ink = CountForeground(image, white);
  std::printf("%s: %lld pixels not white\n", name, static_cast<long long>(ink));
  STYLIZE_CHECK(ink > 10000, "%s: empty image", name);
}

// The image path at the extremes: scales 1e-6 and 1e6, near/far 1e7, both projections, a 1x1
// window, an empty scene. Every channel finite, every normal unit length, and each style
// leaves ink where there is a surface.
void Extremes()
{
  struct Case
  {
    const char* Name;
    int W, H;
    double Scale;
    bool Parallel;
    bool Empty;
    std::function<void(vtkRenderer*)> Adjust;
  };
  const std::vector<Case> cases = {
    { "scale 1e-6", 320, 240, 1e-6, false, false, nullptr },
    { "scale 1e6", 320, 240, 1e6, false, false, nullptr },
    { "scale 1e-6 parallel", 320, 240, 1e-6, true, false, nullptr },
    { "near/far 1e7", 320, 240, 1.0, false, false,
      [](vtkRenderer* r) { SetNearFarRatio(r, 1e-7); } },
    { "1x1 window", 1, 1, 1.0, false, false, nullptr },
    { "empty scene", 160, 120, 1.0, false, true, nullptr },
  };
  for (const Case& c : cases)
  {
    TestScene scene = MakeTestScene(c.W, c.H, c.Parallel, c.Scale);
    if (c.Empty)
    {
      scene.Renderer->RemoveAllViewProps();
    }
    if (c.Adjust)
    {
      c.Adjust(scene.Renderer);
    }
    vtkNew<vtkStylizeLightingPass> lighting;
    vtkNew<vtkStylizeGBufferPass> gbuffer;
    gbuffer->SetPrecision(vtkStylizeGBufferPass::FULL);
    gbuffer->SetPositionSpace(vtkStylizeGBufferPass::OBJECT);
    gbuffer->SetChannels(vtkStylizeGBufferPass::NORMAL | vtkStylizeGBufferPass::POSITION |
      vtkStylizeGBufferPass::LINEAR_DEPTH | vtkStylizeGBufferPass::DIRECTION);
    gbuffer->SetSceneImagePass(lighting);
    scene.Renderer->SetPass(gbuffer);
    scene.Window->Render();
    Channels image;
    Download(gbuffer, image, c.Name);
    vtkIdType surface = 0;
    for (vtkIdType i = 0; i < image.Normal->GetNumberOfTuples(); ++i)
    {
      const float* n = image.Normal->GetPointer(4 * i);
      if (n[3] > 0.5f)
      {
        ++surface;
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        STYLIZE_CHECK(std::abs(len - 1.0) < 1e-3, "%s: normal length %g", c.Name, len);
      }
    }
    std::printf(
      "%s: %lld surface pixels from the image\n", c.Name, static_cast<long long>(surface));
    STYLIZE_CHECK(c.Empty ? surface == 0 : surface > 0, "%s: surface pixels %lld", c.Name,
      static_cast<long long>(surface));
    scene.Renderer->SetPass(nullptr);

    // Each style over the image: ink where there is a surface.
    std::vector<vtkSmartPointer<vtkStylizeStylePass>> styles = {
      vtkSmartPointer<vtkComicPass>::New(), vtkSmartPointer<vtkPixelArtPass>::New(),
      vtkSmartPointer<vtkSketchPass>::New()
    };
    for (vtkStylizeStylePass* style : styles)
    {
      vtkNew<vtkCameraPass> camera;
      camera->SetDelegatePass(style->GetLightingPass());
      style->SetDelegatePass(camera);
      scene.Renderer->SetPass(style);
      scene.Window->Render();
      vtkSmartPointer<vtkImageData> shot = Capture(scene.Window);
      const double white[3] = { 1, 1, 1 };
      const vtkIdType ink = CountForeground(shot, white);
      if (!c.Empty && c.W > 1)
      {
        STYLIZE_CHECK(ink > 100, "%s: %s drew no ink", c.Name, style->GetClassName());
      }
      if (c.Empty)
      {
        STYLIZE_CHECK(ink == 0, "%s: %s drew %lld pixels on an empty scene", c.Name,
          style->GetClassName(), static_cast<long long>(ink));
      }
      scene.Renderer->SetPass(nullptr);
      style->ReleaseGraphicsResources(scene.Window);
    }
  }
}
}

int TestSceneImage(int, char*[])
{
  CompareChannels(false);
  CompareChannels(true);
  // Measured: comic 0.998, pixel art 1.000 (its default edges use no normals), sketch 0.942.
  CompareStyle<vtkComicPass>("comic", 0.95);
  CompareStyle<vtkPixelArtPass>("pixel art", 0.98);
  CompareStyle<vtkSketchPass>("sketch", 0.85);
  Extremes();
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
