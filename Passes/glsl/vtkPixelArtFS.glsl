// VTK Stylize: the pixel-art stages (docs/algorithms.md section 1), one full-screen pass each.
// One stage is compiled per program, chosen by a define:
//   PIXEL_STAGE_REDUCE      (FAITHFUL) average each block of the full-resolution G-buffer
//   PIXEL_STAGE_GAUSS       gray = mean(R, G, B), the paper's 3x3 Gaussian (sigma = 1)
//   PIXEL_STAGE_GRADIENT    Sobel: (Gx, Gy, |G|)
//   PIXEL_STAGE_CLASSIFY    non-maximum suppression and double threshold (Canny) or threshold
//                           (Sobel); depth and normal edges. 1 strong, 0.5 weak, 0 none
//   PIXEL_STAGE_HYSTERESIS  one step: weak art pixels next to a strong one become strong
//   PIXEL_STAGE_STYLIZE     edges, 8x8 ordered dither, palette: the art-pixel image
//   PIXEL_STAGE_UPSAMPLE    each screen pixel takes its art pixel's colour; writes the depth
//                           (not run with PIXEL_BLIT_OUTPUT: the stylize stage writes output
//                           colours and a blit scales them onto the screen)
// Every stage but the last runs at the art-pixel resolution (pixelArtSize). Other defines:
//   PIXEL_FAST, PIXEL_CANNY, PIXEL_SOBEL, PIXEL_DEPTH_EDGES, PIXEL_NORMAL_EDGES, PIXEL_NORMALS,
//   PIXEL_POSITIONS, PIXEL_EDGES (an edge image exists), PIXEL_SURFACE_ANCHOR, PIXEL_TEXELS (the
//   surface's art pixels are texels fixed to it: the upsample stage reads full resolution),
//   PIXEL_STYLIZE_BACKGROUND, PIXEL_PALETTE (0 levels, 1 grays, 2 list), PIXEL_LAYER
//   (0 pixel art, 1 pixelated, 2 edges), PIXEL_BLIT_OUTPUT (the stylize stage writes output
//   colours), PIXEL_REDUCE_SAMPLES (the reduce stage's samples per axis, an ivec2).

// stylizeColorTexture (declared in vtkStylizeScreenFS) is the full-resolution lit colour, or the
// art pixels once they are reduced.
uniform sampler2D pixelInputTexture;         // the previous stage's output
uniform sampler2D pixelArtTexture;           // the art-pixel image (upsample)
uniform sampler2D pixelPaletteTexture;       // palette colours, N x 1

uniform ivec2 pixelArtSize;      // art pixels in this viewport (nx, ny)
uniform ivec2 pixelViewportSize; // screen pixels in this viewport (w, h)
uniform ivec2 pixelBlock;        // screen pixels per art pixel (x, y)
uniform ivec2 pixelGridOrigin;   // viewport pixel where art pixel (0, 0) starts (<= 0)
uniform ivec2 pixelExtentOrigin; // FAITHFUL: viewport pixel of the G-buffer's texel (0, 0)
uniform ivec2 pixelExtentSize;   // FAITHFUL: the G-buffer's size (the blocks' extent)
uniform ivec2 pixelDitherOrigin; // dither index of art pixel (0, 0)
uniform int pixelDitherSize;     // art pixels per matrix cell
uniform float pixelDitherStrength;
uniform int pixelLevels;         // K
uniform int pixelPaletteSize;    // colours in pixelPaletteTexture
uniform float pixelPaletteSpread; // median spacing of the palette's colours
uniform float pixelLow;          // Canny's low threshold
uniform float pixelHigh;         // Canny's high threshold (Sobel's threshold)
uniform float pixelDepthThreshold;
uniform float pixelNormalThreshold;
uniform float pixelArtWorld;     // world size of an art pixel: times depth (perspective) or as is
uniform int pixelParallel;
uniform float pixelAnchorUnit;   // world size of a dither cell (surface anchor)
uniform float pixelTexelUnit;    // world size of a texel, a surface-fixed art pixel
uniform vec3 pixelOutlineColor;
uniform int pixelEmittedLayer;   // 1: a translucent layer of emitted colours alone (a fog)

// This fragment's art pixel (art-resolution stages) from the quad's texture coordinate.
ivec2 pixelArtCoord()
{
  return clamp(ivec2(texCoord * vec2(pixelArtSize)), ivec2(0), pixelArtSize - 1);
}

// texelFetch clamped to the art-pixel grid (clamp-to-edge for the kernels).
vec4 pixelFetch(sampler2D tex, ivec2 p)
{
  return texelFetch(tex, clamp(p, ivec2(0), pixelArtSize - 1), 0);
}

#ifdef PIXEL_STAGE_REDUCE
// Sample ij of the block starting at G-buffer pixel lo, `extent` pixels with n samples per axis;
// ij may lie in a neighbouring block (the same spacing, continued).
ivec2 pixelSample(ivec2 lo, ivec2 extent, ivec2 n, ivec2 ij)
{
  return lo + ivec2(floor(vec2(ij * extent) / vec2(n)));
}

