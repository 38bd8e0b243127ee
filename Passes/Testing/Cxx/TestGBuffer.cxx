// The shared G-buffer: only requested channels are allocated; depth is written back so that
// translucent geometry composites correctly; 2D actors stay crisp; renderers off the window
// origin, several renderers, layered renderers, resizing and tiled (magnified) screenshots work;
// ReleaseGraphicsResources frees everything; destroying the window prints nothing.
#include "vtkConeSource.h"
#include "vtkFloatArray.h"
#include "vtkLineSource.h"
#include "vtkOutputWindow.h"
#include "vtkPlaneSource.h"
#include "vtkRenderStepsPass.h"
#include "vtkStringOutputWindow.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeTestUtilities.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTextureObject.h"

#include <cstdlib>

using namespace stylizetest;

namespace
{
void AddTranslucentAndText(vtkRenderer* ren)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-3, -1.5, 0.2);
  plane->SetPoint1(3, -1.5, 0.2);
  plane->SetPoint2(-3, 1.5, 0.4);
  vtkNew<vtkPolyDataMapper> pm;
  pm->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> pa;
  pa->SetMapper(pm);
  pa->GetProperty()->SetColor(0.2, 0.5, 1.0);
  pa->GetProperty()->SetOpacity(0.5);
  ren->AddActor(pa);
  vtkNew<vtkTextActor> text;
  text->SetInput("G-buffer 2D text");
  text->GetTextProperty()->SetFontSize(18);
  text->GetTextProperty()->SetColor(1, 1, 0);
  text->SetPosition(8, 8);
  ren->AddActor2D(text);
}

enum Mode
{
  PLAIN,   // VTK's default rendering
  GBUFFER, // vtkStylizeGBufferPass with the Standard lighting model
};

void Configure(vtkRenderer* ren, Mode mode)
{
  if (mode == GBUFFER)
  {
    vtkNew<vtkStylizeLightingPass> lighting;
    vtkNew<vtkStylizeGBufferPass> gbuffer;
    gbuffer->SetLightingPass(lighting);
    gbuffer->SetChannels(vtkStylizeGBufferPass::NORMAL);
    ren->SetPass(gbuffer);
  }
}

vtkSmartPointer<vtkImageData> TranslucentScene(Mode mode)
{
  auto win = MakeWindow(300, 200);
  vtkNew<vtkRenderer> ren;
  win->AddRenderer(ren);
  ren->SetBackground(0.1, 0.1, 0.15);
  AddTestActors(ren);
  AddTranslucentAndText(ren);
  PlaceCamera(ren, 1.0, 0, 15, 12.0);
  Configure(ren, mode);
  win->Render();
  auto img = Capture(win);
  win->Finalize();
  return img;
}

vtkSmartPointer<vtkImageData> TwoViewports(
  Mode mode, bool layered, int resizeTo[2] = nullptr, int magnification = 1)
{
  auto win = MakeWindow(320, 200);
  vtkNew<vtkRenderer> left, right;
  win->AddRenderer(left);
  win->AddRenderer(right);
  left->SetBackground(0.2, 0.1, 0.1);
  right->SetBackground(0.1, 0.2, 0.1);
  AddTestActors(left);
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(40);
  vtkNew<vtkPolyDataMapper> cm;
  cm->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> ca;
  ca->SetMapper(cm);
  ca->GetProperty()->SetColor(0.4, 0.8, 1.0);
  right->AddActor(ca);
  if (layered)
  {
    // A full-window overlay layer with its own geometry above the first renderer.
    win->SetNumberOfLayers(2);
    left->SetViewport(0, 0, 1, 1);
    right->SetViewport(0, 0, 1, 1);
    right->SetLayer(1);
  }
  else
  {
    left->SetViewport(0, 0, 0.55, 1);
    right->SetViewport(0.55, 0.2, 1, 0.9);
  }
  PlaceCamera(left, 1.0, 0, 0, 16.0);
  PlaceCamera(right, 1.0, 40, 0, 3.7, 0.0);
  Configure(left, mode);
  Configure(right, mode);
  win->Render();
  if (resizeTo)
  {
    win->SetSize(resizeTo[0], resizeTo[1]);
    win->Render();
  }
  auto img = Capture(win, magnification);
  win->Finalize();
  return img;
}

