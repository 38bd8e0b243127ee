// VTK Stylize sketch pass (vtkSketchPass): per-pixel principal directions by focal surfaces,
// perspective-correct line integral convolution of solid noise, pencil tone.
// docs/algorithms.md section 3. The pass prepends #defines that select what is compiled:
//   SKETCH_STAGE_ESTIMATE  raw direction e (the principal direction of the smaller |curvature|)
//                          and its confidence, from the G-buffer (focal surfaces or the mapped
//                          direction attribute)
//   SKETCH_STAGE_SMOOTH    one sign-invariant smoothing or fill iteration of the raw field
//   SKETCH_STAGE_RESOLVE   fallbacks for undefined pixels, then the requested direction; writes
//                          the final field (xyz view-space unit direction, w linear depth)
//   SKETCH_STAGE_BLUR_X, SKETCH_STAGE_BLUR_Y   the strided Gaussian blur of the lit luminance
//   SKETCH_STAGE_FINAL     strokes (LIC) and tone into the output
//   SKETCH_NEIGHBORS 2|4|8, SKETCH_MODEL, SKETCH_DIRECTION 0|1|2 (minimum, maximum, bisector),
//   SKETCH_NOISE_SCREEN, SKETCH_SCREEN_LIC, SKETCH_CROSS, SKETCH_CONTRAST, SKETCH_TINTED,
//   SKETCH_LAYER 0|1|2|3 (sketch, directions, strokes, tone)
// Lengths arrive in pixels of this viewport or in world units, converted on the CPU.

uniform sampler2D stylizeDirectionTexture;   // G-buffer DIRECTION channel (model-space mode)

uniform ivec2 sketchSize;        // viewport size (pixels)
uniform vec2 sketchPixelOffset;  // this tile's offset in the full image (pixels)
uniform int sketchParallel;      // 1 for parallel projection
uniform float sketchPixelWorld;  // world size of a pixel: times depth (perspective) or as is
uniform vec4 sketchProjection;   // P00, P11, P02, P12 of the camera's projection
uniform vec2 sketchProjOffset;   // P03, P13

// ---- camera helpers -------------------------------------------------------------------------
// Normalized device coordinates of continuous pixel position f (pixel centres at i + 0.5).
vec2 sketchNDC(vec2 f)
{
  return f / vec2(sketchSize) * 2.0 - 1.0;
}

// View-space position of the surface seen at pixel position f at linear depth d.
vec3 sketchViewPosition(vec2 f, float d)
{
  vec2 ndc = sketchNDC(f);
  vec2 xy = sketchParallel == 1 ? (ndc - sketchProjOffset) / sketchProjection.xy
                                : d * (ndc + sketchProjection.zw) / sketchProjection.xy;
  return vec3(xy, -d);
}

// Continuous pixel position of view-space point v.
vec2 sketchProject(vec3 v)
{
  vec2 ndc = sketchParallel == 1
    ? sketchProjection.xy * v.xy + sketchProjOffset
    : (sketchProjection.xy * v.xy + sketchProjection.zw * v.z) / max(-v.z, 1e-30);
  return (ndc + 1.0) * 0.5 * vec2(sketchSize);
}

float sketchPixelWorldAt(float d)
{
  return sketchParallel == 1 ? sketchPixelWorld : sketchPixelWorld * d;
}

// A tangent frame (x, y) of unit normal n, continuous away from n = +-x.
void sketchFrame(vec3 n, out vec3 x, out vec3 y)
{
  vec3 a = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  x = normalize(a - n * dot(a, n));
  y = cross(n, x);
}