// The linear depth at G-buffer pixel p; 0 outside the G-buffer.
float pixelReduceDepth(ivec2 p)
{
  bool inside = all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, pixelExtentSize));
  return inside ? texelFetch(stylizeLinearDepthTexture, p, 0).r : 0.0;
}

// The samples of sample ij's surface (linear depth z) in a row along `dir` through it, itself
// included, counted up to `cap`: the row ends at the background, at a line and where the next
// sample lies behind by a step steeper than the depth-edge threshold (the surface's occluding
// edge). A nearer next sample continues the row: a surface turning away near its silhouette
// steepens towards it, and an occluder in front does not make the surface behind it thin.
int pixelRun(ivec2 lo, ivec2 extent, ivec2 n, ivec2 ij, ivec2 dir, float z, int cap)
{
  vec2 axis = vec2(abs(dir));
  float pixels = dot(vec2(extent) / vec2(n), axis); // screen pixels per step
  float slope = pixelDepthThreshold * pixelArtWorld * pixels / dot(vec2(pixelBlock), axis);
  int run = 1;
  for (int side = -1; side <= 1; side += 2)
  {
    float previous = z;
    for (int m = 1; m < cap && run < cap; ++m)
    {
      float zq = pixelReduceDepth(pixelSample(lo, extent, n, ij + side * m * dir));
      float gap = slope * (pixelParallel == 1 ? 1.0 : previous);
      if (!(zq > 0.0) || zq - previous > gap)
      {
        break;
      }
      previous = zq;
      ++run;
    }
  }
  return run;
}

// The means of a set of samples.
struct PixelSamples
{
  float count;
  vec3 colour;
  float opacity;
  float depth;
  vec3 normal;
  vec3 position;
};

void pixelAdd(inout PixelSamples s, ivec2 p, vec4 c4, float z)
{
  s.count += 1.0;
  s.colour += c4.rgb;
  s.opacity += clamp(c4.a, 0.0, 1.0);
  s.depth += z;
#ifdef PIXEL_NORMALS
  s.normal += texelFetch(stylizeNormalTexture, p, 0).xyz;
#endif
#ifdef PIXEL_POSITIONS
  s.position += texelFetch(stylizePositionTexture, p, 0).xyz;
#endif
}

