"""The generator's tables: the classes documented, the output paths, the units and values a
comment may state, and the spellings of the ParaView XML and of vtkstylize's option table
(proxies, skipped and advanced parameters, command-line options)."""
import os
import re

# The repository: scripts/stylize_parameters/config.py is two folders below it.
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DESCRIPTION = "Parameter reference of the VTK Stylize passes, generated from the wrapped classes."
OUTPUT = os.path.join("docs", "PARAMETERS.md")
README = "README.md"
DIFF_LINES = 200  # --check shows at most this many lines of each stale file's diff

# The classes documented, in order.
CLASSES = ["vtkStylizeLightingPass", "vtkStylizeGBufferPass", "vtkComicPass", "vtkPixelArtPass",
           "vtkSketchPass", "vtkLineArtPass", "vtkStylizePrincipalCurvatures", "vtkStylizeFeatureLines",
           "vtkStylizeLineVisibility", "vtkStylizeReader"]
# The classes of the Filters module (the others are passes).
FILTER_CLASSES = {"vtkStylizePrincipalCurvatures", "vtkStylizeFeatureLines",
                  "vtkStylizeLineVisibility", "vtkStylizeReader"}

# Units recognized in a comment, first match wins (the phrase must say it is the unit).
UNIT_PATTERNS = [
    (r"\bdimensionless\b", "dimensionless"),
    (r"\bin screen pixels\b", "screen pixels"),
    (r"(?:\bin |, |\()points\b|\bpoints at the focal distance\b", "points"),
    (r"(?:\bin |, |\()pixels\b", "pixels"),
    (r"\bart pixels per\b", "art pixels"),
    (r"(?:\bin |, |\()degrees\b", "degrees"),
    (r"(?:\bin |, |\()radians\b", "radians"),
    (r"(?:\bin |, |\()world units\b", "world units"),
    (r"(?:\bin |, |\()MiB\b", "MiB"),
    (r"(?:\bin |, |\()seconds\b", "seconds"),
    (r"\b[Tt]ones? (?:above|below)\b", "tone (lit luminance)"),
    (r"\b[Nn]umber of\b|\blevels per\b|\b(?:[Hh]ysteresis|LIC) steps\b|\biterations\b|"
     r"\bmany steps\b", "count"),
]
VECTOR_UNIT_PATTERNS = [(r"\bRGB\b", "RGB")] + UNIT_PATTERNS

NUM = r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
NAMED_VALUES = {"on": True, "off": False, "nullptr": None, "NULL": None, "white": (1.0, 1.0, 1.0),
                "black": (0.0, 0.0, 0.0)}
SCALAR_TYPES = {"int", "double", "float", "bool", "unsigned int", "long", "vtkIdType",
                "unsigned char", "char"}
PROBE = 1.0e300
INT_PROBE = 2 ** 31 - 1


# Settings of the style base that whoever renders sets, not the user's look (their comments say
# who sets them).
RENDERING_PLUMBING = {"WindowScale"}


# ------------------------------------------------------------------------------------------------
# ParaView server-manager XML (the plugin's view exposes these proxies as subproxies)

XML_PASSES = "Plugin/View/StylizePasses.xml"
XML_VIEW = "Plugin/View/StylizeView.xml"
XML_GROUP = "stylize_passes"
# (proxy name, class, label, exposed-name prefix, values of the view's Style that show it: one
# value, or "!V" for every value but V; None: every style, no decorator)
XML_PROXIES = [
    ("ComicPass", "vtkComicPass", "Comic", "Comic", "1"),
    ("PixelArtPass", "vtkPixelArtPass", "Pixel art", "PixelArt", "2"),
    ("SketchPass", "vtkSketchPass", "Sketch", "Sketch", "3"),
    ("LineArtPass", "vtkLineArtPass", "Line art", "LineArt", "4"),
    ("LightingPass", "vtkStylizeLightingPass", "Lighting", "Lighting", "!0"),
]
XML_ALL_STYLES = "1 2 3 4"
# ParaView's representations with a Volume type: each gets the display property StylizeVolume
# (its volume's vtkStylizeStylePass::STYLIZE_VOLUME, set by the view), shown with Volume only.
XML_VOLUME_DISPLAYS = ("UniformGridRepresentation", "UnstructuredGridRepresentation",
                       "StructuredGridRepresentation")