float sketchLuminance(vec3 c)
{
  return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

ivec2 sketchPixel()
{
  return clamp(ivec2(texCoord * vec2(sketchSize)), ivec2(0), sketchSize - 1);
}

// Linear depth d and normal n of pixel p; false on the background and on lines and points.
bool sketchSurfaceAt(ivec2 p, out float d, out vec3 n)
{
  d = texelFetch(stylizeLinearDepthTexture, p, 0).r;
  vec4 n4 = texelFetch(stylizeNormalTexture, p, 0);
  n = n4.xyz;
  return d > 0.0 && n4.a >= 0.5;
}

// The doubled-angle vector (x^2 - y^2, 2 x y) = |v|^2 (cos 2a, sin 2a): v and -v give the same.
vec2 sketchDoubled(vec2 v)
{
  return vec2(v.x * v.x - v.y * v.y, 2.0 * v.x * v.y);
}

bool sketchInside(ivec2 q)
{
  return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, sketchSize));
}

// ---- stage 1: raw directions ----------------------------------------------------------------
#ifdef SKETCH_STAGE_ESTIMATE
uniform float sketchSpacing;     // world floor of the neighbour spacing
uniform int sketchMaxStride;     // pixels
uniform float sketchPlanar;      // |kappa| h below which a pair counts as planar
uniform float sketchUmbilic;     // confidence below which a pixel is undefined

// Neighbour q seen from centre x (normal n, tangent frame X, Y): where its normal ray crosses the
// tangent plane (u) and the ray's direction scaled to unit height (m). False when q is off the
// surface (background, another surface, a fold).
bool sketchNeighbor(ivec2 q, vec3 x, vec3 n, vec3 X, vec3 Y, out vec2 u, out vec2 m)
{
  u = vec2(0.0);
  m = vec2(0.0);
  if (!sketchInside(q))
  {
    return false;
  }
  float d;
  vec3 nq;
  if (!sketchSurfaceAt(q, d, nq))
  {
    return false;
  }
  vec3 dp = sketchViewPosition(vec2(q) + 0.5, d) - x;
  vec2 t = vec2(dot(dp, X), dot(dp, Y));
  float h = dot(dp, n);
  float mz = dot(nq, n);
  if (!(mz > 0.5) || !(abs(h) <= length(t)))
  {
    return false;
  }
  m = vec2(dot(nq, X), dot(nq, Y)) / mz;
  u = t - h * m;
  return true;
}

float sketchCross(vec2 a, vec2 b)
{
  return a.x * b.y - a.y * b.x;
}

// One neighbour pair: the focal quadratic in kappa = 1 / lambda,
//   c kappa^2 + b kappa + a = 0,
// root of the larger |kappa|; the rays' points at that focal height lie along the principal
// direction of the smaller |kappa|: r = kappa u + m (the point times kappa: no overflow on flat
// ground). Accumulates their doubled angles (total least squares through the origin), each
// scaled by 1 / (kappa h)^2 so that an umbilic pair (r ~ 0) weighs nothing.
void sketchPair(vec2 u1, vec2 m1, bool ok1, vec2 u2, vec2 m2, bool ok2, inout vec3 acc)
{
  if (!ok1 || !ok2)
  {
    return;
  }
  float a = sketchCross(m1, m2);
  float b = sketchCross(u1, m2) + sketchCross(m1, u2);
  float c = sketchCross(u1, u2);
  float h2 = 0.5 * (dot(u1, u1) + dot(u2, u2));
  if (!(abs(c) > 0.05 * h2)) // neighbours collinear with the centre
  {
    return;
  }
  float disc = b * b - 4.0 * a * c;
  if (disc < 0.0)
  {
    return;
  }
  float sq = sqrt(disc);
  float kappa = (b >= 0.0 ? (-b - sq) : (-b + sq)) / (2.0 * c);
  float kh2 = kappa * kappa * h2;
  if (!(kh2 > sketchPlanar * sketchPlanar) || isinf(kh2))
  {
    return;
  }
  vec2 r1 = kappa * u1 + m1;
  vec2 r2 = kappa * u2 + m2;
  acc.xy += (sketchDoubled(r1) + sketchDoubled(r2)) / kh2;
  acc.z += 2.0;
}