// The art pixel's block of full-resolution pixels, clipped to the full image; blocks wider than
// 16 pixels are sampled at 16 evenly spaced pixels per axis. A sample is on a surface (linear
// depth > 0), on a line or point (unlit primitives: the G-buffer's linear depth -1), or on the
// background (0).
void pixelMain()
{
  ivec2 k = pixelArtCoord();
  ivec2 lo = max(pixelGridOrigin + k * pixelBlock - pixelExtentOrigin, ivec2(0));
  ivec2 hi = min(pixelGridOrigin + (k + 1) * pixelBlock - pixelExtentOrigin, pixelExtentSize);
  ivec2 extent = max(hi - lo, ivec2(1));
  ivec2 n = min(extent, ivec2(16));
  PixelSamples surface = PixelSamples(0.0, vec3(0.0), 0.0, 0.0, vec3(0.0), vec3(0.0));
  PixelSamples thin = surface;
  PixelSamples primitive = surface;
  vec3 backgroundColour = vec3(0.0);
  float zmin = 3.4e38;
  float zmax = 0.0;
  // Constant loop bounds (PIXEL_REDUCE_SAMPLES: min(block, 16) per axis) let the compiler
  // unroll the loops; a block clipped by the image's edge takes its own n samples.
  for (int j = 0; j < PIXEL_REDUCE_SAMPLES.y; ++j)
  {
    for (int i = 0; i < PIXEL_REDUCE_SAMPLES.x; ++i)
    {
      if (i >= n.x || j >= n.y)
      {
        continue;
      }
      ivec2 p = lo + (ivec2(i, j) * extent) / n;
      vec4 c4 = texelFetch(stylizeColorTexture, p, 0);
      float z = texelFetch(stylizeLinearDepthTexture, p, 0).r;
      if (z > 0.0)
      {
        pixelAdd(surface, p, c4, z);
        zmin = min(zmin, z);
        zmax = max(zmax, z);
      }
      else if (z < 0.0)
      {
        pixelAdd(primitive, p, c4, 0.0);
      }
      else
      {
        backgroundColour += c4.rgb;
      }
    }
  }
  float count = float(n.x * n.y);
  // Thin parts of surfaces (glyphs' shafts, wires): samples whose surface is at most half a block
  // across along x or y, bounded by the background, lines or depth steps (a convex silhouette's
  // cap, wider than that, is not thin). Sought only where the block holds more than one surface
  // or more than surfaces (an interior block pays nothing).
  float step = pixelDepthThreshold * pixelArtWorld; // the steepest surface in one art pixel
  bool mixed = surface.count < count ||
    zmax - zmin > step * (pixelParallel == 1 ? 1.0 : zmin);
  if (mixed && surface.count > 0.0 && primitive.count == 0.0)
  {
    ivec2 cap = n / 2 + 1; // thin: at most half a block across
    for (int j = 0; j < PIXEL_REDUCE_SAMPLES.y; ++j)
    {
      for (int i = 0; i < PIXEL_REDUCE_SAMPLES.x; ++i)
      {
        ivec2 ij = ivec2(i, j);
        ivec2 p = lo + (ij * extent) / n;
        float z = i < n.x && j < n.y ? texelFetch(stylizeLinearDepthTexture, p, 0).r : 0.0;
        if (z > 0.0 &&
          (pixelRun(lo, extent, n, ij, ivec2(1, 0), z, cap.x) < cap.x ||
            pixelRun(lo, extent, n, ij, ivec2(0, 1), z, cap.y) < cap.y))
        {
          pixelAdd(thin, p, texelFetch(stylizeColorTexture, p, 0), z);
        }
      }
    }
  }
  // A line or point in the block wins: lines and points are never dropped. Then an art pixel
  // belongs to the surface when at least half of its block does; it takes the mean of its
  // surface samples (hard silhouettes, no halo of background colour), otherwise the mean of its
  // background samples; a tie (exactly half) goes to the sample nearest the block's centre. Thin
  // parts win over the background and over the surfaces they lie in front of, so that they
  // stay at least one art pixel wide.
  ivec2 centre = clamp(lo + extent / 2, ivec2(0), pixelExtentSize - 1);
  bool centreOnSurface = texelFetch(stylizeLinearDepthTexture, centre, 0).r > 0.0;
  bool covered = surface.count > 0.5 * count || (surface.count == 0.5 * count && centreOnSurface);
  float rest = surface.count - thin.count;
  // (at least half a row of them: a thin part crossing the block, not a corner's tip clipping it)
  bool thinWins = thin.count >= 0.5 * float(min(n.x, n.y)) &&
    (!covered || rest == 0.0 || thin.depth / thin.count < (surface.depth - thin.depth) / rest);
  PixelSamples chosen = primitive.count > 0.0 ? primitive : (thinWins ? thin : surface);
  covered = covered || thinWins || primitive.count > 0.0;
  float m = max(chosen.count, 1.0);
  vec3 colour = covered ? chosen.colour / m : backgroundColour / max(count - surface.count, 1.0);
  // alpha: the surface's mean opacity (a translucent layer's), 0 on the background, plus 2 on
  // a thin part, line or point (drawn in its colour, not outlined); linear depth: -1 marks a
  // line or point
  float marked = thinWins || primitive.count > 0.0 ? 2.0 : 0.0;
  gl_FragData[0] = vec4(colour, covered ? marked + chosen.opacity / m : 0.0);
  float linear = primitive.count > 0.0 ? -1.0 : (covered ? chosen.depth / m : 0.0);
  gl_FragData[1] = vec4(linear, 0.0, 0.0, 1.0);
  bool solid = covered && primitive.count == 0.0;
#ifdef PIXEL_NORMALS
  float nl = length(chosen.normal);
  vec4 normalOut = solid && nl > 0.0 ? vec4(chosen.normal / nl, 1.0) : vec4(0.0, 0.0, 1.0, 0.0);
  gl_FragData[2] = normalOut;
#endif
#ifdef PIXEL_POSITIONS
  vec4 positionOut = solid ? vec4(chosen.position / m, 1.0) : vec4(0.0);
#ifdef PIXEL_NORMALS
  gl_FragData[3] = positionOut;
#else
  gl_FragData[2] = positionOut;
#endif
#endif
}
#endif

#ifdef PIXEL_STAGE_GAUSS
// Eq. 6: corner 0.0751136, edge 0.1238414, centre 0.2041799 (sigma = 1).
float pixelGray(ivec2 p)
{
  vec3 c = pixelFetch(stylizeColorTexture, p).rgb;
  return (c.r + c.g + c.b) / 3.0;
}
void pixelMain()
{
  ivec2 p = pixelArtCoord();
  float corners = pixelGray(p + ivec2(-1, -1)) + pixelGray(p + ivec2(1, -1)) +
    pixelGray(p + ivec2(-1, 1)) + pixelGray(p + ivec2(1, 1));
  float edges = pixelGray(p + ivec2(0, -1)) + pixelGray(p + ivec2(-1, 0)) +
    pixelGray(p + ivec2(1, 0)) + pixelGray(p + ivec2(0, 1));
  float g = 0.0751136 * corners + 0.1238414 * edges + 0.2041799 * pixelGray(p);
  gl_FragData[0] = vec4(g, 0.0, 0.0, 1.0);
}
#endif

