// VTK Stylize comic pass (vtkComicPass): three-phase edges, halftone dots, hatch lines.
// docs/algorithms.md section 2. The pass prepends #defines that select what is compiled:
//   COMIC_STAGE_EDGES   first stage of the colour-edge path: writes f_normal and k1, k2
//   COMIC_STAGE_COMPOSITE the composite stage: edges, pattern and ink into the output
//   COMIC_DEPTH_EDGES, COMIC_NORMAL_EDGES, COMIC_COLOR_EDGES   the enabled edge phases
//   COMIC_FEATURE_LINES   the feature lines' ink (vtkStylizeFeatureStrokes) with the edges
//   COMIC_DOTS, COMIC_HATCH, COMIC_CROSS                       the enabled patterns
//   COMIC_OBJECT_ANCHOR   patterns anchored to the object-space position, not the screen
//   COMIC_HATCH_PRINCIPAL hatch lines around the form, along the principal direction field
//                         (vtkStylizeFieldFS, computed before the composite stage)
//   COMIC_TINTED          keep the data's hue under the ink
//   COMIC_LAYER           0 the comic image, 1 the edge factor alone, 2 the pattern alone,
//                         3 the pattern's inputs (vector figures), 4 the paper under the ink
// and the pattern's constants, which vtkComicPatterns.h holds for the pass and the vector figure:
//   COMIC_PI, COMIC_DOT_DISC_COVERAGE, COMIC_DOT_CORNER_COVERAGE, COMIC_DOT_INSCRIBED_RADIUS,
//   COMIC_DOT_CORNER_RADIUS   the dot's radius from its coverage
//   COMIC_FIXED_ANGLE_STEP    the direction step FIGURE_INPUTS records for the fixed HatchAngle
// Lengths arrive in pixels of the final (possibly magnified) image, already multiplied by the
// pixels-per-point factor on the CPU, so the shader is resolution-free.

uniform sampler2D comicEdgeTexture;          // stage 1 output: luminance of f_normal, k1, k2
uniform sampler2D comicFeatureInk;           // COMIC_FEATURE_LINES: the strokes' ink in [0, 1]
                                             // (red), the iso-lines' halo (green)

uniform ivec2 comicSize;           // viewport size (pixels)
uniform vec2 comicPixelOffset;     // this tile's offset in the full image (pixels)
uniform int comicParallel;         // 1 for parallel projection
uniform float comicPixelWorld;     // world size of a pixel: times depth (perspective) or as is
uniform int comicStride;           // Sobel tap distance (pixels)
uniform vec3 comicEdgeWeights;     // a1, a2, a3 (sum 1)
uniform float comicDepthThreshold; // depth slope where depth edges start (dimensionless)
uniform float comicNormalThreshold;
uniform float comicColorThreshold;
uniform float comicDotSpacing;     // pixels (screen) or world units (object anchor)
uniform float comicHatchSpacing;   // pixels (screen) or world units (object anchor)
uniform float comicHatchWidth;     // fraction of the hatch spacing; 0: follows the tone
uniform vec2 comicDotDirection;    // (cos, sin) of the screen angle
uniform float comicHatchAngle;     // radians
uniform int comicHatchDirections;  // 0: one direction; n: normal-dependent, n steps over 180 deg
uniform float comicBright;         // a1 of eq. 13-14: dots above
uniform float comicDark;           // a2 of eq. 13-14: hatching below
uniform float comicCross;          // cross-hatching below this tone
uniform int comicEmittedLayer;     // 1: a translucent layer of emitted colours alone (a fog)
uniform sampler2D comicField;      // COMIC_HATCH_PRINCIPAL: xyz view-space direction, w depth
uniform int comicHatchSteps;       // COMIC_HATCH_PRINCIPAL: angle steps over 180 degrees

