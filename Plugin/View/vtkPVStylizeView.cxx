#include "vtkPVStylizeView.h"

#include "vtkAlgorithm.h"
#include "vtkBoundingBox.h"
#include "vtkCallbackCommand.h"
#include "vtkComicPass.h"
#include "vtkCompositeRepresentation.h"
#include "vtkContext2DScalarBarActor.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLineArtPass.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVDefaultPass.h"
#include "vtkPVLODVolume.h"
#include "vtkPVProgressHandler.h"
#include "vtkPVSession.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkPixelArtPass.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSketchPass.h"
#include "vtkStylizeAnimationEncoder.h"
#include "vtkStylizeFigureLayerSource.h"
#include "vtkStylizeFigureWriter.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeStylePass.h"
#include "vtkVolumeRepresentation.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkPVStylizeView);

/**
 * Where the view's vector figures get their layers (vtkStylizeFigureWriter::SetLayerSource()):
 * the style is the view's (ParaView keeps it in its synchronized renderers, not in the
 * renderer), and every frame renders as the view renders (StillRender: the ranks composited,
 * the style applied after compositing).
 */
class vtkPVStylizeViewFigureSource : public vtkStylizeFigureLayerSource
{
public:
  static vtkPVStylizeViewFigureSource* New();
  vtkTypeMacro(vtkPVStylizeViewFigureSource, vtkStylizeFigureLayerSource);
  vtkPVStylizeView* View = nullptr;

  vtkStylizeStylePass* FindStylePass() override { return this->View->GetActiveStylePass(); }

  vtkRenderer* FindStyleRenderer() override { return this->View->GetRenderer(); }

  void RenderFrame() override { this->View->StillRender(); }

  bool CaptureLayer(int layer, const double* key, int, vtkImageData* out) override
  {
    vtkPVStylizeView* view = this->View;
    vtkStylizeStylePass* style = view->GetActiveStylePass();
    if (!style)
    {
      return false;
    }
    double background[3];
    view->GetBackground(background);
    const int mode = view->ColorMode;
    const bool own = view->GetUseRenderViewSettingsForBackground();
    if (key)
    {
      view->SetUseRenderViewSettingsForBackground(false);
      view->SetBackgroundColorMode(vtkPVRenderView::DEFAULT);
      view->SetBackground(key[0], key[1], key[2]);
    }
    const int previous = style->SwapLayer(layer);
    view->StillRender();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(view->GetRenderWindow());
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->ShouldRerenderOff();
    grab->Update();
    out->DeepCopy(grab->GetOutput());
    style->SwapLayer(previous);
    if (key)
    {
      view->SetUseRenderViewSettingsForBackground(own);
      view->SetBackgroundColorMode(mode);
      view->SetBackground(background);
    }
    return out->GetNumberOfPoints() > 0;
  }

  // ParaView's colour legends paint themselves through vtkContext2D (their layout is not
  // vtkScalarBarActor's): painted into the figure's device, as vectors.
  bool PaintContextOverlay(vtkProp* actor, vtkViewport* viewport, vtkContext2D* painter) override
  {
    if (auto* bar = vtkContext2DScalarBarActor::SafeDownCast(actor))
    {
      if (!this->View->ShowsColorLegends())
      {
        return true; // (left out, as on the screen)
      }
      // only the first rank writes the figure (and lays the legend out: the others' legends
      // may never have rendered, and would paint with no viewport)
      vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
      if (!controller || controller->GetLocalProcessId() == 0)
      {
        bar->Paint(painter);
      }
      return true;
    }
    return this->Superclass::PaintContextOverlay(actor, viewport, painter);
  }

protected:
  vtkPVStylizeViewFigureSource() = default;
  ~vtkPVStylizeViewFigureSource() override = default;
};
vtkStandardNewMacro(vtkPVStylizeViewFigureSource);