#ifdef PIXEL_STAGE_GRADIENT
// Sobel with y up: Gx = right - left, Gy = top - bottom, weights 1 2 1.
void pixelMain()
{
  ivec2 p = pixelArtCoord();
  float a = pixelFetch(pixelInputTexture, p + ivec2(-1, 1)).r;
  float b = pixelFetch(pixelInputTexture, p + ivec2(0, 1)).r;
  float c = pixelFetch(pixelInputTexture, p + ivec2(1, 1)).r;
  float d = pixelFetch(pixelInputTexture, p + ivec2(-1, 0)).r;
  float f = pixelFetch(pixelInputTexture, p + ivec2(1, 0)).r;
  float g = pixelFetch(pixelInputTexture, p + ivec2(-1, -1)).r;
  float h = pixelFetch(pixelInputTexture, p + ivec2(0, -1)).r;
  float i = pixelFetch(pixelInputTexture, p + ivec2(1, -1)).r;
  float gx = (c + 2.0 * f + i) - (a + 2.0 * d + g);
  float gy = (a + 2.0 * b + c) - (g + 2.0 * h + i);
  gl_FragData[0] = vec4(gx, gy, sqrt(gx * gx + gy * gy), 1.0);
}
#endif

#ifdef PIXEL_STAGE_CLASSIFY
// Neighbour along the quantized gradient direction (0, 45, 90 or 135 degrees).
ivec2 pixelDirection(vec2 g)
{
  vec2 a = abs(g);
  const float t1 = 0.41421356; // tan(22.5 deg)
  const float t2 = 2.41421356; // tan(67.5 deg)
  if (a.y <= t1 * a.x)
  {
    return ivec2(1, 0);
  }
  if (a.y >= t2 * a.x)
  {
    return ivec2(0, 1);
  }
  return (g.x > 0.0) == (g.y > 0.0) ? ivec2(1, 1) : ivec2(-1, 1);
}