void sketchMain()
{
  ivec2 p = sketchPixel();
  float d0;
  vec3 n;
  if (!sketchSurfaceAt(p, d0, n))
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
#ifdef SKETCH_MODEL
  // The mapped direction where the data gives one with confidence (its vertices agree), else
  // the screen estimate.
  vec4 given = texelFetch(stylizeDirectionTexture, p, 0);
  if (given.a > sketchUmbilic)
  {
    gl_FragData[0] = vec4(given.xyz, max(given.a, 1e-3));
    return;
  }
#endif
  vec3 X, Y;
  sketchFrame(n, X, Y);
  vec3 x = sketchViewPosition(vec2(p) + 0.5, d0);
  // The stride keeps neighbours at least sketchSpacing apart in world units.
  int s = int(clamp(ceil(sketchSpacing / sketchPixelWorldAt(d0)), 1.0, float(sketchMaxStride)));
  vec2 uR, mR, uU, mU, uL, mL, uD, mD;
  bool okR = sketchNeighbor(p + ivec2(s, 0), x, n, X, Y, uR, mR);
  bool okU = sketchNeighbor(p + ivec2(0, s), x, n, X, Y, uU, mU);
  vec3 acc = vec3(0.0);
  sketchPair(uR, mR, okR, uU, mU, okU, acc);
#if SKETCH_NEIGHBORS >= 4
  bool okL = sketchNeighbor(p - ivec2(s, 0), x, n, X, Y, uL, mL);
  bool okD = sketchNeighbor(p - ivec2(0, s), x, n, X, Y, uD, mD);
  sketchPair(uU, mU, okU, uL, mL, okL, acc);
  sketchPair(uL, mL, okL, uD, mD, okD, acc);
  sketchPair(uD, mD, okD, uR, mR, okR, acc);
#endif
#if SKETCH_NEIGHBORS >= 8
  vec2 u1, m1, u2, m2, u3, m3, u4, m4;
  bool ok1 = sketchNeighbor(p + ivec2(s, s), x, n, X, Y, u1, m1);
  bool ok2 = sketchNeighbor(p + ivec2(-s, s), x, n, X, Y, u2, m2);
  bool ok3 = sketchNeighbor(p + ivec2(-s, -s), x, n, X, Y, u3, m3);
  bool ok4 = sketchNeighbor(p + ivec2(s, -s), x, n, X, Y, u4, m4);
  sketchPair(u1, m1, ok1, u2, m2, ok2, acc);
  sketchPair(u2, m2, ok2, u3, m3, ok3, acc);
  sketchPair(u3, m3, ok3, u4, m4, ok4, acc);
  sketchPair(u4, m4, ok4, u1, m1, ok1, acc);
#endif
  float confidence = acc.z > 0.0 ? min(1.0, length(acc.xy) / acc.z) : 0.0;
  if (!(confidence > sketchUmbilic))
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
  float theta = 0.5 * atan(acc.y, acc.x);
  gl_FragData[0] = vec4(X * cos(theta) + Y * sin(theta), confidence);
}
#endif

// ---- stage 2: smoothing and fill ------------------------------------------------------------
#ifdef SKETCH_STAGE_SMOOTH
uniform sampler2D sketchInput; // xyz direction, w confidence (> 0 defined, < 0 filled, 0 none)
uniform int sketchRadius;      // tap distance (pixels)
uniform int sketchFillOnly;    // 1: defined pixels keep their value (fill iterations)

