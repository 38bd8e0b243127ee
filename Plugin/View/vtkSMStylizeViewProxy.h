/**
 * @class   vtkSMStylizeViewProxy
 * @brief   The client-side proxy of the VTK Stylize view (vtkPVStylizeView).
 *
 * ParaView's render-view proxy under its own class name, so that the view's definition names a
 * class (`<StylizeViewProxy>` in StylizeView.xml) that only a process with the plugin can make.
 * A client without the plugin, connected to a server that has it, then refuses to create the
 * view ("Creation of new proxy vtkSMStylizeViewProxy failed", and CreateView raises) instead of
 * aborting when its own process cannot make vtkPVStylizeView.
 *
 * A transparent-background screenshot (SaveScreenshot(..., TransparentBackground=1)) renders the
 * view over white and over black and makes transparent what differs. ParaView saves the
 * background properties first (SaveXMLState with a property iterator) and restores them after
 * (LoadXMLState): between the two, this proxy switches the view's FreezeBackground on, so that
 * the style draws the same ink in both renders, computed over the view's own background.
 *
 * A screenshot larger than the view (SaveScreenshot(..., ImageResolution=...) beyond ViewSize)
 * is rendered by ParaView in tiles, one view-sized render each. A style reads each pixel's
 * neighbours, which a tile does not have beyond its borders (IceT hands the style the tile's
 * image only): the tiles would join with seams. With a style on, this proxy renders such a
 * screenshot in one piece instead, the view resized to the full size with its PPI multiplied
 * by the magnification (text and scalar bars in proportion, as in ParaView's tiled capture),
 * then restored, when it is at most MaxOnePieceSide pixels a side and MaxOnePiecePixels in all;
 * otherwise it tiles as ParaView.
 *
 * A display's StylizeVolume (a property this plugin gives ParaView's representations with a
 * Volume type) leaves its volume to ParaView in every style: before each render (Update()) this
 * proxy lists the displays with StylizeVolume off in the view's internal PlainVolumeDisplays
 * property, pushed to every rank (vtkPVStylizeView::AddPlainVolumeDisplay()) when the list
 * changes.
 *
 * It behaves as vtkSMRenderViewProxy in every other way.
 */

#ifndef vtkSMStylizeViewProxy_h
#define vtkSMStylizeViewProxy_h

#include "vtkSMRenderViewProxy.h"
#include "vtkStylizeParaViewViewModule.h" // for export macro

class VTKSTYLIZEPARAVIEWVIEW_EXPORT vtkSMStylizeViewProxy : public vtkSMRenderViewProxy
{
public:
  static vtkSMStylizeViewProxy* New();
  vtkTypeMacro(vtkSMStylizeViewProxy, vtkSMRenderViewProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  using Superclass::SaveXMLState;
  /** As vtkSMProxy; before a transparent-background capture, also freezes the background. */
  vtkPVXMLElement* SaveXMLState(vtkPVXMLElement* root, vtkSMPropertyIterator* iter) override;
  /** As vtkSMProxy; after a transparent-background capture, also releases the background. */
  int LoadXMLState(vtkPVXMLElement* element, vtkSMProxyLocator* locator) override;

  /** As vtkSMViewProxy; first lists the volumes left to ParaView (PlainVolumeDisplays). */
  void Update() override;

  /** The largest side of a screenshot rendered in one piece, pixels. */
  static constexpr int MaxOnePieceSide = 8192;
  /** The most pixels of a screenshot rendered in one piece (8K UHD fits). */
  static constexpr double MaxOnePiecePixels = 7680.0 * 4320.0;

protected:
  vtkSMStylizeViewProxy() = default;

  /**
   * As vtkSMViewProxy; a magnified capture with a style on renders in one piece where the
   * window can hold it (see the class description).
   */
  vtkImageData* CaptureWindowInternal(int magnificationX, int magnificationY) override;
  ~vtkSMStylizeViewProxy() override = default;

  /** Sets the view's FreezeBackground and pushes it at once. */
  void PushFreezeBackground(bool freeze);

  bool BackgroundFrozen = false;

  /**
   * Sets the view's PlainVolumeDisplays to the shown displays whose StylizeVolume is 0, and
   * pushes it when that changed.
   */
  void UpdatePlainVolumes();

private:
  vtkSMStylizeViewProxy(const vtkSMStylizeViewProxy&) = delete;
  void operator=(const vtkSMStylizeViewProxy&) = delete;
};

#endif