void pixelMain()
{
  ivec2 p = pixelArtCoord();
  float result = 0.0;
#if defined(PIXEL_CANNY) || defined(PIXEL_SOBEL)
  vec3 g = pixelFetch(pixelInputTexture, p).xyz;
#ifdef PIXEL_CANNY
  // Non-maximum suppression: a maximum along the gradient; on a plateau of equal magnitudes
  // (a step between two art pixels) the art pixel on the positive side is kept.
  ivec2 dir = pixelDirection(g.xy);
  float m = g.z;
  float ahead = pixelFetch(pixelInputTexture, p + dir).z;
  float behind = pixelFetch(pixelInputTexture, p - dir).z;
  float eps = 1e-5 * max(m, 1e-6);
  bool keep = m > 0.0 && m >= ahead - eps && m > behind + eps;
  float low = min(pixelLow, pixelHigh);
  result = !keep ? 0.0 : (m >= pixelHigh ? 1.0 : (m >= low ? 0.5 : 0.0));
#else
  result = g.z >= pixelHigh ? 1.0 : 0.0;
#endif
#endif
#if defined(PIXEL_DEPTH_EDGES) || defined(PIXEL_NORMAL_EDGES)
  float z = pixelFetch(stylizeLinearDepthTexture, p).r;
  if (z > 0.0)
  {
    const ivec2 offsets[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
#ifdef PIXEL_NORMAL_EDGES
    vec3 n = pixelFetch(stylizeNormalTexture, p).xyz;
#endif
    for (int i = 0; i < 4; ++i)
    {
      ivec2 q = p + offsets[i];
      if (q.x < 0 || q.y < 0 || q.x >= pixelArtSize.x || q.y >= pixelArtSize.y)
      {
        continue;
      }
      float zq = texelFetch(stylizeLinearDepthTexture, q, 0).r;
#ifdef PIXEL_DEPTH_EDGES
      // The slope against the screen: the depth step over the world size of an art pixel.
      // Background neighbours count as infinitely far; the nearer side is outlined.
      float world = pixelParallel == 1 ? pixelArtWorld : pixelArtWorld * z;
      if (!(zq > 0.0) || (zq > z && (zq - z) > pixelDepthThreshold * world))
      {
        result = 1.0;
      }
#endif
#ifdef PIXEL_NORMAL_EDGES
      // Creases: the one-sided difference, so the outline is one art pixel wide.
      if (zq > 0.0 && (i == 0 || i == 2) &&
        length(texelFetch(stylizeNormalTexture, q, 0).xyz - n) > pixelNormalThreshold)
      {
        result = 1.0;
      }
#endif
    }
  }
#endif
  gl_FragData[0] = vec4(result, 0.0, 0.0, 1.0);
}
#endif

#ifdef PIXEL_STAGE_HYSTERESIS
void pixelMain()
{
  ivec2 p = pixelArtCoord();
  float c = pixelFetch(pixelInputTexture, p).r;
  if (c > 0.25 && c < 0.75)
  {
    for (int j = -1; j <= 1; ++j)
    {
      for (int i = -1; i <= 1; ++i)
      {
        ivec2 q = p + ivec2(i, j);
        if (q.x >= 0 && q.y >= 0 && q.x < pixelArtSize.x && q.y < pixelArtSize.y &&
          texelFetch(pixelInputTexture, q, 0).r > 0.75)
        {
          c = 1.0;
        }
      }
    }
  }
  gl_FragData[0] = vec4(c, 0.0, 0.0, 1.0);
}
#endif

#if defined(PIXEL_STAGE_STYLIZE) || defined(PIXEL_TEXELS)
// Eq. 11: the threshold (M[R] - 0.5) / 64 of dither cell q.
float pixelThreshold(ivec2 q)
{
  return (float(stylizeBayer(q)) - 0.5) / 64.0;
}

vec3 pixelQuantize(vec3 c, float t)
{
#if PIXEL_PALETTE == 0
  float k = float(pixelLevels - 1);
  return min(floor(c * k + t), vec3(k)) / k;
#elif PIXEL_PALETTE == 1
  float k = float(pixelLevels - 1);
  float g = (c.r + c.g + c.b) / 3.0;
  return vec3(min(floor(g * k + t), k) / k);
#else
  vec3 target = c + (t - 0.5) * pixelPaletteSpread;
  vec3 best = vec3(0.0);
  float bestDistance = 1e30;
  for (int i = 0; i < pixelPaletteSize; ++i)
  {
    vec3 p = texelFetch(pixelPaletteTexture, ivec2(i, 0), 0).rgb;
    vec3 d = p - target;
    float e = dot(d, d);
    if (e < bestDistance)
    {
      bestDistance = e;
      best = p;
    }
  }
  return best;
#endif
}

#endif

#if defined(PIXEL_STAGE_STYLIZE) || defined(PIXEL_STAGE_UPSAMPLE)
// An art pixel (the stylize stage's rgb and alpha code) as the output pixel it becomes; q, its
// index on the tiles' common grid. In a translucent layer of the quantized picture an art pixel
// is all there or not at all (a screen door: its opacity against the Bayer matrix, shifted by
// the golden ratio for each layer so that the layers' doors interleave), so that the layers
// composite to the palette's colours; the PIXELATED layer blends.
vec4 pixelOutputColour(vec4 art, ivec2 q)
{
  // (a fog's layer has no surface to outline: its outline pixels are left out, as its paper is
  // where its opacity is low; vtkStylizeStylePass::GetTranslucentLayerEmitted())
  if (stylizeTranslucentLayer > 0 && pixelEmittedLayer == 1 && art.a > 1.75)
  {
    return vec4(0.0);
  }
  float opacity = clamp(2.0 * (art.a - 1.0), 0.0, 1.0);
  if (stylizeTranslucentLayer > 0 && PIXEL_LAYER != 1)
  {
    float t = fract((float(stylizeBayer(q)) - 0.5) / 64.0 + 0.618034 * float(stylizeTranslucentLayer - 1));
    opacity = opacity > t ? 1.0 : 0.0;
  }
  return stylizeOutput(art.a < 0.5, art.rgb, opacity, art.a > 1.75 ? 1.0 : 0.0);
}
#endif

#ifdef PIXEL_STAGE_STYLIZE
// Art pixel p holds a line or point (an unlit primitive, no surface) or a thin part of a
// surface: FAITHFUL's reduce stage marks them with 2 added to the alpha; at FAST's art
// resolution a line or point has the G-buffer's linear depth -1.
bool pixelPlain(ivec2 p)
{
#ifdef PIXEL_FAST
  return texelFetch(stylizeLinearDepthTexture, p, 0).r < 0.0;
#else
  return texelFetch(stylizeColorTexture, p, 0).a > 1.5;
#endif
}

// A colour edge on the background next to a plain art pixel (the halo Canny finds on both sides
// of a line one art pixel wide) and not next to an outlined surface.
bool pixelHalo(ivec2 p)
{
  bool plain = false;
  for (int j = -1; j <= 1; ++j)
  {
    for (int i = -1; i <= 1; ++i)
    {
      ivec2 q = clamp(p + ivec2(i, j), ivec2(0), pixelArtSize - 1);
      bool marked = pixelPlain(q);
      if (!marked && texelFetch(stylizeLinearDepthTexture, q, 0).r > 0.0)
      {
        return false;
      }
      plain = plain || marked;
    }
  }
  return plain;
}

void pixelMain()
{
  ivec2 p = pixelArtCoord();
  vec4 c4 = texelFetch(stylizeColorTexture, p, 0);
  vec3 c = stylizeSaturateFinite(c4.rgb);
  bool surface = texelFetch(stylizeLinearDepthTexture, p, 0).r > 0.0;
  // Lines, points and thin parts take the palette in their own colour, unoutlined.
  bool plain = pixelPlain(p);
  float alpha = c4.a > 1.5 ? c4.a - 2.0 : c4.a;
  float opacity = stylizeIsFinite(alpha) ? clamp(alpha, 0.0, 1.0) : 1.0;
#ifdef PIXEL_EDGES
  bool edge = !plain && texelFetch(pixelInputTexture, p, 0).r > 0.75 && (surface || !pixelHalo(p));
#else
  bool edge = false;
#endif

#if PIXEL_LAYER == 1
  vec3 result = c;
#elif PIXEL_LAYER == 2
  vec3 result = edge ? vec3(0.0) : vec3(1.0);
#else
#ifdef PIXEL_SURFACE_ANCHOR
  // (a dither cell never smaller than an art pixel: stylizeGridLevelScale)
  StylizeTriplanar anchor =
    stylizeTriplanarFrame(stylizePositionTexture, p, pixelArtSize, vec2(p + pixelDitherOrigin));
  vec2 anchorUnit = pixelAnchorUnit * stylizeGridLevelScale(anchor.J / pixelAnchorUnit);
  ivec2 cell = surface ? ivec2(floor(anchor.plane / anchorUnit)) :
                         (p + pixelDitherOrigin) / pixelDitherSize;
#else
  ivec2 q = p + pixelDitherOrigin;
  ivec2 cell = q / pixelDitherSize;
#endif
  // (a plain art pixel, one wide, is not dithered: its nearest palette colour)
  float t = plain ? 0.5 : 0.5 + (pixelThreshold(cell) - 0.5) * pixelDitherStrength;
  vec3 result = pixelQuantize(c, t);
#ifndef PIXEL_STYLIZE_BACKGROUND
  result = surface || plain ? result : c;
#endif
  result = edge ? pixelOutlineColor : result;
#endif
  // alpha: 2 for an outline, 1 + opacity / 2 for a surface, line or point (a translucent layer's
  // opacity is below 1), 0 for the background
  vec4 art = vec4(result, edge ? 2.0 : (surface || plain ? 1.0 + 0.5 * opacity : 0.0));
#ifdef PIXEL_BLIT_OUTPUT
  // the upsample's output colour, computed here once per art pixel and blitted to the screen
  gl_FragData[0] = pixelOutputColour(art, p + pixelDitherOrigin);
#else
  gl_FragData[0] = art;
#endif
}
#endif

#ifdef PIXEL_STAGE_UPSAMPLE
#ifdef PIXEL_TEXELS
// Texels: art pixels fixed to the surface, so that they move with it in an animation. Texel
// (i, j) of a surface point is the cell floor(plane / pixelTexelUnit) of its object-space
// position projected on the coordinate plane facing its geometric normal (triplanar). Every
// screen pixel of a texel takes the texel's mean lit colour (pixelTexelColour), dithered by the
// texel's matrix entry and quantized.
// Colour outlines are found on the texels too, so that they move with the surface: Canny's test
// along each texel axis on the grays at the neighbouring texels' centres (a step above the high
// threshold that is a maximum along that axis; no hysteresis). Silhouettes and occluding
// contours, which no texel holds still, are outlined on the screen: the surface pixels within one
// art pixel of the background or of a surface far behind. Normal edges (creases) are not drawn.

// A full-resolution channel at viewport pixel v; 0 outside the rendered extent.
vec4 pixelSceneFetch(sampler2D channel, ivec2 v)
{
  ivec2 e = v - pixelExtentOrigin;
  if (e.x < 0 || e.y < 0 || e.x >= pixelExtentSize.x || e.y >= pixelExtentSize.y)
  {
    return vec4(0.0);
  }
  return texelFetch(channel, e, 0);
}

// The object-space position at viewport pixel v (a = 0 off the surface).
vec4 pixelScenePosition(ivec2 v)
{
  return pixelSceneFetch(stylizePositionTexture, v);
}

// The position's change per screen pixel along one axis, central where both neighbours are on
// the surface, one-sided where one is, zero where neither is.
vec3 pixelPositionStep(vec4 pos, ivec2 v, ivec2 step)
{
  vec4 ahead = pixelScenePosition(v + step);
  vec4 behind = pixelScenePosition(v - step);
  if (ahead.a > 0.5 && behind.a > 0.5)
  {
    return 0.5 * (ahead.xyz - behind.xyz);
  }
  return ahead.a > 0.5 ? ahead.xyz - pos.xyz : (behind.a > 0.5 ? pos.xyz - behind.xyz : vec3(0.0));
}

struct PixelTexel
{
  bool found;     // the centre was found on the texel
  ivec2 cell;     // the texel's index on its plane
  ivec2 centre;   // the viewport pixel nearest its centre
  vec2 at;        // its centre, continuous (viewport pixels, pixel v's centre at v)
  int axis;       // the coordinate plane it lies on
  mat2 toScreen;  // screen pixels per texel step (the inverse of d(texel) / d(screen))
  vec2 unit;      // its world size along the plane's two axes: pixelTexelUnit at its levels
};

// The texel at viewport pixel v. Not found where the surface grazes the view or where the
// texel's centre is not on the same texel (a texel cut by a silhouette).
PixelTexel pixelTexelAt(ivec2 v)
{
  PixelTexel t;
  t.found = false;
  t.cell = ivec2(0);
  t.centre = v;
  t.at = vec2(v);
  t.axis = 2;
  t.toScreen = mat2(0.0);
  t.unit = vec2(pixelTexelUnit);
  vec4 pos = pixelScenePosition(v);
  vec3 dx = pixelPositionStep(pos, v, ivec2(1, 0));
  vec3 dy = pixelPositionStep(pos, v, ivec2(0, 1));
  vec3 gn = abs(cross(dx, dy));
  if (!(pos.a > 0.5) || !(max(gn.x, max(gn.y, gn.z)) > 0.0))
  {
    return t;
  }
  int axis = stylizeTriplanarAxis(gn);
  t.axis = axis;
  mat2 J0 = mat2(stylizePlaneCoordinates(dx, axis), stylizePlaneCoordinates(dy, axis)) /
    pixelTexelUnit;
  vec2 unit = pixelTexelUnit * stylizeGridLevelScale(J0);
  t.unit = unit;
  vec2 uv = stylizePlaneCoordinates(pos.xyz, axis) / unit;
  vec2 cell = floor(uv);
  if (!stylizeIsFinite(cell.x) || !stylizeIsFinite(cell.y) || abs(cell.x) > 1.0e9 ||
    abs(cell.y) > 1.0e9)
  {
    return t;
  }
  t.cell = ivec2(cell);
  // J = d(uv) / d(screen); the centre is J^-1 (cell + 1/2 - uv) away.
  mat2 J = mat2(stylizePlaneCoordinates(dx, axis) / unit, stylizePlaneCoordinates(dy, axis) / unit);
  float det = determinant(J);
  float scale = dot(J[0], J[0]) + dot(J[1], J[1]);
  if (!(abs(det) > 1.0e-3 * scale) || !stylizeIsFinite(det))
  {
    return t;
  }
  t.toScreen = inverse(J);
  float reach = 2.0 * float(max(pixelBlock.x, pixelBlock.y)) + 2.0;
  vec2 offset = clamp(t.toScreen * (cell + 0.5 - uv), vec2(-reach), vec2(reach));
  // One Newton step from the first guess corrects for the surface's curvature.
  vec4 guess = pixelScenePosition(v + ivec2(round(offset)));
  if (guess.a > 0.5)
  {
    vec2 guessUV = stylizePlaneCoordinates(guess.xyz, axis) / unit;
    offset = clamp(offset + t.toScreen * (cell + 0.5 - guessUV), vec2(-reach), vec2(reach));
  }
  t.at = vec2(v) + offset;
  t.centre = v + ivec2(round(offset));
  vec4 at = pixelScenePosition(t.centre);
  t.found = at.a > 0.5 && all(equal(floor(stylizePlaneCoordinates(at.xyz, axis) / unit), cell));
  return t;
}

// The texel's lit colour: the mean of the pixels at 3 x 3 points spread over it (those on the
// surface and on this texel), as the faithful art pixel is the mean of its block. One pixel's
// colour, the one nearest the centre, changes as the surface moves a fraction of a pixel (a
// scan's lighting varies from pixel to pixel), and would flip a texel near a quantization level.
vec4 pixelTexelColour(PixelTexel t)
{
  vec4 sum = vec4(0.0);
  float n = 0.0;
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      vec2 s = (vec2(i, j) - 1.0) / 3.0;
      ivec2 q = ivec2(round(t.at + t.toScreen * s));
      vec4 pos = pixelScenePosition(q);
      if (pos.a > 0.5 &&
        all(equal(floor(stylizePlaneCoordinates(pos.xyz, t.axis) / t.unit), vec2(t.cell))))
      {
        sum += pixelSceneFetch(stylizeColorTexture, q);
        n += 1.0;
      }
    }
  }
  return n > 0.0 ? sum / n : pixelSceneFetch(stylizeColorTexture, t.centre);
}