XML_VOLUME_DISPLAY_TEXT = (
    "Draw this volume in the Stylize view's style (with the style's StylizeVolumes on): off "
    "leaves it to ParaView, drawn as ParaView draws it over the stylized picture "
    "(vtkStylizeStylePass::STYLIZE_VOLUME 0 on its volume, set by the view on every rank). "
    "Default on.")
# Where a setting's 0 stands for a choice made for the user, the panel's label says so (a bare 0
# in the field reads as zero): (class, parameter) -> what 0 means, as the label's suffix shows it.
# The generator warns of a setting whose default is 0 and whose comment explains a 0 ("0:",
# "0 (default)") without an entry here.
XML_ZERO_MEANS = {("vtkComicPass", "HatchWidth"): "Auto",
                  ("vtkComicPass", "HatchDirections"): "Hatch Angle",
                  ("vtkPixelArtPass", "ArtPixelsAcross"): "Auto",
                  ("vtkStylizeReader", "MemoryLimit"): "Auto",
                  ("vtkStylizeReader", "TimeLimit"): "Auto"}
# A range wider than this ratio (max / min, or max - min from 0 or below) is a text field, not
# a slider: a slider over [0, 16384] cannot set a small value. The class still clamps.
XML_SLIDER_RATIO = 1000.0
# The papers the comments cite ("eq. 12", "the paper"), named in the tooltips: class -> source;
# the lighting pass's settings name their model first ("Comic:", "PixelArt:").
XML_SOURCES = {
    "vtkComicPass": "Hu et al., Real-time non-photorealistic rendering method for black-and-white "
                    "comic style in games and animation, J. System Simulation 36(7), 2024",
    "vtkPixelArtPass": "the pixel-art paper, A high-performance real-time pixelated "
                       "non-photorealistic rendering method",
    "vtkSketchPass": "Zhang & Gong, Sketch rendering based on real-time principal direction "
                     "estimation, 2020",
}
XML_MODEL_SOURCES = {"Comic:": "vtkComicPass", "PixelArt:": "vtkPixelArtPass"}
# Parameters the view sets itself, so not exposed: (class, parameter) -> why.
XML_SKIP = {("vtkStylizeLightingPass", "Model"): "set by the view",
            ("vtkStylizeLightingPass", "ColorMode"): "set by the style (its Tint, ColoredLights)",
            ("vtkStylizeLightingPass", "SolidColorTones"): "set by the style with ColorMode",
            ("vtkStylizeLightingPass", "SolidColorWhite"): "set by the style with ColorMode",
            ("vtkSketchPass", "SceneBounds"): "set by the view (the data's bounds on all ranks)",
            ("vtkPixelArtPass", "InteractiveImageReduction"):
                "no effect: the pixel art renders its scene at its art resolution already",
            **{(c, "PlainAnnotations"): "always on in ParaView's view (its data axes grid "
               "drawn as ParaView draws it)"
               for c in ("vtkComicPass", "vtkPixelArtPass", "vtkSketchPass", "vtkLineArtPass")},
            **{("vtkPixelArtPass", n): "the pixel art draws no iso-lines"
               for n in ("IsoLines", "IsoLineWidth", "IsoLineSpacing")},
            ("vtkSketchPass", "DirectionArrayName"):
                "ParaView's data is composite: Model reads its tangents, which the Principal "
                "Curvatures filter's TangentDirection picks"}
# panel_visibility="advanced": tuning knobs of the algorithms rather than of the look, by name,
# and settings whose comment says they are for measurement, testing or a baseline.
XML_ADVANCED_NAME = re.compile(r"(?:Thresholds?|Tolerance|Stride|Seed)$|^ReferenceHeight$")
XML_ADVANCED_TEXT = re.compile(
    r"\b(?:measurements?|testing|numeric tests?|baseline|accuracy study)\b", re.I)