void sketchMain()
{
  ivec2 p = sketchPixel();
  vec4 c = texelFetch(sketchInput, p, 0);
  float d0;
  vec3 n;
  if (!sketchSurfaceAt(p, d0, n) || (sketchFillOnly == 1 && c.w != 0.0))
  {
    gl_FragData[0] = c;
    return;
  }
  vec3 X, Y;
  sketchFrame(n, X, Y);
  vec3 x = sketchViewPosition(vec2(p) + 0.5, d0);
  // Doubled angles in this pixel's tangent frame: d and -d count the same.
  vec3 acc = vec3(0.0);
  for (int j = -1; j <= 1; ++j)
  {
    for (int i = -1; i <= 1; ++i)
    {
      ivec2 q = p + ivec2(i, j) * sketchRadius;
      if (!sketchInside(q))
      {
        continue;
      }
      vec4 e = texelFetch(sketchInput, q, 0);
      if (e.w == 0.0)
      {
        continue;
      }
      if (i != 0 || j != 0)
      {
        // same surface: a similar normal, and close to this pixel's tangent plane
        vec4 nq = texelFetch(stylizeNormalTexture, q, 0);
        float dq = texelFetch(stylizeLinearDepthTexture, q, 0).r;
        vec3 dp = sketchViewPosition(vec2(q) + 0.5, dq) - x;
        if (nq.a < 0.5 || dot(nq.xyz, n) < 0.7 || abs(dot(dp, n)) > 0.5 * length(dp))
        {
          continue;
        }
      }
      vec2 v = vec2(dot(e.xyz, X), dot(e.xyz, Y));
      float l2 = dot(v, v);
      if (!(l2 > 1e-8))
      {
        continue;
      }
      float w = abs(e.w) * ((i == 0 && j == 0) ? 1.0 : 0.5);
      acc += vec3(sketchDoubled(v) / l2, 1.0) * w;
    }
  }
  float len = length(acc.xy);
  if (!(len > 1e-6 * acc.z) || !(acc.z > 0.0))
  {
    gl_FragData[0] = c.w != 0.0 ? c : vec4(0.0);
    return;
  }
  float theta = 0.5 * atan(acc.y, acc.x);
  float confidence = max(len / acc.z, 1e-3);
  gl_FragData[0] = vec4(X * cos(theta) + Y * sin(theta), c.w > 0.0 ? confidence : -confidence);
}
#endif

// ---- stage 3: fallbacks and the requested direction -----------------------------------------
#ifdef SKETCH_STAGE_RESOLVE
uniform sampler2D sketchInput;
uniform int sketchGradientStride; // Sobel tap distance of the lighting-gradient fallback
uniform vec2 sketchScreenDirection; // the last resort: a fixed screen direction

void sketchMain()
{
  ivec2 p = sketchPixel();
  float d0;
  vec3 n;
  if (!sketchSurfaceAt(p, d0, n))
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
  vec4 c = texelFetch(sketchInput, p, 0);
  vec3 e = c.xyz - n * dot(c.xyz, n);
  bool defined = c.w != 0.0 && dot(e, e) > 1e-8;
  vec3 result;
  if (defined)
  {
    e = normalize(e);
#if SKETCH_DIRECTION == 0
    result = e;
#elif SKETCH_DIRECTION == 1
    result = cross(n, e);
#else
    result = normalize(e + cross(n, e));
#endif
  }
  else
  {
    // Planar or umbilic and nothing to fill from: strokes along the isophotes of the lit image
    // (perpendicular to its Sobel gradient at the gradient stride), else a fixed screen
    // direction.
    int s = sketchGradientStride;
    float l[9];
    for (int b = 0; b < 9; ++b)
    {
      ivec2 t = clamp(p + ivec2(b % 3 - 1, b / 3 - 1) * s, ivec2(0), sketchSize - 1);
      l[b] = b == 4 ? 0.0 : sketchLuminance(texelFetch(stylizeColorTexture, t, 0).rgb);
    }
    vec2 g = stylizeSobel(l);
    vec2 screen = dot(g, g) > 1e-10 ? normalize(vec2(-g.y, g.x)) : sketchScreenDirection;
    vec3 v = vec3(screen, 0.0);
    result = v - n * dot(v, n);
    if (!(dot(result, result) > 1e-8))
    {
      result = cross(n, vec3(0.0, 0.0, 1.0));
      result = dot(result, result) > 1e-8 ? result : vec3(1.0, 0.0, 0.0);
    }
    result = normalize(result);
  }
  gl_FragData[0] = vec4(result, d0);
}
#endif