#ifdef PIXEL_EDGES
// The neighbouring texel's centre (i, j) texel steps away, estimated from this texel's own.
ivec2 pixelTexelStep(PixelTexel t, vec2 steps)
{
  vec2 offset = t.toScreen * steps;
  float reach = 4.0 * float(max(pixelBlock.x, pixelBlock.y)) + 4.0;
  return t.centre + ivec2(round(clamp(offset, vec2(-reach), vec2(reach))));
}

// The art pixels' smoothed gray (Canny's Gaussian, pixelInputTexture), bilinearly interpolated
// at viewport pixel v: a smooth field that a texel's neighbours sample without aliasing.
float pixelSceneGray(ivec2 v)
{
#if defined(PIXEL_CANNY) || defined(PIXEL_SOBEL)
  vec2 a = (vec2(v - pixelGridOrigin) + 0.5) / vec2(pixelBlock) - 0.5;
  ivec2 a0 = ivec2(floor(a));
  vec2 f = a - vec2(a0);
  float g00 = pixelFetch(pixelInputTexture, a0).r;
  float g10 = pixelFetch(pixelInputTexture, a0 + ivec2(1, 0)).r;
  float g01 = pixelFetch(pixelInputTexture, a0 + ivec2(0, 1)).r;
  float g11 = pixelFetch(pixelInputTexture, a0 + ivec2(1, 1)).r;
  return mix(mix(g00, g10, f.x), mix(g01, g11, f.x), f.y);
#else
  return 0.0;
#endif
}