//------------------------------------------------------------------------------
void vtkPVStylizeView::SetPatternsAnchored(int anchored)
{
  if (vtkStylizeStylePass* style = this->GetActiveStylePass())
  {
    if (anchored)
    {
      style->AnchorPatternsToSurface();
    }
    else
    {
      style->RestorePatternAnchors();
    }
  }
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::AddPlainVolumeDisplay(vtkPVDataRepresentation* display)
{
  if (display)
  {
    this->PlainVolumeDisplays.emplace_back(display);
  }
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::RemoveAllPlainVolumeDisplays()
{
  this->PlainVolumeDisplays.clear();
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::MarkPlainVolumes()
{
  vtkInformationIntegerKey* key = vtkStylizeStylePass::STYLIZE_VOLUME();
  std::vector<vtkWeakPointer<vtkVolumeRepresentation>> keyed;
  for (vtkPVDataRepresentation* display : this->PlainVolumeDisplays)
  {
    auto* composite = vtkCompositeRepresentation::SafeDownCast(display);
    auto* volume = vtkVolumeRepresentation::SafeDownCast(
      composite ? composite->GetActiveRepresentation() : display);
    vtkVolume* actor = volume ? volume->GetActor() : nullptr;
    if (!actor)
    {
      continue;
    }
    if (!actor->GetPropertyKeys())
    {
      vtkNew<vtkInformation> keys;
      actor->SetPropertyKeys(keys);
    }
    if (!actor->GetPropertyKeys()->Has(key) || actor->GetPropertyKeys()->Get(key) != 0)
    {
      actor->GetPropertyKeys()->Set(key, 0);
    }
    keyed.emplace_back(volume);
  }
  for (vtkVolumeRepresentation* volume : this->PlainVolumes)
  {
    vtkVolume* actor = volume ? volume->GetActor() : nullptr;
    if (actor && actor->GetPropertyKeys() &&
      std::find(keyed.begin(), keyed.end(), volume) == keyed.end())
    {
      actor->GetPropertyKeys()->Remove(key);
    }
  }
  this->PlainVolumes = std::move(keyed);
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::EncodeAnimation(const char* pattern, int fps, const char* output)
{
  this->FigureResult.clear();
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!output || !*output || (controller && controller->GetLocalProcessId() > 0))
  {
    return;
  }
  this->FigureResult = vtkStylizeAnimationEncoder::Encode(pattern, fps, output);
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::WriteFigure(const char* fileName)
{
  this->FigureResult.clear();
  if (!fileName || !*fileName)
  {
    return;
  }
  vtkNew<vtkPVStylizeViewFigureSource> source;
  source->View = this;
  source->SetRenderWindow(this->GetRenderWindow());
  vtkNew<vtkStylizeFigureWriter> writer;
  writer->SetLayerSource(source);
  writer->SetFileName(fileName);
  // Every rank renders the layers (compositing is collective); the first writes the file.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  writer->SetWriteToMemory(controller && controller->GetLocalProcessId() > 0);
  writer->Write();
  this->FigureResult = writer->GetErrorMessage();
  // the style's frame as it was
  this->StillRender();
}

//------------------------------------------------------------------------------
vtkPVStylizeView::vtkPVStylizeView()
{
  this->ComicPass = vtkSmartPointer<vtkComicPass>::New();
  this->PixelArtPass = vtkSmartPointer<vtkPixelArtPass>::New();
  this->SketchPass = vtkSmartPointer<vtkSketchPass>::New();
  this->LineArtPass = vtkSmartPointer<vtkLineArtPass>::New();
  this->LightingPass = vtkSmartPointer<vtkStylizeLightingPass>::New();
  // Per rank, the lighting pass renders what ParaView's default pass renders.
  this->LightingDelegate = vtkSmartPointer<vtkPVDefaultPass>::New();
  this->LightingPass->SetDelegatePass(this->LightingDelegate);
  // Per rank, under a style, the G-buffer: lit colour and depth for IceT, and the channels the
  // style reads (normals, positions, directions) kept for it.
  this->RankGBuffer = vtkSmartPointer<vtkStylizeGBufferPass>::New();
  this->RankGBuffer->SetLightingPass(this->LightingPass);
  this->RequestedFXAA = this->UseFXAA;
  this->ProgressReporter = vtkSmartPointer<vtkAlgorithm>::New();
}

//------------------------------------------------------------------------------
vtkPVStylizeView::~vtkPVStylizeView()
{
  this->RemoveAllPlainVolumeDisplays();
  this->MarkPlainVolumes(); // (takes the keys off)
  if (this->SynchronizedRenderers)
  {
    this->SynchronizedRenderers->SetImageProcessingPass(nullptr);
    this->SynchronizedRenderers->SetRenderPass(nullptr);
  }
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::SetComicPass(vtkComicPass* pass)
{
  this->ComicPass = pass ? pass : vtkSmartPointer<vtkComicPass>::New().GetPointer();
  this->Modified();
}

void vtkPVStylizeView::SetPixelArtPass(vtkPixelArtPass* pass)
{
  this->PixelArtPass = pass ? pass : vtkSmartPointer<vtkPixelArtPass>::New().GetPointer();
  this->Modified();
}

void vtkPVStylizeView::SetSketchPass(vtkSketchPass* pass)
{
  this->SketchPass = pass ? pass : vtkSmartPointer<vtkSketchPass>::New().GetPointer();
  this->Modified();
}

void vtkPVStylizeView::SetLineArtPass(vtkLineArtPass* pass)
{
  this->LineArtPass = pass ? pass : vtkSmartPointer<vtkLineArtPass>::New().GetPointer();
  this->Modified();
}

void vtkPVStylizeView::SetLightingPass(vtkStylizeLightingPass* pass)
{
  this->LightingPass = pass ? pass : vtkSmartPointer<vtkStylizeLightingPass>::New().GetPointer();
  this->LightingPass->SetDelegatePass(this->LightingDelegate);
  if (this->RankGBuffer)
  {
    this->RankGBuffer->SetLightingPass(this->LightingPass);
  }
  this->Modified();
}

vtkComicPass* vtkPVStylizeView::GetComicPass()
{
  return this->ComicPass;
}

vtkPixelArtPass* vtkPVStylizeView::GetPixelArtPass()
{
  return this->PixelArtPass;
}

vtkSketchPass* vtkPVStylizeView::GetSketchPass()
{
  return this->SketchPass;
}

vtkLineArtPass* vtkPVStylizeView::GetLineArtPass()
{
  return this->LineArtPass;
}

vtkStylizeLightingPass* vtkPVStylizeView::GetLightingPass()
{
  return this->LightingPass;
}

//------------------------------------------------------------------------------
vtkStylizeStylePass* vtkPVStylizeView::GetActiveStylePass()
{
  switch (this->Style)
  {
    case COMIC:
      return this->ComicPass;
    case PIXEL_ART:
      return this->PixelArtPass;
    case SKETCH:
      return this->SketchPass;
    case LINE_ART:
      return this->LineArtPass;
    default:
      return nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::SetUseFXAA(bool use)
{
  this->RequestedFXAA = use;
  this->Superclass::SetUseFXAA(use && this->Style == NONE);
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::SetBackgroundColorMode(int mode)
{
  this->Superclass::SetBackgroundColorMode(mode);
  this->ColorMode =
    std::min(std::max(mode, static_cast<int>(DEFAULT)), static_cast<int>(STEREO_SKYBOX));
}

//------------------------------------------------------------------------------
bool vtkPVStylizeView::GetFlatBackground(double rgb[3])
{
  this->UpdateBackground();
  vtkRenderer* ren = this->GetRenderer();
  if (!ren || ren->GetGradientBackground() || ren->GetTexturedBackground() ||
    this->ColorMode == vtkPVRenderView::SKYBOX || this->ColorMode == vtkPVRenderView::STEREO_SKYBOX)
  {
    return false;
  }
  ren->GetBackground(rgb);
  return true;
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::SetFreezeBackground(int freeze)
{
  if ((freeze != 0) == this->BackgroundFrozen)
  {
    return;
  }
  if (freeze)
  {
    this->FrozenFlat = this->GetFlatBackground(this->FrozenBackground);
  }
  this->BackgroundFrozen = freeze != 0;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::ReleasePassResources(vtkStylizeStylePass* keep)
{
  vtkRenderWindow* window = this->GetRenderWindow();
  if (!window)
  {
    return;
  }
  for (vtkStylizeStylePass* pass : { static_cast<vtkStylizeStylePass*>(this->ComicPass),
         static_cast<vtkStylizeStylePass*>(this->PixelArtPass),
         static_cast<vtkStylizeStylePass*>(this->SketchPass),
         static_cast<vtkStylizeStylePass*>(this->LineArtPass) })
  {
    if (pass && pass != keep)
    {
      pass->ReleaseGraphicsResources(window);
    }
  }
  if (!keep && this->LightingPass)
  {
    this->LightingPass->ReleaseGraphicsResources(window);
  }
  if (!keep && this->RankGBuffer)
  {
    this->RankGBuffer->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::ConfigurePasses()
{
  vtkStylizeStylePass* style = this->GetActiveStylePass();
  if (style != this->LastStylePass)
  {
    // A style that is switched off gives its textures back.
    this->ReleasePassResources(style);
    this->LastStylePass = style;
  }
  int model = this->LightingModel;
  if (this->LightingModel == STYLE_DEFAULT)
  {
    model = this->Style == COMIC ? vtkStylizeLightingPass::COMIC
                                 : (this->Style == PIXEL_ART ? vtkStylizeLightingPass::PIXEL_ART
                                                             : vtkStylizeLightingPass::STANDARD);
  }
  this->LightingPass->SetModel(model);
  // The style's colours (black and white, the data's hues, neutral lights) on each rank too.
  if (style)
  {
    style->ConfigureLightingColors(this->LightingPass);
  }
  else
  {
    this->LightingPass->SetColorMode(vtkStylizeLightingPass::LIT_COLORS);
  }
  const bool lighting = style || this->LightingModel != STYLE_DEFAULT;
  this->Superclass::SetUseFXAA(this->RequestedFXAA && !style);
  // Per rank: under a style the G-buffer (lit by the lighting pass), otherwise the lighting
  // pass alone or ParaView's own pass.
  this->RankGBuffer->SetDrawTranslucent(true);
  vtkRenderPass* rankPass = style ? static_cast<vtkRenderPass*>(this->RankGBuffer)
                                  : (lighting ? this->LightingPass.GetPointer() : nullptr);
  this->SynchronizedRenderers->SetRenderPass(rankPass);
  // A style needs the composited depth (IceT pastes it back only when asked); ParaView's own
  // frames do not ask (with ordered compositing, which carries no depth, IceT reports an error).
  this->SynchronizedRenderers->SetUseDepthBuffer(style != nullptr);
  if (style)
  {
    // After compositing, the style takes the ranks' own normals, positions and directions
    // (composited by depth across the ranks) instead of rebuilding them from the depth.
    style->GetGBufferPass()->SetChannelSource(this->RankGBuffer);
    vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
    style->GetGBufferPass()->SetController(controller);
    // Translucent surfaces: the style renders them itself from the props, one layer at a time
    // (the rank's pass leaves them out of the image); with several ranks each renders the layer
    // of its own props and the style composites the layers by depth across the ranks.
    this->RankGBuffer->SetDrawTranslucent(style->GetTranslucentLayers() == 0);
    const bool severalRanks = controller && controller->GetNumberOfProcesses() > 1;
    // Annotations (the data axes grid, 3D text) drawn plain over the style's picture: each rank's
    // G-buffer leaves them out of the composited picture and the style draws rank 0's over it
    // (ParaView gives every rank's grid the whole data's bounds).
    this->RankGBuffer->SetLeaveOutAnnotations(style->GetPlainAnnotations());
    // Volumes the style leaves to ParaView (StylizeVolumes off, a display's StylizeVolume off):
    // the style draws them over its picture, as in VTK (on several ranks each rank's pieces,
    // composited in visibility order: depth compositing would keep none of them).
    this->RankGBuffer->SetLeaveOutVolumes(true);
    if (severalRanks && style->GetTranslucentLayers() == 0 && this->DataNeedsOrderedCompositing &&
      !this->WarnedUnlayered)
    {
      // The ranks are composited by depth, which keeps only what wrote a depth.
      vtkWarningMacro("On several ranks a style with TranslucentLayers 0 leaves translucent "
                      "surfaces out of the picture; set TranslucentLayers above 0.");
      this->WarnedUnlayered = true;
    }
    // ParaView renders over transparent black where it composites (several ranks, or a server
    // rendering for its client) and paints the view's background under the result afterwards:
    // the style is told which flat background that will be (a gradient, an image or a skybox
    // leaves the image's own colour).
    // While a transparent-background screenshot renders, the background frozen before it.
    double background[3];
    const bool flat =
      this->BackgroundFrozen ? this->FrozenFlat : this->GetFlatBackground(background);
    style->GetGBufferPass()->SetUseImageBackground(flat);
    if (flat)
    {
      style->GetGBufferPass()->SetImageBackground(
        this->BackgroundFrozen ? this->FrozenBackground : background);
    }
  }
  for (vtkStylizeStylePass* pass : { static_cast<vtkStylizeStylePass*>(this->ComicPass),
         static_cast<vtkStylizeStylePass*>(this->PixelArtPass),
         static_cast<vtkStylizeStylePass*>(this->SketchPass),
         static_cast<vtkStylizeStylePass*>(this->LineArtPass) })
  {
    pass->SetWindowScale(this->WindowScale[0], this->WindowScale[1]);
  }
  this->SynchronizedRenderers->SetImageProcessingPass(style);
  // The sketch's object scale counts the data of all ranks (the style runs on the composited
  // image, where a rank's own props would give another scale on every rank count).
  double bounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  if (this->GeometryBounds.IsValid())
  {
    this->GeometryBounds.GetBounds(bounds);
  }
  this->SketchPass->SetSceneBounds(bounds);
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::Update()
{
  this->Superclass::Update();
  this->DataNeedsOrderedCompositing = this->NeedsOrderedCompositing;
}

//------------------------------------------------------------------------------
bool vtkPVStylizeView::ShowsColorLegends()
{
  vtkStylizeStylePass* style = this->GetActiveStylePass();
  return !style || style == this->PixelArtPass.GetPointer() || style->GetTinted();
}

//------------------------------------------------------------------------------
std::vector<vtkProp*> vtkPVStylizeView::HideColorLegends()
{
  std::vector<vtkProp*> hidden;
  for (vtkRenderer* ren : { this->GetRenderer(), this->GetNonCompositedRenderer() })
  {
    if (!ren)
    {
      continue;
    }
    // (a legend is a widget representation among the view's props: its actors are 2D)
    vtkNew<vtkPropCollection> actors;
    vtkPropCollection* props = ren->GetViewProps();
    vtkCollectionSimpleIterator it;
    vtkProp* prop;
    for (props->InitTraversal(it); (prop = props->GetNextProp(it));)
    {
      if (prop->GetVisibility())
      {
        prop->GetActors2D(actors);
      }
    }
    for (actors->InitTraversal(it); (prop = actors->GetNextProp(it));)
    {
      if (prop->GetVisibility() && prop->IsA("vtkScalarBarActor"))
      {
        prop->SetVisibility(0);
        hidden.push_back(prop);
      }
    }
  }
  return hidden;
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::Render(bool interactive, bool skip_rendering)
{
  this->ConfigurePasses();
  this->MarkPlainVolumes();
  // Ordered compositing (what ParaView does on several ranks for translucent geometry and
  // volumes) blends the ranks' images without their depth, and a style needs the composited
  // depth: under a style the ranks are composited by depth, translucent surfaces by the style's
  // layers.
  this->NeedsOrderedCompositing = this->DataNeedsOrderedCompositing && !this->GetActiveStylePass();
  const std::vector<vtkProp*> hidden =
    this->ShowsColorLegends() ? std::vector<vtkProp*>() : this->HideColorLegends();
  vtkStylizeStylePass* style = this->GetActiveStylePass();
  const unsigned long tag = style ? this->ReportProgressOf(style) : 0;
  this->Superclass::Render(interactive, skip_rendering);
  if (style)
  {
    style->RemoveObserver(tag);
  }
  for (vtkProp* prop : hidden)
  {
    prop->SetVisibility(1);
  }
}

//------------------------------------------------------------------------------
unsigned long vtkPVStylizeView::ReportProgressOf(vtkStylizeStylePass* style)
{
  // ParaView's progress bar follows the algorithms registered with the session's progress
  // handler (only algorithms): the style's progress is the reporter's. Only frames that do
  // work report: a frame that keeps its lines sends 1 alone, which is not passed on.
  if (!this->ProgressRegistered)
  {
    vtkPVSession* session = this->GetSession();
    if (session && session->GetProgressHandler())
    {
      this->ProgressReporter->SetProgressText("Stylize: finding the lines");
      session->GetProgressHandler()->RegisterProgressEvent(this->ProgressReporter, 0);
      this->ProgressRegistered = true;
    }
  }
  if (!this->ProgressForward)
  {
    auto forward = vtkSmartPointer<vtkCallbackCommand>::New();
    forward->SetClientData(this);
    forward->SetCallback(
      [](vtkObject*, unsigned long, void* self, void* data)
      {
        auto* view = static_cast<vtkPVStylizeView*>(self);
        const double fraction = *static_cast<double*>(data);
        if (fraction < 1.0 || view->ProgressReported)
        {
          view->ProgressReporter->UpdateProgress(std::max(0.0, std::min(fraction, 1.0)));
        }
        view->ProgressReported = fraction < 1.0;
      });
    this->ProgressForward = forward;
  }
  this->ProgressReported = false;
  return style->AddObserver(vtkCommand::ProgressEvent, this->ProgressForward);
}

//------------------------------------------------------------------------------
void vtkPVStylizeView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const names[] = { "None", "Comic", "Pixel art", "Sketch", "Line art" };
  os << indent << "Style: " << names[this->Style] << "\n";
  os << indent << "LightingModel: " << this->LightingModel << "\n";
  os << indent << "RequestedFXAA: " << this->RequestedFXAA << "\n";
}