float comicLuminance(vec3 c)
{
  return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

// This pixel's index in the G-buffer textures (which have the viewport's size).
ivec2 comicPixel()
{
  return clamp(ivec2(texCoord * vec2(comicSize)), ivec2(0), comicSize - 1);
}

ivec2 comicTap(ivec2 p, int dx, int dy)
{
  return clamp(p + ivec2(dx, dy) * comicStride, ivec2(0), comicSize - 1);
}


float comicSobelLength(vec3 v[9])
{
  vec3 gx = (v[2] + 2.0 * v[5] + v[8]) - (v[0] + 2.0 * v[3] + v[6]);
  vec3 gy = (v[6] + 2.0 * v[7] + v[8]) - (v[0] + 2.0 * v[1] + v[2]);
  return 0.125 * sqrt(dot(gx, gx) + dot(gy, gy));
}

// Edge strength G in [0, 1] from a response: 0 below t, 1 from 2t, smooth between.
float comicEdgeStrength(float response, float t)
{
  return smoothstep(t, 2.0 * t, response);
}

#ifdef COMIC_DEPTH_EDGES
// Off a surface (centre z[4] = 0): whether a surface tap's surface goes on past it, one more tap
// in the same direction. The outline lies on both sides of a silhouette; a thin part (a glyph's
// shaft, a wire) gets it on its own side only, so that it stays as thin as it is drawn rather
// than swelling into a blob of ink.
bool comicWideNeighbour(ivec2 p, float z[9])
{
  for (int k = 0; k < 9; ++k)
  {
    ivec2 o = ivec2(k % 3 - 1, k / 3 - 1);
    if (z[k] > 0.0 &&
      texelFetch(stylizeLinearDepthTexture, comicTap(p, 2 * o.x, 2 * o.y), 0).r > 0.0)
    {
      return true;
    }
  }
  return false;
}

// Phase 1 (eq. 4-5): Sobel on the linear depth, made scale-free by dividing by the world size of
// a pixel at that depth, so the response is the surface's slope against the view ray (tan of the
// angle between normal and view axis) or a depth jump in pixel units. A surface next to no
// surface (background, lines) is an edge on both sides.
float comicDepthEdge(ivec2 p)
{
  float z[9];
  int surfaces = 0;
  float zmin = 3.4e38;
  for (int j = -1; j <= 1; ++j)
  {
    for (int i = -1; i <= 1; ++i)
    {
      float d = texelFetch(stylizeLinearDepthTexture, comicTap(p, i, j), 0).r;
      d = (d > 0.0 && d < 3.4e38) ? d : 0.0;
      z[(j + 1) * 3 + i + 1] = d;
      if (d > 0.0)
      {
        ++surfaces;
        zmin = min(zmin, d);
      }
    }
  }
  if (surfaces == 0)
  {
    return 0.0;
  }
  if (surfaces < 9)
  {
    return z[4] > 0.0 || comicWideNeighbour(p, z) ? 1.0 : 0.0;
  }
  float pixel = comicParallel == 1 ? comicPixelWorld : comicPixelWorld * zmin;
  // Divide each tap by the pixel size first: no overflow or underflow at 1e-6..1e6 scales.
  for (int k = 0; k < 9; ++k)
  {
    z[k] = (z[k] - zmin) / pixel;
  }
  float slope = length(stylizeSobel(z)) / float(comicStride);
  return comicEdgeStrength(slope, comicDepthThreshold);
}
#endif

#ifdef COMIC_NORMAL_EDGES
// Phase 2 (eq. 6-7): Sobel on the view-space normals (the change of the unit normal per tap).
// Taps without a normal take the centre's, so they add nothing (depth edges cover them).
float comicNormalEdge(ivec2 p)
{
  vec4 c = texelFetch(stylizeNormalTexture, p, 0);
  if (c.a < 0.5)
  {
    return 0.0;
  }
  vec3 n[9];
  for (int j = -1; j <= 1; ++j)
  {
    for (int i = -1; i <= 1; ++i)
    {
      vec4 t = texelFetch(stylizeNormalTexture, comicTap(p, i, j), 0);
      n[(j + 1) * 3 + i + 1] = t.a > 0.5 ? t.xyz : c.xyz;
    }
  }
  return comicEdgeStrength(comicSobelLength(n), comicNormalThreshold);
}
#endif

// k1 = 1 - G1 and k2 = 1 - G2 of this pixel.
vec2 comicGeometryEdges(ivec2 p)
{
  vec2 k = vec2(1.0);
#ifdef COMIC_DEPTH_EDGES
  k.x = 1.0 - comicDepthEdge(p);
#endif
#ifdef COMIC_NORMAL_EDGES
  k.y = 1.0 - comicNormalEdge(p);
#endif
  return k;
}

#ifdef COMIC_STAGE_EDGES

// Stage 1 of the colour-edge path: f_normal = E k1 k2 (eq. 5-7) for the colour Sobel of stage 2,
// which runs on its luminance (the tone the pattern is drawn from), with k1 and k2.
void comicMain()
{
  ivec2 p = comicPixel();
  vec2 k = comicGeometryEdges(p);
  vec3 e = stylizeSaturateFinite(texelFetch(stylizeColorTexture, p, 0).rgb);
  gl_FragData[0] = vec4(comicLuminance(e) * k.x * k.y, k.x, k.y, 1.0);
}

#else

// Hatch lines (eq. 11-12, reconstructed): u is the coordinate across the lines in spacing units;
// the line is the band within half the width w (a fraction of the spacing) of an integer,
// anti-aliased over aa spacing units; a line narrower than the smooth edge is a band of half
// width aa, lighter by its excess, so that the ink's area is kept. 1 = paper.
float comicLines(float u, float w, float aa)
{
  float t = abs(fract(u + 0.5) - 0.5);
  float hw = 0.5 * w;
  if (w >= 1.0)
  {
    return 0.0;
  }
  if (w <= 0.0)
  {
    return 1.0;
  }
  return hw >= aa ? smoothstep(hw - aa, hw + aa, t)
                  : 1.0 - (hw / aa) * (1.0 - smoothstep(0.0, 2.0 * aa, t));
}

// The dot screen's cells at `plane` (pixels or world units; planeJ its derivatives per pixel)
// turned by `direction` (cos, sin): xy the cell coordinates, z the smooth edge (half the cell
// units a pixel spans), w how much the dots fade to their mean (a cell's side under three
// pixels, stylizePatternFade). The tone's dots and a fog's opacity screen use it.
vec4 comicDotCells(vec2 plane, mat2 planeJ, vec2 direction)
{
  vec2 dx = stylizeRotate(planeJ[0], direction) / comicDotSpacing;
  vec2 dy = stylizeRotate(planeJ[1], direction) / comicDotSpacing;
  float aa = clamp(0.5 * max(abs(dx.x) + abs(dy.x), abs(dx.y) + abs(dy.y)), 1e-4, 0.5);
  float fade = stylizePatternFade(max(length(vec2(dx.x, dy.x)), length(vec2(dx.y, dy.y))));
  return vec4(stylizeRotate(plane / comicDotSpacing, direction), aa, fade);
}

// The value of a line's ink in the tinted comic: its hue at this fraction of full value.
const float comicLineInk = 0.25;

void comicMain()
{
  ivec2 p = comicPixel();
  vec4 image = texelFetch(stylizeColorTexture, p, 0);
  vec3 colour = stylizeSaturateFinite(image.rgb);
  float depth = texelFetch(stylizeDepthTexture, p, 0).r;
  bool background = !(depth < 1.0);
  float linearDepth = texelFetch(stylizeLinearDepthTexture, p, 0).r;
  bool surface = linearDepth > 0.0;

  // ---- edges: e = k1 (a1 + a2 k2 + a3 k2 k3), so that f = E e (eq. 9)
  float e = 1.0;
#if defined(COMIC_COLOR_EDGES)
  vec4 fc = texelFetch(comicEdgeTexture, p, 0);
  float k1 = fc.g;
  float k2 = fc.b;
  float fn[9];
  for (int j = -1; j <= 1; ++j)
  {
    for (int i = -1; i <= 1; ++i)
    {
      fn[(j + 1) * 3 + i + 1] = texelFetch(comicEdgeTexture, comicTap(p, i, j), 0).r;
    }
  }
  float k3 = 1.0 - comicEdgeStrength(length(stylizeSobel(fn)), comicColorThreshold);
  e = k1 * (comicEdgeWeights.x + k2 * (comicEdgeWeights.y + comicEdgeWeights.z * k3));
#elif defined(COMIC_DEPTH_EDGES) || defined(COMIC_NORMAL_EDGES)
  vec2 k = comicGeometryEdges(p);
  e = k.x * (comicEdgeWeights.x + k.y * (comicEdgeWeights.y + comicEdgeWeights.z));
#endif
#if defined(COMIC_FEATURE_LINES) && COMIC_LAYER != 1
  // (the EDGES layer leaves the lines out: a vector figure draws them as paths)
  e *= 1.0 - clamp(texelFetch(comicFeatureInk, p, 0).r, 0.0, 1.0);
#endif

  // ---- pattern coordinates and their derivatives per pixel
  float tone = surface ? stylizeTone(colour) : comicLuminance(colour); // (lines keep theirs)
  vec2 pixel = vec2(p) + 0.5 + comicPixelOffset;
#ifdef COMIC_OBJECT_ANCHOR
  // Triplanar projection of the object-space position on the plane facing its geometric normal
  // (from the neighbouring positions), in world units, and its derivatives per pixel.
  StylizeTriplanar anchor = stylizeTriplanarFrame(stylizePositionTexture, p, comicSize, pixel);
  vec2 plane = anchor.plane;
  mat2 planeJ = anchor.J;
#else
  vec2 plane = pixel;
  mat2 planeJ = mat2(1.0);
#endif

  float pattern = tone;
#if !defined(COMIC_HATCH)
  float angleStep = COMIC_FIXED_ANGLE_STEP;
#endif
#if defined(COMIC_DOTS) || defined(COMIC_HATCH)
#ifdef COMIC_DOTS
  vec4 dotCell = comicDotCells(plane, planeJ, comicDotDirection);
  vec2 dotUV = dotCell.xy;
  float dotAA = dotCell.z;
  float dotFade = dotCell.w;
  float dots = stylizeHalftoneDots(dotUV, tone, dotAA);
#else
  float dots = tone;
#endif
#ifdef COMIC_HATCH
  vec2 hatchUV = plane / comicHatchSpacing;
  mat2 hatchJ = planeJ / comicHatchSpacing; // d(hatchUV) / dx and / dy
  float hatchAA = clamp(0.5 * max(abs(hatchJ[0].x) + abs(hatchJ[1].x),
                                  abs(hatchJ[0].y) + abs(hatchJ[1].y)), 1e-4, 0.5);
  float angle = comicHatchAngle;
  // the layer FIGURE_INPUTS's record of the direction: COMIC_FIXED_ANGLE_STEP = comicHatchAngle
  float angleStep = COMIC_FIXED_ANGLE_STEP;
#ifdef COMIC_HATCH_PRINCIPAL
  // Around the form: the screen angle of the field's direction (larger |curvature|), in
  // comicHatchSteps steps over 180 degrees so that each region keeps straight lines.
  vec4 principal = texelFetch(comicField, p, 0);
  if (principal.w > 0.0)
  {
    vec2 f0 = vec2(p) + 0.5;
    vec2 s = fieldProject(fieldViewPosition(f0, principal.w) +
      principal.xyz * (1e-3 * fieldPixelWorldAt(principal.w))) - f0;
    if (dot(s, s) > 1e-12)
    {
      float stepAngle = COMIC_PI / float(max(comicHatchSteps, 1));
      float k = floor(atan(s.y, s.x) / stepAngle + 0.5);
      angle = stepAngle * k;
      angleStep = mod(k, float(max(comicHatchSteps, 1)));
    }
  }
#else
  if (comicHatchDirections > 0)
  {
    // eq. 12: the direction follows the screen-space normal, in steps of 180/n degrees
    vec3 n = texelFetch(stylizeNormalTexture, p, 0).xyz;
    if (dot(n.xy, n.xy) > 0.04)
    {
      float stepAngle = COMIC_PI / float(comicHatchDirections);
      float phi = atan(n.y, n.x);
      float k = floor(phi / stepAngle + 0.5);
      angle += stepAngle * k;
      angleStep = mod(k, float(comicHatchDirections));
    }
  }
#endif
  vec2 across = vec2(-sin(angle), cos(angle));
  // The line width: constant (eq. 11), or the tone's: one direction covers 1 - I, two crossed
  // directions of width 1 - sqrt(I) cover 1 - I together.
  float ink = clamp(1.0 - tone, 0.0, 1.0);
#ifdef COMIC_CROSS
  bool crossed = tone < comicCross;
  float width = comicHatchWidth > 0.0 ? comicHatchWidth
                                      : (crossed ? 1.0 - sqrt(clamp(tone, 0.0, 1.0)) : ink);
#else
  float width = comicHatchWidth > 0.0 ? comicHatchWidth : ink;
#endif
  float hatch = comicLines(dot(hatchUV, across), width, hatchAA);
  // the lines' frequency across them, cycles per pixel
  float hatchFrequency = length(across * hatchJ);
#ifdef COMIC_CROSS
  if (crossed)
  {
    vec2 along = vec2(across.y, -across.x);
    hatch = min(hatch, comicLines(dot(hatchUV, along), width, hatchAA));
    hatchFrequency = max(hatchFrequency, length(along * hatchJ));
  }
#endif
  float hatchFade = stylizePatternFade(hatchFrequency);
#else
  float hatch = tone;
#endif
  // Zones (eq. 13-14): dots above a1, hatching below a2, a continuous blend between.
  float t = comicBright > comicDark ? clamp((tone - comicDark) / (comicBright - comicDark), 0.0, 1.0)
                                    : step(comicDark, tone);
  // Below two pixels a cell cannot be drawn without aliasing (its dot or line falls between
  // pixels differently as the surface moves: moire on the still, flicker in an orbit), so the
  // pattern fades to its mean (the tone; the paper between lines of a fixed HatchWidth) as its
  // cells go from three pixels to two: anchored to the surface, where it turns away from the view;
  // on the screen, in a window much smaller than ReferenceHeight.
#if defined(COMIC_DOTS)
  dots = mix(dots, tone, dotFade);
#endif
#if defined(COMIC_HATCH)
  float hatchMean = 1.0 - clamp(width, 0.0, 1.0);
#ifdef COMIC_CROSS
  hatchMean *= crossed ? hatchMean : 1.0;
#endif
  hatch = mix(hatch, comicHatchWidth > 0.0 ? hatchMean : tone, hatchFade);
#endif
  pattern = mix(hatch, dots, t);
#endif
  // Beside an iso-line the patterns give way to the paper (the strokes' green channel, their
  // halo; 0 without iso-lines), so that the line reads over hatching and dots.
  float halo = 0.0;
#ifdef COMIC_FEATURE_LINES
  halo = clamp(texelFetch(comicFeatureInk, p, 0).g, 0.0, 1.0);
#endif
  pattern = mix(pattern, 1.0, halo);
  // Lines and points (unlit primitives: linear depth -1, streamlines, wireframes) are ink; the
  // paper stays.
  bool primitive = !surface && !background && linearDepth < 0.0;
  if (!surface)
  {
    pattern = background ? 1.0 : (primitive ? 0.0 : tone);
  }

#ifdef COMIC_TINTED
  // Keep the hue and saturation of the lit colour at full value: the data's colours stay
  // readable under the ink. The background keeps its own colour.
  float m = max(colour.r, max(colour.g, colour.b));
  vec3 paper = m > 1e-4 ? colour / m : vec3(1.0);
  // (a line's ink keeps its hue, darkened: a streamline coloured by its data stays readable)
  vec3 result = background ? colour * e : paper * ((primitive ? comicLineInk : pattern) * e);
#else
  vec3 result = background ? colour * e : vec3(pattern * e);
#endif
#if COMIC_LAYER == 1
  result = vec3(e);
#elif COMIC_LAYER == 2
  result = background ? colour : vec3(pattern);
#elif COMIC_LAYER == 3
  // what vtkStylizeFigureWriter draws the dots and hatch lines from: the tone, the hatch
  // direction's step (COMIC_FIXED_ANGLE_STEP: HatchAngle), 1 on surfaces
  // (the iso-lines' halo records the paper's tone: the figure's patterns give way there too)
  result = vec3(surface ? mix(tone, 1.0, halo) : 1.0, angleStep / 255.0, surface ? 1.0 : 0.0);
#elif COMIC_LAYER == 4
  // (lines and points, which carry no pattern, as the comic draws them)
#ifdef COMIC_TINTED
  result = background ? colour : (surface ? paper : paper * (primitive ? comicLineInk : pattern));
#else
  result = background ? colour : vec3(surface ? 1.0 : pattern);
#endif
#endif
  if (stylizeDiscardBackground == 1 && background && e >= 1.0)
  {
    discard;
  }
  // A fog's layer (vtkStylizeStylePass::GetTranslucentLayerEmitted()) has no surface to
  // outline, and its opacity is no plain gradient either: it is drawn as a screen of dots
  // covering that share of each cell (turned COMIC_FOG_SCREEN_ANGLE from the tone's dots, fading
  // to the mean below three pixels a cell like them), its ink (where its depth, normal or colour
  // jump: its shells' silhouettes) only within them, none beside it.
  float drawnAlpha = image.a;
  float drawnInk = 1.0 - e;
  if (comicEmittedLayer == 1)
  {
    vec4 fogCell = comicDotCells(plane, planeJ, stylizeRotate(comicDotDirection,
      vec2(cos(COMIC_FOG_SCREEN_ANGLE), sin(COMIC_FOG_SCREEN_ANGLE))));
    float opacity = clamp(image.a, 0.0, 1.0);
    float screen = 1.0 - stylizeHalftoneDots(fogCell.xy, 1.0 - opacity, fogCell.z);
    drawnAlpha = background ? 0.0 : mix(screen, opacity, fogCell.w);
    drawnInk = background ? 0.0 : (1.0 - e) * drawnAlpha;
  }
  gl_FragData[0] = stylizeOutput(background, result, drawnAlpha, drawnInk);
  gl_FragDepth = stylizeWindowDepth(depth);
}

#endif
