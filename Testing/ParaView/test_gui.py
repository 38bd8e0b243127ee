"""paraview.gui: the VTK Stylize plugin in the ParaView GUI (run by run_gui.sh, not directly).

    paraview-stylize --dr --script=test_gui.py --test-script=EVENTS.xml --exit

with STYLIZE_GUI_OUT naming the output folder. As the GUI's startup script it replaces the
layout's render view by a Render View (Stylize), shows a contour of the Wavelet source as a
Stylized Surface, sets Style to Comic and checks, in the GUI session, the Style property and
its entries, a few of the exposed pass settings, that 'Stylized Surface' is offered for the
display, and that the comic image differs from the style None's. It saves the view as
gui-comic.png and writes gui-result.txt: "PASS" or the failed checks (run_gui.sh fails the test
unless the file says PASS). Then run_gui.sh's QtTesting events check the properties panel's
widgets, use File > Export Stylized Figure... and File > Save Stylized Orbit... (ParaView's file
dialog, the orbit's option dialog) and call check_exports() and capture_window() (below): the
files those entries wrote, and the whole window saved as gui-window.png.
"""
import ctypes
import ctypes.util
import os
import re
import struct
import subprocess
import xml.etree.ElementTree as ElementTree
import zlib

from paraview.simple import *  # noqa: F401,F403
from stylize_pv_scene import check, failures, pixels  # on PYTHONPATH through run_gui.sh

out = os.environ.get("STYLIZE_GUI_OUT", os.getcwd())
os.makedirs(out, exist_ok=True)
result = os.path.join(out, "gui-result.txt")


def write_png(path, width, height, rgb):
    """An 8-bit RGB PNG from rows of packed RGB bytes, top row first."""
    stride = 3 * width
    raw = b"".join(b"\0" + bytes(rgb[y * stride:(y + 1) * stride]) for y in range(height))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0,
                                                                   0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


class _XImage(ctypes.Structure):
    _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("xoffset", ctypes.c_int),
                ("format", ctypes.c_int), ("data", ctypes.c_void_p), ("byte_order", ctypes.c_int),
                ("bitmap_unit", ctypes.c_int), ("bitmap_bit_order", ctypes.c_int),
                ("bitmap_pad", ctypes.c_int), ("depth", ctypes.c_int),
                ("bytes_per_line", ctypes.c_int), ("bits_per_pixel", ctypes.c_int),
                ("red_mask", ctypes.c_ulong), ("green_mask", ctypes.c_ulong),
                ("blue_mask", ctypes.c_ulong)]