// LINEAR_DEPTH: positive on surfaces, 0 on the background, -1 on lines and points (no surface
// normal), which the styles draw as lines (docs/gbuffer.md); lines keep their width in points
// in a tiled screenshot.
void CheckLineMarker()
{
  auto win = MakeWindow(160, 120);
  vtkNew<vtkRenderer> ren;
  win->AddRenderer(ren);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(0, -1, 0);
  plane->SetPoint2(-1, 1, 0);
  vtkNew<vtkLineSource> line; // in front of the plane, across it and the background
  line->SetPoint1(-1.5, 0, 0.5);
  line->SetPoint2(1.5, 0.3, 0.5);
  for (vtkPolyDataAlgorithm* source :
    { static_cast<vtkPolyDataAlgorithm*>(plane), static_cast<vtkPolyDataAlgorithm*>(line) })
  {
    vtkNew<vtkPolyDataMapper> m;
    m->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkActor> a;
    a->SetMapper(m);
    a->GetProperty()->SetLineWidth(3);
    a->GetProperty()->SetColor(0.1, 0.1, 0.4);
    ren->AddActor(a);
  }
  ren->ResetCamera();
  vtkNew<vtkStylizeLightingPass> lighting;
  vtkNew<vtkStylizeGBufferPass> gbuffer;
  gbuffer->SetLightingPass(lighting);
  gbuffer->SetChannels(vtkStylizeGBufferPass::LINEAR_DEPTH);
  ren->SetPass(gbuffer);
  win->Render();
  vtkNew<vtkFloatArray> depth;
  STYLIZE_CHECK(
    gbuffer->DownloadChannel(vtkStylizeGBufferPass::LINEAR_DEPTH_BUFFER, depth), "linear depth");
  int lines = 0, surfaces = 0, background = 0, other = 0;
  for (vtkIdType i = 0; i < depth->GetNumberOfValues(); ++i)
  {
    const float z = depth->GetValue(i);
    (z == -1.0f ? lines : (z > 0.0f ? surfaces : (z == 0.0f ? background : other)))++;
  }
  std::printf("linear depth: %d line, %d surface, %d background, %d other pixels\n", lines,
    surfaces, background, other);
  STYLIZE_CHECK(lines > 200 && surfaces > 1000 && background > 1000 && other == 0,
    "lines must be -1, surfaces positive, the background 0");
  // Lines at their width in points: a 3x tiled screenshot draws the 3 px line 9 px wide (VTK
  // keeps 3 px in each tile).
  ren->SetBackground(1, 1, 1);
  int widths[2] = { 0, 0 };
  for (int k : { 1, 3 })
  {
    auto img = Capture(win, k);
    const int* d = img->GetDimensions();
    const int x = d[0] * 3 / 4; // right of the plane: the line over the background
    for (int y = 0; y < d[1]; ++y)
    {
      const auto* c = static_cast<unsigned char*>(img->GetScalarPointer(x, y, 0));
      widths[k / 3] += (c[0] + c[1] + c[2] < 600) ? 1 : 0;
    }
  }
  std::printf("line width: %d px in the window, %d px in a 3x screenshot\n", widths[0], widths[1]);
  STYLIZE_CHECK(widths[0] >= 2 && std::abs(widths[1] - 3 * widths[0]) <= 2,
    "a 3x screenshot draws lines %d px wide, %d in the window", widths[1], widths[0]);
  win->Finalize();
}
}

