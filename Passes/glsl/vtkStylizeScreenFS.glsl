// VTK Stylize: helpers shared by the style passes' full-screen shaders.
#ifndef VTK_STYLIZE_SCREEN
#define VTK_STYLIZE_SCREEN

// The coordinate plane facing normal n (0: yz, 1: zx, 2: xy), and a point's coordinates on it:
// the two halves of a triplanar projection. Near-ties (within STYLIZE_TRIPLANAR_TIE of each
// other) go to the earlier plane: a facet at 45 degrees, common in meshes symmetric about a
// plane, would otherwise pick its plane pixel by pixel from the rounding of its normal.
#define STYLIZE_TRIPLANAR_TIE 1.0e-3
int stylizeTriplanarAxis(vec3 n)
{
  vec3 a = abs(n);
  float keep = 1.0 - STYLIZE_TRIPLANAR_TIE;
  return a.x >= keep * max(a.y, a.z) ? 0 : (a.y >= keep * a.z ? 1 : 2);
}

vec2 stylizePlaneCoordinates(vec3 p, int axis)
{
  return axis == 0 ? p.yz : (axis == 1 ? p.zx : p.xy);
}

// The step in object-space position from pixel p to its neighbour along d, on the same surface:
// of the forward and the backward difference, the shorter whose pixel is on a surface (a
// neighbour across a silhouette or a crease does not count). w = 0 where neither is.
vec4 stylizePositionStep(sampler2D positions, vec4 pos, ivec2 p, ivec2 size, ivec2 d)
{
  ivec2 a = p + d;
  ivec2 b = p - d;
  bool inA = all(greaterThanEqual(a, ivec2(0))) && all(lessThan(a, size));
  bool inB = all(greaterThanEqual(b, ivec2(0))) && all(lessThan(b, size));
  vec4 pa = inA ? texelFetch(positions, a, 0) : vec4(0.0);
  vec4 pb = inB ? texelFetch(positions, b, 0) : vec4(0.0);
  vec3 fa = pa.xyz - pos.xyz;
  vec3 fb = pos.xyz - pb.xyz;
  bool onA = inA && pa.a > 0.5;
  bool onB = inB && pb.a > 0.5;
  if (onA && onB)
  {
    return vec4(dot(fa, fa) <= dot(fb, fb) ? fa : fb, 1.0);
  }
  return onA ? vec4(fa, 1.0) : (onB ? vec4(fb, 1.0) : vec4(0.0));
}

// Triplanar projection of the object-space position stored at pixel p (a = 1 on surfaces) on
// the coordinate plane facing its geometric normal, found from the neighbouring positions, with
// its derivatives: J = (d plane / dx, d plane / dy), world units per pixel. The derivatives are
// this pixel's own, its neighbours' positions projected on its plane, so they do not jump where
// a neighbour projects on another plane as fwidth() over a 2 x 2 quad does; a pixel with no
// neighbour on its surface along x or y (a sliver) gets an unbounded one (STYLIZE_NO_STEP).
// Where there is no surface: plane = fallback, J = identity (the screen).
#define STYLIZE_NO_STEP 1.0e6
struct StylizeTriplanar
{
  vec2 plane;
  mat2 J;
};

StylizeTriplanar stylizeTriplanarFrame(sampler2D positions, ivec2 p, ivec2 size, vec2 fallback)
{
  StylizeTriplanar t;
  t.plane = fallback;
  t.J = mat2(1.0);
  vec4 pos = texelFetch(positions, p, 0);
  if (!(pos.a > 0.5))
  {
    return t;
  }
  vec4 dx = stylizePositionStep(positions, pos, p, size, ivec2(1, 0));
  vec4 dy = stylizePositionStep(positions, pos, p, size, ivec2(0, 1));
  vec3 gn = (dx.w > 0.5 && dy.w > 0.5) ? cross(dx.xyz, dy.xyz) : vec3(0.0, 0.0, 1.0);
  int axis = stylizeTriplanarAxis(gn);
  t.plane = stylizePlaneCoordinates(pos.xyz, axis);
  t.J = mat2(dx.w > 0.5 ? stylizePlaneCoordinates(dx.xyz, axis) : vec2(STYLIZE_NO_STEP),
    dy.w > 0.5 ? stylizePlaneCoordinates(dy.xyz, axis) : vec2(STYLIZE_NO_STEP));
  return t;
}

// The plane coordinates alone (stylizeTriplanarFrame).
vec2 stylizeTriplanar(sampler2D positions, ivec2 p, ivec2 size, vec2 fallback)
{
  return stylizeTriplanarFrame(positions, p, size, fallback).plane;
}

// How much of a periodic pattern to fade to its mean at `frequency`, its highest fundamental
// frequency on the screen (cycles per pixel): none up to a third (a period of three pixels),
// all at the Nyquist frequency (a half: two pixels), so that no pattern is drawn finer than the
// pixels can show (aliased into moire where a surface anchored pattern turns away from the view).
float stylizePatternFade(float frequency)
{
  return stylizeIsFinite(frequency) ? smoothstep(1.0 / 3.0, 0.5, frequency) : 1.0;
}