def capture_window(name="gui-window.png", width=1280, height=800):
    """Saves the screen's top-left width x height pixels (the main window, which run_gui.sh
    places at +0+0) with Xlib's XGetImage, so that no screenshot tool is needed. Called from
    run_gui.sh's events once the GUI has painted; records the outcome in gui-result.txt."""
    path = os.path.join(out, name)
    try:
        x11 = ctypes.CDLL(ctypes.util.find_library("X11") or "libX11.so.6")
        x11.XOpenDisplay.restype = ctypes.c_void_p
        x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
        x11.XDefaultRootWindow.restype = ctypes.c_ulong
        x11.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
        x11.XDefaultScreen.argtypes = [ctypes.c_void_p]
        x11.XDisplayWidth.argtypes = x11.XDisplayHeight.argtypes = [ctypes.c_void_p, ctypes.c_int]
        x11.XGetImage.restype = ctypes.POINTER(_XImage)
        x11.XGetImage.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_int,
                                  ctypes.c_uint, ctypes.c_uint, ctypes.c_ulong, ctypes.c_int]
        x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
        display = x11.XOpenDisplay(None)
        if not display:
            raise RuntimeError("cannot open the X display")
        try:
            screen = x11.XDefaultScreen(display)
            width = min(width, x11.XDisplayWidth(display, screen))
            height = min(height, x11.XDisplayHeight(display, screen))
            image = x11.XGetImage(display, x11.XDefaultRootWindow(display), 0, 0, width, height,
                                  ctypes.c_ulong(-1).value, 2)  # AllPlanes, ZPixmap
            if not image:
                raise RuntimeError("XGetImage failed")
            im = image.contents
            if im.bits_per_pixel != 32 or im.byte_order != 0:  # 32-bit LSBFirst pixels only
                raise RuntimeError("unsupported pixels: %d bits, byte order %d"
                                   % (im.bits_per_pixel, im.byte_order))
            data = ctypes.string_at(im.data, im.bytes_per_line * height)
            shift = {m: (m & -m).bit_length() - 1 for m in (im.red_mask, im.green_mask,
                                                              im.blue_mask)}
            rgb = bytearray(3 * width * height)
            for y in range(height):
                row = data[y * im.bytes_per_line:y * im.bytes_per_line + 4 * width]
                for c, mask in enumerate((im.red_mask, im.green_mask, im.blue_mask)):
                    rgb[3 * width * y + c:3 * width * (y + 1):3] = row[shift[mask] // 8::4]
        finally:
            x11.XCloseDisplay(display)
        write_png(path, width, height, rgb)
        colours = len(set(bytes(rgb[i:i + 3]) for i in range(0, len(rgb), 3 * 97)))
        message = "window captured to %s (%dx%d, %d colours sampled)" % (path, width, height,
                                                                         colours)
        ok = colours > 20
    except Exception as error:  # noqa: BLE001 - recorded as a failure
        message, ok = "window capture failed: %s" % error, False
    return _record(ok, message)


def _record(ok, message):
    print(("ok   " if ok else "FAIL ") + message, flush=True)
    with open(result, "a") as f:
        f.write(("" if ok else "FAIL ") + message + "\n")
    return ok


def check_exports():
    """What run_gui.sh's File menu events wrote (issue 40, item 3): gui-figure.svg from Export
    Stylized Figure... (an SVG of the view's size with the comic's elements), and from Save
    Stylized Orbit... with Frames 3, Degrees 30, Frame rate 5: gui-orbit-0000.png ... 0002.png
    (the view turned between frames), gui-orbit.gif with 3 frames, and the camera put back;
    no gui-refused.svg (the figure asked for under the style None, whose message box the
    events checked and closed)."""
    view = GetActiveView()
    width, height = view.ViewSize
    ok = True
    try:
        root = ElementTree.parse(os.path.join(out, "gui-figure.svg")).getroot()
        size = [float(root.get(k, "0").rstrip("ptx")) for k in ("width", "height")]
        elements = sum(1 for _ in root.iter())
        ok &= _record(root.tag.endswith("svg") and abs(size[0] - width) <= 1
                      and abs(size[1] - height) <= 1 and elements > 20,
                      "Export Stylized Figure... wrote gui-figure.svg (%gx%g for a %dx%d view, "
                      "%d elements)" % (size[0], size[1], width, height, elements))
    except Exception as error:  # noqa: BLE001 - recorded as a failure
        ok &= _record(False, "gui-figure.svg: %s" % error)
    frames = [os.path.join(out, "gui-orbit-%04d.png" % i) for i in range(4)]
    found = [os.path.exists(f) for f in frames]
    ok &= _record(found == [True, True, True, False], "Save Stylized Orbit... wrote frames %s "
                  "(0-2 expected)" % [i for i, f in enumerate(found) if f])
    if all(found[:3]):
        images = [pixels(f) for f in frames[:3]]
        sizes = [im[0] for im in images]
        moved = min(sum(abs(x - y) for p, q in zip(a[1], b[1]) for x, y in zip(p, q))
                    / (3.0 * len(a[1])) for a, b in zip(images, images[1:]))
        ok &= _record(all(s[:2] == (width, height) for s in sizes) and moved > 0.5,
                      "orbit frames of the view's size %s turn (least mean change %.2f levels)"
                      % (sizes[0][:2], moved))
    try:
        count = subprocess.run(
            ["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
             "stream=nb_read_frames", "-of", "csv=p=0", os.path.join(out, "gui-orbit.gif")],
            capture_output=True, text=True, timeout=60).stdout.strip()
        ok &= _record(count == "3", "gui-orbit.gif has %s frames (3 expected)" % (count or "no"))
    except Exception as error:  # noqa: BLE001 - recorded as a failure
        ok &= _record(False, "gui-orbit.gif: %s" % error)
    ok &= _record(not os.path.exists(os.path.join(out, "gui-refused.svg")),
                  "under the style None the entry wrote no figure (its refusal was shown)")
    camera = [list(view.CameraPosition), list(view.CameraFocalPoint), list(view.CameraViewUp)]
    restored = max(abs(a - b) for u, v in zip(camera, saved_camera) for a, b in zip(u, v))
    ok &= _record(restored < 1e-6, "the orbit put the camera back (off by %.2g)" % restored)
    return ok


saved_camera = []


def set_style(index):
    """Sets the active view's Style (run_gui.sh's events: None for a refused figure)."""
    view = GetActiveView()
    view.Style = index
    Render(view)


def run():
    # --- the plugin's view in the GUI's layout, in place of the default render view
    layout = GetLayout()
    check(layout is not None, "the GUI has an active layout")
    old = GetActiveView()
    if old is not None:
        check(old.GetXMLName() == "RenderView", "the default view is a render view (%s)"
              % old.GetXMLName())
        Delete(old)
        del old
    view = CreateView("StylizeView")  # raises when the plugin did not load
    check(view.GetXMLLabel() == "Render View (Stylize)", "view label '%s'" % view.GetXMLLabel())
    AssignViewToLayout(view=view, layout=layout, hint=0)
    SetActiveView(view)
    check(layout.GetViewLocation(view) >= 0 and len(GetViewsInLayout(layout)) == 1,
          "the Stylize view is the layout's only view")
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]

    # --- the properties the panel shows
    style = view.GetProperty("Style")
    check(style is not None, "view property Style exists")
    entries = [style.GetDomain("enum").GetEntryText(i)
               for i in range(style.GetDomain("enum").GetNumberOfEntries())]
    check(entries == ["None", "Comic", "Pixel art", "Sketch", "Line art"], "Style entries %s" % entries)
    for name in ["ComicEdgeWidth", "ComicDots", "ComicHatching", "PixelArtPixelSize",
                 "SketchStepLength", "LightingSubjectFactor"]:
        check(view.GetProperty(name) is not None, "view property %s exists" % name)
    exposed = [p for p in view.ListProperties()
               if p.startswith(("Comic", "PixelArt", "Sketch", "Lighting"))]
    check(len(exposed) >= 60, "at least 60 pass settings on the view (%d)" % len(exposed))

    # --- a contour of the Wavelet source as a Stylized Surface
    wavelet = Wavelet()
    contour = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[157.0])
    display = Show(contour, view)
    available = list(display.GetProperty("Representation").Available)
    check("Stylized Surface" in available, "'Stylized Surface' offered for the display %s"
          % available)
    display.SetRepresentationType("Stylized Surface")
    check(display.Representation == "Stylized Surface", "display representation %s"
          % display.Representation)
    check(display.GetProperty("StylizeSubjectFactor") is not None,
          "display property StylizeSubjectFactor exists")
    # the Wavelet as a Volume: its Stylize Volume property, on, shown with Volume only
    volume = Show(wavelet, view)
    volume.SetRepresentationType("Volume")
    stylize = volume.GetProperty("StylizeVolume")
    check(stylize is not None and volume.StylizeVolume == 1,
          "a Volume display's StylizeVolume exists and is on")
    decorator = stylize.SMProperty.GetHints().FindNestedElementByName(
        "PropertyWidgetDecorator") if stylize and stylize.SMProperty.GetHints() else None
    check(decorator is not None and decorator.GetAttribute("property") == "Representation" and
          decorator.GetAttribute("value") == "Volume", "StylizeVolume is shown with Volume only")
    Hide(wavelet, view)
    view.CameraPosition = [30.0, -45.0, 25.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    Render(view)  # the first render resets the camera; move closer after it
    view.ResetCamera()
    focal, position = list(view.CameraFocalPoint), list(view.CameraPosition)
    view.CameraPosition = [f + (p - f) / 1.3 for f, p in zip(focal, position)]  # closer

    # --- the panel (issue 40): what 0 means in the label, a number field where a range spans
    # more than three decades (a domain without a maximum: no slider), each range said once in
    # the tooltip and the paper an equation comes from named, no Lighting section under None
    for name, label in [("ComicHatchWidth", "Hatch Width (0 = Auto)"),
                        ("ComicHatchDirections", "Hatch Directions (0 = Hatch Angle)"),
                        ("PixelArtArtPixelsAcross", "Art Pixels Across (0 = Auto)")]:
        shown = view.GetProperty(name).SMProperty.GetXMLLabel()
        check(shown == label, "%s's label is %r (%r expected)" % (name, shown, label))
    for name, slider in [("PixelArtArtPixelsAcross", False), ("PixelArtPixelSize", False),
                         ("ComicReferenceHeight", False), ("ComicEdgeWidth", True),
                         ("ComicHatchWidth", True)]:
        domain = view.GetProperty(name).SMProperty.GetDomain("range")
        has_max = bool(domain and domain.GetMaximumExists(0))
        check(has_max == slider, "%s: %s" % (name, "a slider" if slider else "a number field"))
    repeated, unsourced = [], []
    for name in view.ListProperties():
        documentation = view.GetProperty(name).SMProperty.GetDocumentation()
        text = " ".join((documentation.GetDescription() if documentation else "").split())
        if text.count("Range [") > 1:
            repeated.append(name)
        if re.search(r"\b[Ee]q\. ?\d", text) and "Source:" not in text:
            unsourced.append(name)
    check(not repeated, "tooltips that state a range twice: %s" % repeated)
    check(not unsourced, "tooltips citing an equation without its source: %s" % unsourced)
    lighting = [view.SMProxy.GetPropertyGroup(i)
                for i in range(view.SMProxy.GetNumberOfPropertyGroups())
                if view.SMProxy.GetPropertyGroup(i).GetXMLLabel() == "Lighting"]
    hint = lighting[0].GetHints().FindNestedElementByName("PropertyWidgetDecorator") \
        if lighting and lighting[0].GetHints() else None
    check(hint is not None and hint.GetAttribute("property") == "Style" and
          hint.GetAttribute("value") == "0" and hint.GetAttribute("inverse") == "1",
          "the Lighting section is hidden under Style None")

    # --- the style None, then Comic: the comic image keeps the contour's colours (Tint Data
    # colors) and differs from None's
    images = {}
    for index, name in [(0, "none"), (1, "comic")]:
        view.Style = index
        Render(view)
        path = os.path.join(out, "gui-%s.png" % name)
        SaveScreenshot(path, view, ImageResolution=[600, 450])
        images[name] = pixels(path)[1]
    element = view.SMProxy.GetProperty("Style").GetElement(0)
    check(element == 1 and view.Style == "Comic", "Style is Comic (%d, %s)" % (element, view.Style))
    d = sum(abs(x - y) for p, q in zip(images["none"], images["comic"])
            for x, y in zip(p, q)) / (3.0 * max(1, len(images["none"])))
    check(d > 5.0, "the comic image differs from the style None's (mean %.1f levels)" % d)
    chroma = max(max(p) - min(p) for p in images["comic"])
    none_chroma = max(max(p) - min(p) for p in images["none"])
    check(chroma > 50 or none_chroma <= 50, "the comic image keeps the contour's colours "
          "(chroma %d, None's %d)" % (chroma, none_chroma))
    # the contour stays the active source, so the panel shows its display and the view
    SetActiveSource(contour)
    saved_camera[:] = [list(view.CameraPosition), list(view.CameraFocalPoint),
                       list(view.CameraViewUp)]


try:
    run()
except Exception as error:  # noqa: BLE001 - any error fails the test through the result file
    import traceback
    traceback.print_exc()
    failures.append("error: %r" % error)
with open(result, "w") as f:
    f.write("".join("FAIL %s\n" % m for m in failures) if failures else "PASS\n")
print("%d failures" % len(failures), flush=True)