// Linear depth at viewport pixel v, 0 off the surface and outside the rendered extent.
float pixelSceneDepth(ivec2 v)
{
  return pixelSceneFetch(stylizeLinearDepthTexture, v).r;
}

// Silhouettes and occluding contours at the screen's resolution: the pixel is within one art
// pixel of the background or of a surface far behind it (the nearer side is outlined).
bool pixelSilhouetteNear(ivec2 v)
{
  float z = pixelSceneDepth(v);
  float world = pixelParallel == 1 ? pixelArtWorld : pixelArtWorld * z;
  int reach = max(pixelBlock.x, pixelBlock.y);
  int steps = min(reach, 8);
  const ivec2 dirs[8] = ivec2[8](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1),
    ivec2(1, 1), ivec2(-1, 1), ivec2(1, -1), ivec2(-1, -1));
  for (int d = 0; d < 8; ++d)
  {
    for (int i = 1; i <= steps; ++i)
    {
      // diagonals reach as far as the sides (the art pixel's half-diagonal is not outlined)
      int r = (i * reach + steps - 1) / steps;
      ivec2 q = v + dirs[d] * (d < 4 ? r : max(1, (r * 7) / 10));
      float zq = pixelSceneDepth(q);
      if (!(zq > 0.0) || (zq > z && (zq - z) > pixelDepthThreshold * world))
      {
        return true;
      }
    }
  }
  return false;
}