// Levels of detail of a grid fixed to the surface whose cell coordinates change by
// J = (d cell / dx, d cell / dy) per screen pixel: the factors 2^level (x: the cells' first
// axis, y: their second) that make a cell at least a pixel long on the screen along each axis
// where the surface turns away from the view (finer cells would alias: their colours and
// dither entries fall between the pixels differently as the surface moves). Each axis has its
// own level (a receding floor keeps its cells' width while their depth grows), in whole levels:
// a coarse cell is the union of fine ones.
vec2 stylizeGridLevelScale(mat2 J)
{
  vec2 frequency = vec2(length(vec2(J[0].x, J[1].x)), length(vec2(J[0].y, J[1].y)));
  vec2 level = vec2(0.0);
  for (int a = 0; a < 2; ++a)
  {
    float f = frequency[a];
    level[a] = stylizeIsFinite(f) && f > 1.0 ? min(ceil(log2(f)), 30.0) : 0.0;
  }
  return exp2(level);
}

// Sobel responses (gx, gy) of a 3x3 neighbourhood, divided by 8: the mean central difference
// per tap. Index: 0..8 = (-1,-1) (0,-1) (1,-1) (-1,0) (0,0) (1,0) (-1,1) (0,1) (1,1).
vec2 stylizeSobel(float v[9])
{
  float gx = (v[2] + 2.0 * v[5] + v[8]) - (v[0] + 2.0 * v[3] + v[6]);
  float gy = (v[6] + 2.0 * v[7] + v[8]) - (v[0] + 2.0 * v[1] + v[2]);
  return vec2(gx, gy) * 0.125;
}

// The ordered-dither matrix of the pixel-art paper (eq. 10, values 1..64), row-major: entry
// (y mod 8) * 8 + (x mod 8). Pixel art thresholds with it; the sketch pass staggers its stroke
// starts with it.
const int stylizeBayerMatrix[64] = int[64](
   1, 49, 13, 61,  4, 52, 16, 64,
  33, 17, 45, 29, 36, 20, 48, 32,
   9, 57,  5, 53, 12, 60,  8, 56,
  41, 25, 37, 21, 44, 28, 40, 24,
   3, 51, 15, 63,  2, 50, 14, 62,
  35, 19, 47, 31, 34, 18, 46, 30,
  11, 59,  7, 55, 10, 58,  6, 54,
  43, 27, 39, 23, 42, 26, 38, 22);

// The matrix entry (1..64) of cell q (two's complement: also right for negative cells).
int stylizeBayer(ivec2 q)
{
  ivec2 m = q & 7;
  return stylizeBayerMatrix[m.y * 8 + m.x];
}
#endif

// Rotates a 2D vector by the angle whose (cos, sin) is cs.
vec2 stylizeRotate(vec2 v, vec2 cs)
{
  return vec2(cs.x * v.x - cs.y * v.y, cs.y * v.x + cs.x * v.y);
}

// Halftone dots (the comic's eq. 10; vtkComicPatterns.h holds the constants, which a style
// that draws dots prepends as #defines): ink where the distance to the cell centre is below the
// radius whose disc covers 1 - I of the cell (continuous in I), anti-aliased over aa cell units, keeping the
// ink's area: the smooth edge adds 0.2 pi aa^2 to a disc, so the disc is drawn that much
// smaller, and a dot smaller than the smooth edge is a blob of radius aa, lighter by its
// excess (else the lightest tones would turn to gray specks where the cells are a few pixels
// wide). 1 = paper.
#ifdef COMIC_DOT_DISC_COVERAGE
float stylizeHalftoneDots(vec2 uv, float tone, float aa)
{
  vec2 f = fract(uv) - 0.5;
  float d = length(f);
  float coverage = clamp(1.0 - tone, 0.0, 1.0);
  // disc area pi r^2 = coverage up to r = 0.5; then the corners fill until r = sqrt(0.5)
  if (coverage > COMIC_DOT_DISC_COVERAGE)
  {
    float r = mix(COMIC_DOT_INSCRIBED_RADIUS, COMIC_DOT_CORNER_RADIUS,
      (coverage - COMIC_DOT_DISC_COVERAGE) / COMIC_DOT_CORNER_COVERAGE);
    return smoothstep(r - aa, r + aa, d);
  }
  float r2 = coverage / COMIC_PI;
  float big = r2 - 0.2 * aa * aa;
  if (big >= aa * aa)
  {
    float r = sqrt(big);
    return smoothstep(r - aa, r + aa, d);
  }
  float scale = r2 / (1.2 * aa * aa);
  return 1.0 - scale * (1.0 - smoothstep(0.0, 2.0 * aa, d));
}
#endif