// ---- stage 4: strided Gaussian blur of the lit luminance ------------------------------------
#if defined(SKETCH_STAGE_BLUR_X) || defined(SKETCH_STAGE_BLUR_Y)
uniform sampler2D sketchInput;  // BLUR_Y: the BLUR_X output
uniform int sketchBlurStride;   // k: one low-resolution texel per k x k pixels, taps k apart
uniform float sketchBlurSigma;  // pixels
uniform int sketchBlurTaps;     // taps on each side
uniform ivec2 sketchBlurSize;   // the low-resolution size

void sketchMain()
{
  ivec2 p = clamp(ivec2(texCoord * vec2(sketchBlurSize)), ivec2(0), sketchBlurSize - 1);
  float sum = 0.0;
  float wsum = 0.0;
  for (int t = -sketchBlurTaps; t <= sketchBlurTaps; ++t)
  {
    float dx = float(t * sketchBlurStride);
    float w = exp(-0.5 * dx * dx / (sketchBlurSigma * sketchBlurSigma));
#ifdef SKETCH_STAGE_BLUR_X
    ivec2 q = clamp(p * sketchBlurStride + sketchBlurStride / 2 + ivec2(t * sketchBlurStride, 0),
      ivec2(0), sketchSize - 1);
    float v = sketchLuminance(texelFetch(stylizeColorTexture, q, 0).rgb);
#else
    ivec2 q = clamp(p + ivec2(0, t), ivec2(0), sketchBlurSize - 1);
    float v = texelFetch(sketchInput, q, 0).r;
#endif
    sum += w * v;
    wsum += w;
  }
  gl_FragData[0] = vec4(sum / wsum, 0.0, 0.0, 1.0);
}
#endif

// ---- stage 5: strokes and tone --------------------------------------------------------------
#ifdef SKETCH_STAGE_FINAL
uniform sampler2D sketchField;   // the resolved field: xyz view-space direction, w linear depth
uniform sampler2D sketchBlur;    // the blurred luminance (linear filtering)
uniform sampler3D sketchNoise;   // tileable solid noise
uniform vec2 sketchNoiseStats;   // mean and standard deviation of the noise texture
uniform float sketchNoiseScale;  // noise texels per object unit (per pixel: screen noise)
uniform float sketchStepPixels;  // LIC step, pixels at the stroke's start
uniform int sketchSteps;         // LIC steps on each side
uniform float sketchStrokeContrast;
uniform float sketchContrast;    // contrast against the blurred image
uniform vec2 sketchBright;       // t1, t2
uniform float sketchCross;       // cross-hatching below this tone
uniform vec3 sketchPencil;
uniform vec3 sketchPaper;

// The field at continuous pixel position f, bilinear over the taps on the stroke's surface
// (depth within tol of the expected depth), directions flipped to agree with ref. w = 0: none.
vec4 sketchFieldAt(vec2 f, vec3 ref, float expected, float tol)
{
  vec2 g = f - 0.5;
  vec2 fl = floor(g);
  vec2 t = g - fl;
  ivec2 i0 = ivec2(fl);
  vec4 acc = vec4(0.0);
  float wsum = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    ivec2 o = ivec2(k & 1, k >> 1);
    ivec2 q = clamp(i0 + o, ivec2(0), sketchSize - 1);
    vec4 e = texelFetch(sketchField, q, 0);
    float w = (o.x == 1 ? t.x : 1.0 - t.x) * (o.y == 1 ? t.y : 1.0 - t.y);
    if (!(e.w > 0.0) || abs(e.w - expected) > tol)
    {
      continue;
    }
    acc += w * vec4(dot(e.xyz, ref) < 0.0 ? -e.xyz : e.xyz, e.w);
    wsum += w;
  }
  return wsum > 1e-4 ? acc / wsum : vec4(0.0);
}