int TestGBuffer(int, char*[])
{
  CheckLineMarker();
  // Translucent geometry over the composited depth, and 2D text, equal to VTK's rendering.
  StrictCompare(
    TranslucentScene(GBUFFER), TranslucentScene(PLAIN), 2, 0.0, 2, "translucent plane and 2D text");
  // Renderers off the window origin, several renderers.
  {
    auto g = TwoViewports(GBUFFER, false);
    auto p = TwoViewports(PLAIN, false);
    if (!StrictCompare(g, p, 2, 0.0, 2, "two renderers, one off the origin"))
    {
      WritePNG(g, "gbuffer-two-renderers.png");
      WritePNG(p, "plain-two-renderers.png");
    }
  }
  // Layered renderers: the upper layer's background stays transparent.
  StrictCompare(
    TwoViewports(GBUFFER, true), TwoViewports(PLAIN, true), 2, 0.0, 2, "layered renderers");
  // Resizing between frames.
  int size[2] = { 210, 260 };
  StrictCompare(TwoViewports(GBUFFER, false, size), TwoViewports(PLAIN, false, size), 2, 0.0, 2,
    "resized window");
  // Tiled rendering (vtkWindowToImageFilter magnification 3): no seams.
  StrictCompare(TwoViewports(GBUFFER, false, nullptr, 3), TwoViewports(PLAIN, false, nullptr, 3), 2,
    0.0, 2, "magnified x3 (tiled)");

  // Only the requested channels are allocated; ReleaseGraphicsResources frees everything;
  // destroying the window prints no error.
  vtkNew<vtkStringOutputWindow> messages;
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkOutputWindow::SetInstance(messages);
  {
    auto win = MakeWindow(160, 120);
    vtkNew<vtkRenderer> ren;
    win->AddRenderer(ren);
    AddTestActors(ren);
    PlaceCamera(ren);
    vtkNew<vtkStylizeLightingPass> lighting;
    vtkNew<vtkStylizeGBufferPass> gbuffer;
    gbuffer->SetLightingPass(lighting);
    ren->SetPass(gbuffer);
    win->Render();
    STYLIZE_CHECK(gbuffer->GetColorTexture() && gbuffer->GetDepthTexture(), "colour/depth missing");
    STYLIZE_CHECK(!gbuffer->GetNormalTexture() && !gbuffer->GetPositionTexture(),
      "channels allocated that nobody asked for");
    gbuffer->SetChannels(vtkStylizeGBufferPass::NORMAL);
    win->Render();
    STYLIZE_CHECK(
      gbuffer->GetNormalTexture() && !gbuffer->GetPositionTexture(), "NORMAL only: wrong channels");
    gbuffer->SetChannels(vtkStylizeGBufferPass::POSITION);
    win->Render();
    STYLIZE_CHECK(!gbuffer->GetNormalTexture() && gbuffer->GetPositionTexture(),
      "POSITION only: wrong channels");
    vtkNew<vtkFloatArray> pos;
    STYLIZE_CHECK(
      gbuffer->DownloadChannel(vtkStylizeGBufferPass::POSITION_BUFFER, pos), "position download");
    STYLIZE_CHECK(!gbuffer->DownloadChannel(vtkStylizeGBufferPass::NORMAL_BUFFER, pos),
      "a normal download succeeded without a normal channel");
    gbuffer->ReleaseGraphicsResources(win);
    STYLIZE_CHECK(
      !gbuffer->GetColorTexture() && !gbuffer->GetDepthTexture() && !gbuffer->GetPositionTexture(),
      "ReleaseGraphicsResources left textures");
    win->Render(); // works again after a release
    STYLIZE_CHECK(gbuffer->GetColorTexture() != nullptr, "no render after release");
    // Object-space positions: independent of the camera.
    gbuffer->SetPositionSpace(vtkStylizeGBufferPass::OBJECT);
    win->Render();
    win->Finalize();
  }
  {
    // The pass outliving its window, and a window destroyed without Finalize.
    vtkNew<vtkStylizeGBufferPass> gbuffer;
    vtkNew<vtkStylizeLightingPass> lighting;
    gbuffer->SetLightingPass(lighting);
    gbuffer->SetChannels(3);
    {
      auto win = MakeWindow(100, 80);
      vtkNew<vtkRenderer> ren;
      win->AddRenderer(ren);
      AddTestActors(ren);
      PlaceCamera(ren);
      ren->SetPass(gbuffer);
      win->Render();
    }
  }
  vtkOutputWindow::SetInstance(previous);
  std::printf(
    "messages printed while releasing and destroying: \"%s\"\n", messages->GetOutput().c_str());
  STYLIZE_CHECK(messages->GetOutput().empty(), "messages: %s", messages->GetOutput().c_str());
  return stylizetest::Failures == 0 ? 0 : 1;
}