// The G-buffer channels every style samples (vtkStylizeGBufferPass), and how a style's final
// stage writes the background (stylizeOutputAlpha() below, stylizeDiscardBackground).
uniform sampler2D stylizeColorTexture;       // lit colour
uniform sampler2D stylizeDepthTexture;       // window depth (written back as gl_FragDepth)
uniform sampler2D stylizeLinearDepthTexture; // -z_view, 0 where there is no surface
uniform sampler2D stylizeNormalTexture;      // view-space normal, a = 1 on surfaces
uniform sampler2D stylizePositionTexture;    // object-space position, a = 1 on surfaces
uniform int stylizeDiscardBackground; // 1 for layered renderers: keep the layer below

// Alpha of a style's output pixel. Surfaces are opaque. On the background, a scene that came
// from an image (vtkStylizeGBufferPass::SceneImagePass: a compositor such as IceT leaves the
// background transparent for the root to fill) keeps the image's alpha, plus the ink drawn
// there (outlines); a scene rendered from geometry is opaque everywhere.
uniform int stylizeSceneFromImage;
// rgb: the background the picture stands for (vtkStylizeGBufferPass::ImageBackground; the
// G-buffer's colour holds it on the background); a = 1 when set. stylizeRendererBackground: the
// renderer's background in this frame (what the image shows there: transparent black under
// compositing, the colour a transparent-background screenshot renders over).
uniform vec4 stylizeImageBackground;
uniform vec3 stylizeRendererBackground;

// The translucent layer the style draws (vtkStylizeStylePass::TranslucentLayers: 1 the nearest,
// 0 the opaque scene). In a layer the output is premultiplied, its alpha the surface's opacity (imageAlpha: the G-buffer colour's
// alpha) or the ink of the style's lines, whichever is more; on the layer's background the ink
// alone.
uniform int stylizeTranslucentLayer;

float stylizeOutputAlpha(bool background, float imageAlpha, float ink)
{
  return (background && stylizeSceneFromImage == 1) ? clamp(max(imageAlpha, ink), 0.0, 1.0) : 1.0;
}

// A style's output pixel: `rgb` is what the pixel shows over the scene's background, finite and
// saturated. Where the style computed over ImageBackground instead of the renderer's own
// background, the background's share of a pixel that is not opaque goes back to the renderer's:
// under compositing (transparent black) the colour is premultiplied, so that painting the
// background under it later gives `rgb`; in a transparent-background screenshot the pixel shows
// the colour it renders over, with the same ink.
vec4 stylizeOutput(bool background, vec3 rgb, float imageAlpha, float ink)
{
  vec3 colour = stylizeSaturateFinite(rgb);
  if (stylizeTranslucentLayer > 0)
  {
    float layerAlpha = background ? ink : max(imageAlpha, ink);
    layerAlpha = stylizeIsFinite(layerAlpha) ? clamp(layerAlpha, 0.0, 1.0) : 1.0;
    return vec4(colour * layerAlpha, layerAlpha);
  }
  float alpha = stylizeOutputAlpha(background, imageAlpha, ink);
  if (background && stylizeSceneFromImage == 1 && stylizeImageBackground.a > 0.5)
  {
    colour = clamp(colour + (1.0 - alpha) * (stylizeRendererBackground - stylizeImageBackground.rgb),
      0.0, 1.0);
  }
  return vec4(colour, alpha);
}

#ifdef STYLIZE_STAGE_LAYERS
// The translucent layers, stylized and composited front to back (premultiplied), laid over the
// stylized opaque scene (vtkStylizeStylePass::RenderTranslucentLayers()).
uniform sampler2D stylizeLayersTexture;
void stylizeLayersMain()
{
  ivec2 size = textureSize(stylizeLayersTexture, 0);
  ivec2 p = clamp(ivec2(texCoord * vec2(size)), ivec2(0), size - 1);
  vec4 layers = texelFetch(stylizeLayersTexture, p, 0);
  gl_FragData[0] = clamp(layers, 0.0, 1.0);
}
#endif

#ifdef STYLIZE_STAGE_BACKGROUND
// The background as every style's final stage writes it, for the pixels away from the scene
// (vtkStylizeStylePass::RenderStageToOutput()): the saturated colour with the background's
// alpha and depth; layered renderers keep the layer below.
void stylizeBackgroundMain()
{
  ivec2 size = textureSize(stylizeColorTexture, 0);
  ivec2 p = clamp(ivec2(texCoord * vec2(size)), ivec2(0), size - 1);
  if (stylizeDiscardBackground == 1)
  {
    discard;
  }
  vec4 image = texelFetch(stylizeColorTexture, p, 0);
  gl_FragData[0] = stylizeOutput(true, image.rgb, image.a, 0.0);
  gl_FragDepth = stylizeWindowDepth(texelFetch(stylizeDepthTexture, p, 0).r);
}
#endif