XML_ADVANCED_RULE = (
    'panel_visibility="advanced" marks the tuning parameters: names ending in Threshold(s), '
    "Tolerance, Stride or Seed, the ReferenceHeight (the size of a point), and parameters whose "
    "comment says they are for measurement, testing or a baseline (e.g. the accuracy study's "
    "screen-space LIC).")
XML_INT_TYPES = {"int", "bool", "unsigned int", "long", "vtkIdType", "unsigned char", "char"}
XML_WIDTH = 100

XML_FILTERS = "Plugin/View/StylizeFilters.xml"
# (proxy name, class, label, input data type, help): ParaView filters of the Filters module.
XML_FILTER_PROXIES = [
    ("PrincipalCurvatures", "vtkStylizePrincipalCurvatures", "Principal Curvatures", "vtkPolyData",
     "Principal curvatures and directions of a surface (its polygons; run Extract Surface on "
     "other data first). The Stylize view's Sketch draws along them with Direction Source "
     "Model: the direction chosen by Tangent Direction becomes the point data's tangents."),
]
# (proxy name, documented class, label, help, information properties: (name, getter,
# documentation), the proxy's class in ParaView, ParaView's reader factory: [(file description,
# the extensions of the class's GetSupportedExtensions() given, or all of them)]): ParaView
# sources (readers) of the Filters and IO modules. They are in the Sources menu, in Python
# (paraview.simple.StylizeCheckedReader) and among File > Open's file types; the factory asks the
# ParaView class's CanReadFile() which files File > Open should give them (vtkPVStylizeCheckedReader:
# those ParaView's own reader reads with a loss, the triangle-strip PLY). The PLY entry comes
# apart, so that the Open dialog's "Set reader as default" for a PLY file stores *.ply alone.
XML_SOURCE_PROXIES = [
    ("StylizeCheckedReader", "vtkStylizeReader", "Stylize Checked Reader",
     "For files that may be broken or hostile: the same checks as the vtkstylize command, so "
     "that such a file gives one error line instead of crashing, hanging or exhausting the "
     "memory of the server. File > Open gives it the PLY files stored as triangle strips (whose "
     "surface ParaView's PLY Reader reads with no cells); for any other file choose its file "
     "type in the Open dialog, or this source.",
     [("ErrorMessage", "GetErrorMessage",
       "The reason the last read failed, one line (empty after a success); read it with "
       "UpdatePropertyInformation() and GetPropertyValue(\"ErrorMessage\").")],
     "vtkPVStylizeCheckedReader",
     [("Stylize Checked Reader (PLY)", ".ply"),
      ("Stylize Checked Reader (VTK, Exodus, EnSight, OpenFOAM, OBJ, STL)", None)]),
]



# ------------------------------------------------------------------------------------------------
# The command line's option table (vtkstylize)