float sketchNoiseAt(vec2 f)
{
#ifdef SKETCH_NOISE_SCREEN
  return texture(sketchNoise, vec3((f + sketchPixelOffset) * sketchNoiseScale, 0.5)).r;
#else
  vec4 pos = texelFetch(stylizePositionTexture, clamp(ivec2(f), ivec2(0), sketchSize - 1), 0);
  return texture(sketchNoise, pos.xyz * sketchNoiseScale).r;
#endif
}

// Line integral convolution of the noise through pixel p (view position x0) along dir0 (or, for
// cross-hatching, along n0 x dir). Perspective-correct: each step moves in world space along the
// surface, is projected back to the screen, and snaps to the surface seen there. The starts are
// staggered by the ordered-dither matrix. Returns the stroke value, 0.5 on average.
float sketchStroke(ivec2 p, vec3 x0, vec3 dir0, vec3 n0, bool across)
{
  float pw = sketchPixelWorldAt(-x0.z);
  float stepWorld = sketchStepPixels * pw;
  float tol = 2.0 * stepWorld + 2.0 * pw;
  float o = (float(stylizeBayer(p + ivec2(sketchPixelOffset))) - 0.5) / 64.0;
  vec2 f0 = vec2(p) + 0.5;
  float sum = 0.0;
  float wsum = 0.0;
  float w2sum = 0.0;
  float kernel = float(sketchSteps) + 1.0;
  for (int side = 0; side < 2; ++side)
  {
    vec3 d = across ? cross(n0, dir0) : dir0;
    d = side == 0 ? d : -d;
    float along = side == 0 ? o : 1.0 - o;
    vec3 pos = x0 + d * (along * stepWorld);
    vec2 f = f0;
#ifdef SKETCH_SCREEN_LIC
    // The classic 2D LIC baseline: the direction projected once, without the perspective
    // division's dependence on depth, and steps of one pixel length on the screen.
    vec2 d2 = normalize(sketchProjection.xy * d.xy + vec2(1e-12, 0.0));
    f = f0 + d2 * along * sketchStepPixels;
#endif
    for (int k = 0; k < sketchSteps; ++k)
    {
#ifndef SKETCH_SCREEN_LIC
      f = sketchProject(pos);
#endif
      if (any(lessThan(f, vec2(0.0))) || any(greaterThanEqual(f, vec2(sketchSize))))
      {
        break;
      }
#ifdef SKETCH_SCREEN_LIC
      vec4 e = sketchFieldAt(f, vec3(d2, 0.0), texelFetch(sketchField, ivec2(f), 0).w, 1e30);
#else
      vec4 e = sketchFieldAt(f, d, -pos.z, tol);
#endif
      if (!(e.w > 0.0))
      {
        break; // the stroke left the surface
      }
      float w = 1.0 - (float(k) + along) / kernel;
      float v = sketchNoiseAt(f);
      sum += w * v;
      wsum += w;
      w2sum += w * w;
      vec3 nd = e.xyz;
      if (across)
      {
        nd = cross(n0, nd);
      }
      nd = dot(nd, d) < 0.0 ? -nd : nd;
#ifdef SKETCH_SCREEN_LIC
      vec2 nd2 = sketchProjection.xy * nd.xy;
      if (dot(nd2, nd2) > 1e-12)
      {
        nd2 = normalize(nd2);
        d2 = dot(nd2, d2) < 0.0 ? -nd2 : nd2;
      }
      d = nd;
      f += d2 * sketchStepPixels;
#else
      pos = sketchViewPosition(f, e.w); // back onto the surface seen at f
      d = dot(nd, nd) > 1e-8 ? normalize(nd) : d;
      pos += d * stepWorld;
#endif
    }
  }
  if (!(wsum > 0.0))
  {
    return 0.5 + (sketchNoiseAt(f0) - sketchNoiseStats.x) * 0.25 * sketchStrokeContrast /
      max(sketchNoiseStats.y, 1e-4);
  }
  // Normalize: the weighted mean of independent samples has deviation sigma sqrt(w2) / w.
  float z = (sum / wsum - sketchNoiseStats.x) /
    max(sketchNoiseStats.y * sqrt(w2sum) / wsum, 1e-4);
  return clamp(0.5 + 0.25 * sketchStrokeContrast * z, 0.0, 1.0);
}