bool pixelTexelOutline(PixelTexel t)
{
  const vec2 axes[2] = vec2[2](vec2(1.0, 0.0), vec2(0.0, 1.0));
  for (int a = 0; a < 2; ++a)
  {
    // The grays of the texels -2 .. 2 along this axis (off the surface: the nearer texel's).
    float f[5];
    f[2] = pixelSceneGray(t.centre);
    const int order[4] = int[4](-1, 1, -2, 2); // the nearer texels first
    for (int n = 0; n < 4; ++n)
    {
      int i = order[n];
      ivec2 q = pixelTexelStep(t, float(i) * axes[a]);
      f[i + 2] = pixelSceneDepth(q) > 0.0 ? pixelSceneGray(q) : f[i + 2 - sign(i)];
    }
#if defined(PIXEL_CANNY) || defined(PIXEL_SOBEL)
    // Sobel's response to a ramp is 8 times its slope per art pixel: the thresholds in slope.
    float m = 0.5 * abs(f[3] - f[1]) * 8.0;
#ifdef PIXEL_CANNY
    float ahead = 0.5 * abs(f[4] - f[2]) * 8.0;
    float behind = 0.5 * abs(f[2] - f[0]) * 8.0;
    float eps = 1e-5 * max(m, 1e-6);
    if (m >= pixelHigh && m >= ahead - eps && m > behind + eps)
    {
      return true;
    }
#else
    if (m >= pixelHigh)
    {
      return true;
    }
#endif
#endif
  }
  return false;
}
#endif
#endif

void pixelMain()
{
  ivec2 v = clamp(ivec2(texCoord * vec2(pixelViewportSize)), ivec2(0), pixelViewportSize - 1);
  ivec2 k = clamp((v - pixelGridOrigin) / pixelBlock, ivec2(0), pixelArtSize - 1);
  vec4 art = texelFetch(pixelArtTexture, k, 0);
#ifdef PIXEL_TEXELS
  if (pixelScenePosition(v).a > 0.5)
  {
    // A texel whose centre is not on it (cut by a silhouette, grazing) takes this pixel's colour
    // and its art pixel's dither entry.
    PixelTexel t = pixelTexelAt(v);
    vec4 c4 = t.found ? pixelTexelColour(t) : texelFetch(stylizeColorTexture, v - pixelExtentOrigin, 0);
    ivec2 cell =
      t.found ? ivec2(floor(vec2(t.cell) / float(pixelDitherSize))) : k + pixelDitherOrigin;
    float threshold = 0.5 + (pixelThreshold(cell) - 0.5) * pixelDitherStrength;
#ifdef PIXEL_EDGES
    bool outline = pixelSilhouetteNear(v) || (t.found && pixelTexelOutline(t));
#else
    bool outline = false;
#endif
    float opacity = stylizeIsFinite(c4.a) ? clamp(c4.a, 0.0, 1.0) : 1.0;
    vec3 colour = pixelQuantize(stylizeSaturateFinite(c4.rgb), threshold);
    art = outline ? vec4(pixelOutlineColor, 2.0) : vec4(colour, 1.0 + 0.5 * opacity);
  }
  else if (art.a >= 0.5)
  {
    // The background next to the surface: its own colour, not the art pixel's surface colour or
    // outline (the silhouettes are outlined on the surface's side above).
    vec3 c = stylizeSaturateFinite(texelFetch(stylizeColorTexture, v - pixelExtentOrigin, 0).rgb);
#ifdef PIXEL_STYLIZE_BACKGROUND
    c = pixelQuantize(c, 0.5 + (pixelThreshold(k + pixelDitherOrigin) - 0.5) * pixelDitherStrength);
#endif
    art = vec4(c, 0.0);
  }
#endif
  if (stylizeDiscardBackground == 1 && art.a < 0.5)
  {
    discard;
  }
  gl_FragData[0] = pixelOutputColour(art, k + pixelDitherOrigin);
#ifdef PIXEL_WRITE_DEPTH
#ifdef PIXEL_FAST
  float depth = texelFetch(stylizeDepthTexture, k, 0).r;
#else
  float depth = texelFetch(stylizeDepthTexture, v - pixelExtentOrigin, 0).r;
#endif
  gl_FragDepth = stylizeWindowDepth(depth);
#endif
}
#endif