CLI_TABLE = "Applications/vtkstylize/vtkstylizeSettings.inc"
# How vtkstylize spells each setting it offers: (class, setting) -> (option, metavar, keyword
# spellings of an enumeration). The spelling is the command line's presentation (kept stable for
# scripts); what a setting is, its type, range, default, values and meaning come from the class.
CLI_COMIC = [
    ("EdgeWidth", "--edge-width", "PT"), ("DepthThreshold", "--depth-threshold", "T"),
    ("NormalThreshold", "--normal-threshold", "T"), ("ColorThreshold", "--color-threshold", "T"),
    ("DotSpacing", "--dot-spacing", "PT"), ("DotAngle", "--dot-angle", "DEG"),
    ("HatchSpacing", "--hatch-spacing", "PT"), ("HatchWidth", "--hatch-width", "PT"),
    ("HatchAngle", "--hatch-angle", "DEG"), ("BrightThreshold", "--bright", "T"),
    ("DarkThreshold", "--dark", "T"), ("CrossThreshold", "--cross-threshold", "T"),
    ("ReferenceHeight", "--reference-height", "PX"), ("HatchDirections", "--hatch-directions", "N"),
    ("EdgeWeights", "--edge-weights", "D,N,C"),
    ("Anchor", "--anchor", "screen|object", {"screen": "SCREEN", "object": "OBJECT"}),
    ("HatchOrientation", "--hatch-orientation", "fixed|principal",
     {"fixed": "FIXED", "principal": "PRINCIPAL"}),
    ("Edges", "--no-edges", None), ("Dots", "--no-dots", None), ("Hatching", "--no-hatching", None),
    ("CrossHatching", "--no-cross", None),
    ("Tint", "--tint", "off|data|all",
     {"off": "BLACK_AND_WHITE", "data": "DATA_COLORS", "all": "ALL_COLORS"}),
    ("FeatureLines", "--feature-lines", None), ("FeatureLineWidth", "--feature-line-width", "PT"),
    ("IsoLines", "--iso-lines", "N"), ("IsoLineWidth", "--iso-line-width", "PT"),
    ("IsoLineSpacing", "--iso-line-spacing", "round|even|bands",
     {"round": "ROUND", "even": "EVEN", "bands": "BANDS"}),
]
CLI_PIXEL = [
    ("LowThreshold", "--low-threshold", "T"), ("HighThreshold", "--high-threshold", "T"),
    ("DitherStrength", "--dither-strength", "S"), ("PixelSize", "--pixel-size", "PX"),
    ("ArtPixelsAcross", "--art-pixels", "N"), ("HysteresisIterations", "--hysteresis", "N"),
    ("Levels", "--levels", "K"), ("DitherSize", "--dither-size", "N"),
    ("ColormapColors", "--colormap-colors", "N"), ("ColormapShades", "--colormap-shades", "N"),
    ("DepthThreshold", "--depth-threshold", "T"), ("NormalThreshold", "--normal-threshold", "T"),
    ("Mode", "--mode", "fast|faithful", {"fast": "FAST", "faithful": "FAITHFUL"}),
    ("EdgeDetector", "--edge-detector", "none|sobel|canny",
     {"none": "NO_EDGES", "sobel": "SOBEL", "canny": "CANNY"}),
    ("DitherAnchor", "--dither-anchor", "screen|grid|surface",
     {"screen": "SCREEN", "grid": "GRID", "surface": "SURFACE"}),
    ("Layer", "--pixel-layer", "art|pixelated|edges",
     {"art": "PIXEL_ART", "pixelated": "PIXELATED", "edges": "EDGES"}),
    ("OutlineColor", "--outline", "COLOR"),
    ("DepthEdges", "--no-depth-edges", None), ("NormalEdges", "--normal-edges", None),
    ("SnapToGrid", "--no-snap", None), ("StylizeBackground", "--stylize-background", None),
    ("ColoredLights", "--colored-lights", None),
]
CLI_SKETCH = [
    ("Neighbors", "--neighbors", "2|4|8", {"2": "2", "4": "4", "8": "8"}),
    ("NeighborSpacing", "--neighbor-spacing", "PT"), ("MaxStride", "--max-stride", "PT"),
    ("ObjectScale", "--object-scale", "F"),
    ("PlanarTolerance", "--planar-tolerance", "T"),
    ("UmbilicTolerance", "--umbilic-tolerance", "T"), ("FillRadius", "--fill-radius", "PT"),
    ("FallbackAngle", "--fallback-angle", "DEG"), ("StepLength", "--step-length", "PT"),
    ("NoiseSize", "--noise-size", "PT"), ("StrokeContrast", "--stroke-contrast", "C"),
    ("Contrast", "--contrast", "C"), ("BlurRadius", "--blur-radius", "PT"),
    ("SmoothingRadius", "--smoothing-radius", "PT"), ("FieldTexelSize", "--field-texel", "PT"),
    ("SmoothingIterations", "--smoothing", "N"), ("Steps", "--steps", "N"),
    ("BlurStride", "--blur-stride", "K"),
    ("DirectionSource", "--direction-source", "screen|model",
     {"screen": "SCREEN", "model": "MODEL"}),
    ("Direction", "--direction", "minimum|maximum|bisector",
     {"minimum": "MINIMUM", "maximum": "MAXIMUM", "bisector": "BISECTOR"}),
    ("Noise", "--noise", "white|perlin|worley|sparse",
     {"white": "WHITE", "perlin": "PERLIN", "worley": "WORLEY", "sparse": "SPARSE"}),
    ("NoiseSpace", "--noise-space", "object|screen", {"object": "OBJECT", "screen": "SCREEN_SPACE"}),
    ("LicMode", "--lic", "perspective|screen2d",
     {"perspective": "PERSPECTIVE", "screen2d": "SCREEN_2D"}),
    ("Layer", "--sketch-layer", "sketch|directions|strokes|tone",
     {"sketch": "SKETCH", "directions": "DIRECTIONS", "strokes": "STROKES", "tone": "TONE"}),
    ("BrightThresholds", "--bright-thresholds", "T1,T2"), ("CrossThreshold", "--cross-threshold", "T"),
    ("PencilColor", "--pencil", "COLOR"), ("PaperColor", "--paper", "COLOR"),
    ("CrossHatching", "--no-cross", None),
    ("Tint", "--tint", "off|data|all",
     {"off": "BLACK_AND_WHITE", "data": "DATA_COLORS", "all": "ALL_COLORS"}),
    ("ReferenceHeight", "--reference-height", "PX"),
    ("FeatureLines", "--no-feature-lines", None), ("FeatureLineWidth", "--feature-line-width", "PT"),
    ("VectorFigureStrokes", "--vector-pencil", None),
    ("IsoLines", "--iso-lines", "N"), ("IsoLineWidth", "--iso-line-width", "PT"),
    ("IsoLineSpacing", "--iso-line-spacing", "round|even|bands",
     {"round": "ROUND", "even": "EVEN", "bands": "BANDS"}),
]
CLI_LINES = [
    ("ContourWidth", "--contour-width", "PT"), ("CreaseWidth", "--crease-width", "PT"),
    ("RidgeWidth", "--ridge-width", "PT"), ("ValleyWidth", "--valley-width", "PT"),
    ("SuggestiveWidth", "--suggestive-width", "PT"), ("DepthTaper", "--depth-taper", "F"),
    ("StrengthTaper", "--strength-taper", "F"), ("CreaseAngle", "--crease-angle", "DEG"),
    ("RidgeThreshold", "--ridge-threshold", "T"),
    ("SuggestiveThreshold", "--suggestive-threshold", "T"),
    ("Tone", "--tone", "none|shades|dots", {"none": "NONE", "shades": "SHADES", "dots": "DOTS"}),
    ("DotSpacing", "--dot-spacing", "PT"),
    ("ToneLevels", "--tone-levels", "N"), ("ToneDarkest", "--tone-darkest", "F"),
    ("InkColor", "--ink", "COLOR"), ("PaperColor", "--paper", "COLOR"),
    ("ReferenceHeight", "--reference-height", "PX"),
    ("Layer", "--lines-layer", "lines|paper", {"lines": "LINE_ART", "paper": "PAPER"}),
    ("IsoLines", "--iso-lines", "N"), ("IsoLineWidth", "--iso-line-width", "PT"),
    ("IsoLineSpacing", "--iso-line-spacing", "round|even|bands",
     {"round": "ROUND", "even": "EVEN", "bands": "BANDS"}),
]
CLI_LIGHTING = [
    ("SubjectFactor", "--subject", "P1"), ("GrayLevelsNear", "--levels-near", "N"),
    ("GrayLevelsFar", "--levels-far", "N"), ("SpecularGain", "--specular-gain", "G"),
    ("Scattering", "--scattering", "S"), ("SpecularOcclusion", "--occlusion", "M"),
]
CLI_OPTIONS = [("vtkComicPass", "comic", CLI_COMIC), ("vtkPixelArtPass", "pixel", CLI_PIXEL),
               ("vtkSketchPass", "sketch", CLI_SKETCH), ("vtkLineArtPass", "lines", CLI_LINES),
               ("vtkStylizeLightingPass", "lighting", CLI_LIGHTING)]
# Settings the command line offers by hand (vtkstylize's Options.cxx), and why.
CLI_BY_HAND = [
    "vtkStylizeLightingPass Model: --lighting takes the model's name (GetModelFromName)",
    "vtkPixelArtPass Palette: --palette also offers 1bit and 4grays (palette and levels at once)",
    "vtkPixelArtPass AddPaletteColor: --colors takes a list and selects the CUSTOM palette",
    "vtkSketchPass DirectionSource model: the program also computes the principal directions",
]