void sketchMain()
{
  ivec2 p = sketchPixel();
  vec4 image = texelFetch(stylizeColorTexture, p, 0);
  vec3 colour = image.rgb;
  float depth = texelFetch(stylizeDepthTexture, p, 0).r;
  vec4 field = texelFetch(sketchField, p, 0);
  vec3 n0 = texelFetch(stylizeNormalTexture, p, 0).xyz;
  bool background = !(depth < 1.0);
  bool surface = field.w > 0.0;

  // Tone: the lit luminance, bright faces lifted to white between t1 and t2, then contrast
  // against the blurred image, o + c (o - b).
  float tone = sketchLuminance(colour);
  tone = mix(tone, 1.0, smoothstep(sketchBright.x, sketchBright.y, tone));
#ifdef SKETCH_CONTRAST
  vec2 blurUV = (vec2(p) + 0.5) / vec2(sketchSize);
  float blurred = texture(sketchBlur, blurUV).r;
  tone = clamp(tone + sketchContrast * (tone - blurred), 0.0, 1.0);
#endif
  float dark = 1.0 - tone;

  float stroke = 0.5;
  float value = tone;
  if (surface)
  {
    vec3 x0 = sketchViewPosition(vec2(p) + 0.5, field.w);
    // Strokes only where there is ink to draw: bright pixels skip the integration.
#if SKETCH_LAYER == 2
    bool draw = true;
#elif SKETCH_LAYER == 0
    bool draw = dark > 1.0 / 255.0;
#else
    bool draw = false; // the directions and tone layers show no strokes
#endif
    if (draw)
    {
      stroke = sketchStroke(p, x0, field.xyz, n0, false);
    }
    // The mean of 1 - 2 dark (1 - stroke) is the tone: strokes modulate it, not darken it.
    value = clamp(1.0 - 2.0 * dark * (1.0 - stroke), 0.0, 1.0);
#ifdef SKETCH_CROSS
    float amount = smoothstep(sketchCross, sketchCross - 0.2, tone);
    if (amount > 0.0)
    {
      float crossStroke = sketchStroke(p, x0, field.xyz, n0, true);
      float crossValue = clamp(1.0 - 2.0 * dark * (1.0 - crossStroke), 0.0, 1.0);
      value *= mix(1.0, crossValue, amount);
    }
#endif
  }

#ifdef SKETCH_TINTED
  float m = max(colour.r, max(colour.g, colour.b));
  vec3 paper = m > 1e-4 ? colour / m : sketchPaper;
#else
  vec3 paper = sketchPaper;
#endif
  vec3 result = surface ? mix(sketchPencil, paper, value) : colour;
#if SKETCH_LAYER == 1
  if (surface)
  {
    // the direction's screen angle, modulo 180 degrees, as a hue
    vec2 s = sketchProject(sketchViewPosition(vec2(p) + 0.5, field.w) + field.xyz * 1e-3 *
      sketchPixelWorldAt(field.w)) - (vec2(p) + 0.5);
    float a = atan(s.y, s.x) * 2.0;
    result = 0.5 + 0.5 * vec3(cos(a), cos(a - 2.0943951), cos(a + 2.0943951));
  }
#elif SKETCH_LAYER == 2
  result = surface ? vec3(stroke) : colour;
#elif SKETCH_LAYER == 3
  result = surface ? vec3(tone) : colour;
#endif
  if (stylizeDiscardBackground == 1 && background)
  {
    discard;
  }
  gl_FragData[0] =
    vec4(stylizeSaturateFinite(result), stylizeOutputAlpha(background, image.a, 0.0));
  gl_FragDepth = stylizeWindowDepth(depth);
}
#endif
