// VTK Stylize: a per-pixel field of principal curvature directions from the G-buffer, shared by
// the styles that draw along the surface's form (vtkSketchPass' strokes, vtkComicPass' hatching
// with HatchOrientation PRINCIPAL); docs/algorithms.md section 3. vtkStylizeStylePass runs its
// three stages (RenderDirectionField()) when a style asks for them:
//   FIELD_STAGE_ESTIMATE  raw direction e (the principal direction of the smaller |curvature|)
//                         and its confidence, from the G-buffer (focal surfaces or the mapped
//                         direction attribute)
//   FIELD_STAGE_SMOOTH    one sign-invariant smoothing or fill iteration of the raw field
//   FIELD_STAGE_RESOLVE   the smoothed field upsampled to pixels within each surface,
//                         fallbacks for undefined pixels, then the requested direction; writes
//                         the final field (xyz view-space unit direction, w linear depth)
// The estimate and the smoothing run on a grid of fieldScale x fieldScale pixels per texel,
// aligned with the full image (a tile's grid continues its neighbours'); the resolve runs at
// the pixels.
//   FIELD_NEIGHBORS 2|4|8, FIELD_MODEL, FIELD_DIRECTION 0|1|2 (minimum, maximum, bisector)
// The camera helpers (view positions, projection, tangent frames) are shared with the styles'
// own stages. Lengths arrive in pixels of this viewport or in world units, converted on the CPU.
#if defined(FIELD_STAGE_ESTIMATE) || defined(FIELD_STAGE_SMOOTH) || defined(FIELD_STAGE_RESOLVE)
#define STYLIZE_FIELD_STAGE
#endif
uniform sampler2D stylizeDirectionTexture;   // G-buffer DIRECTION channel (model-space mode)

uniform ivec2 fieldSize;        // viewport size (pixels)
uniform vec2 fieldPixelOffset;  // this tile's offset in the full image (pixels)
uniform int fieldParallel;      // 1 for parallel projection
uniform float fieldPixelWorld;  // world size of a pixel: times depth (perspective) or as is
uniform vec4 fieldProjection;   // P00, P11, P02, P12 of the camera's projection
uniform vec2 fieldProjOffset;   // P03, P13
uniform int fieldScale;         // pixels per texel of the estimate's and smoothing's grid
uniform ivec2 fieldGridOrigin;  // this viewport's offset into its first texel (pixels)
uniform ivec2 fieldGridSize;    // the grid's size (texels)

// ---- camera helpers -------------------------------------------------------------------------
// Normalized device coordinates of continuous pixel position f (pixel centres at i + 0.5).
vec2 fieldNDC(vec2 f)
{
  return f / vec2(fieldSize) * 2.0 - 1.0;
}

// View-space position of the surface seen at pixel position f at linear depth d.
vec3 fieldViewPosition(vec2 f, float d)
{
  vec2 ndc = fieldNDC(f);
  vec2 xy = fieldParallel == 1 ? (ndc - fieldProjOffset) / fieldProjection.xy
                                : d * (ndc + fieldProjection.zw) / fieldProjection.xy;
  return vec3(xy, -d);
}

// Continuous pixel position of view-space point v.
vec2 fieldProject(vec3 v)
{
  vec2 ndc = fieldParallel == 1
    ? fieldProjection.xy * v.xy + fieldProjOffset
    : (fieldProjection.xy * v.xy + fieldProjection.zw * v.z) / max(-v.z, 1e-30);
  return (ndc + 1.0) * 0.5 * vec2(fieldSize);
}

float fieldPixelWorldAt(float d)
{
  return fieldParallel == 1 ? fieldPixelWorld : fieldPixelWorld * d;
}

// A tangent frame (x, y) of unit normal n, continuous away from n = +-x.
void fieldFrame(vec3 n, out vec3 x, out vec3 y)
{
  vec3 a = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  x = normalize(a - n * dot(a, n));
  y = cross(n, x);
}

ivec2 fieldPixel()
{
  return clamp(ivec2(texCoord * vec2(fieldSize)), ivec2(0), fieldSize - 1);
}

// The pixel that grid texel t stands for (its centre pixel, clamped to the viewport).
ivec2 fieldGridPixel(ivec2 t)
{
  return clamp(t * fieldScale + fieldScale / 2 - fieldGridOrigin, ivec2(0), fieldSize - 1);
}

// This stage's grid texel.
ivec2 fieldGridTexel()
{
  return clamp(ivec2(texCoord * vec2(fieldGridSize)), ivec2(0), fieldGridSize - 1);
}

bool fieldGridInside(ivec2 t)
{
  return all(greaterThanEqual(t, ivec2(0))) && all(lessThan(t, fieldGridSize));
}

// Linear depth d and normal n of pixel p; false on the background and on lines and points.
bool fieldSurfaceAt(ivec2 p, out float d, out vec3 n)
{
  d = texelFetch(stylizeLinearDepthTexture, p, 0).r;
  vec4 n4 = texelFetch(stylizeNormalTexture, p, 0);
  n = n4.xyz;
  return d > 0.0 && n4.a >= 0.5;
}

// This stage's pixel p (the estimate: its grid texel's pixel) with its linear depth d and
// normal n; off the surface the stage writes "no direction" (zero) and the caller returns.
bool fieldStageStart(out ivec2 p, out float d, out vec3 n)
{
#ifdef FIELD_STAGE_ESTIMATE
  p = fieldGridPixel(fieldGridTexel());
#else
  p = fieldPixel();
#endif
  if (!fieldSurfaceAt(p, d, n))
  {
    gl_FragData[0] = vec4(0.0);
    return false;
  }
  return true;
}

// The doubled-angle vector (x^2 - y^2, 2 x y) = |v|^2 (cos 2a, sin 2a): v and -v give the same.
vec2 fieldDoubled(vec2 v)
{
  return vec2(v.x * v.x - v.y * v.y, 2.0 * v.x * v.y);
}

bool fieldInside(ivec2 q)
{
  return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, fieldSize));
}

// ---- stage 1: raw directions ----------------------------------------------------------------
#ifdef FIELD_STAGE_ESTIMATE
uniform float fieldSpacing;     // world floor of the neighbour spacing
uniform int fieldMaxStride;     // pixels
uniform float fieldPlanar;      // |kappa| h below which a pair counts as planar
uniform float fieldUmbilic;     // confidence below which a pixel is undefined

// Neighbour q seen from centre x (normal n, tangent frame X, Y): where its normal ray crosses the
// tangent plane (u) and the ray's direction scaled to unit height (m). False when q is off the
// surface (background, another surface, a fold).
bool fieldNeighbor(ivec2 q, vec3 x, vec3 n, vec3 X, vec3 Y, out vec2 u, out vec2 m)
{
  u = vec2(0.0);
  m = vec2(0.0);
  if (!fieldInside(q))
  {
    return false;
  }
  float d;
  vec3 nq;
  if (!fieldSurfaceAt(q, d, nq))
  {
    return false;
  }
  vec3 dp = fieldViewPosition(vec2(q) + 0.5, d) - x;
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

float fieldCross(vec2 a, vec2 b)
{
  return a.x * b.y - a.y * b.x;
}

// One neighbour pair: the focal quadratic in kappa = 1 / lambda,
//   c kappa^2 + b kappa + a = 0,
// root of the larger |kappa|; the rays' points at that focal height lie along the principal
// direction of the smaller |kappa|: r = kappa u + m (the point times kappa: no overflow on flat
// ground). Accumulates their doubled angles (total least squares through the origin), each
// scaled by 1 / (kappa h)^2 so that an umbilic pair (r ~ 0) weighs nothing.
void fieldPair(vec2 u1, vec2 m1, bool ok1, vec2 u2, vec2 m2, bool ok2, inout vec3 acc)
{
  if (!ok1 || !ok2)
  {
    return;
  }
  float a = fieldCross(m1, m2);
  float b = fieldCross(u1, m2) + fieldCross(m1, u2);
  float c = fieldCross(u1, u2);
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
  if (!(kh2 > fieldPlanar * fieldPlanar) || isinf(kh2))
  {
    return;
  }
  vec2 r1 = kappa * u1 + m1;
  vec2 r2 = kappa * u2 + m2;
  acc.xy += (fieldDoubled(r1) + fieldDoubled(r2)) / kh2;
  acc.z += 2.0;
}

// The stage at a surface pixel p, its linear depth d0 and normal n (stylizeFieldMain()).
void fieldSurfaceStage(ivec2 p, float d0, vec3 n)
{
#ifdef FIELD_MODEL
  // The mapped direction where the data gives one with confidence (its vertices agree), else
  // the screen estimate.
  vec4 given = texelFetch(stylizeDirectionTexture, p, 0);
  if (given.a > fieldUmbilic)
  {
    gl_FragData[0] = vec4(given.xyz, max(given.a, 1e-3));
    return;
  }
#endif
  vec3 X, Y;
  fieldFrame(n, X, Y);
  vec3 x = fieldViewPosition(vec2(p) + 0.5, d0);
  // The stride keeps neighbours at least fieldSpacing apart in world units.
  int s = int(clamp(ceil(fieldSpacing / fieldPixelWorldAt(d0)), 1.0, float(fieldMaxStride)));
  vec2 uR, mR, uU, mU, uL, mL, uD, mD;
  bool okR = fieldNeighbor(p + ivec2(s, 0), x, n, X, Y, uR, mR);
  bool okU = fieldNeighbor(p + ivec2(0, s), x, n, X, Y, uU, mU);
  vec3 acc = vec3(0.0);
  fieldPair(uR, mR, okR, uU, mU, okU, acc);
#if FIELD_NEIGHBORS >= 4
  bool okL = fieldNeighbor(p - ivec2(s, 0), x, n, X, Y, uL, mL);
  bool okD = fieldNeighbor(p - ivec2(0, s), x, n, X, Y, uD, mD);
  fieldPair(uU, mU, okU, uL, mL, okL, acc);
  fieldPair(uL, mL, okL, uD, mD, okD, acc);
  fieldPair(uD, mD, okD, uR, mR, okR, acc);
#endif
#if FIELD_NEIGHBORS >= 8
  vec2 u1, m1, u2, m2, u3, m3, u4, m4;
  bool ok1 = fieldNeighbor(p + ivec2(s, s), x, n, X, Y, u1, m1);
  bool ok2 = fieldNeighbor(p + ivec2(-s, s), x, n, X, Y, u2, m2);
  bool ok3 = fieldNeighbor(p + ivec2(-s, -s), x, n, X, Y, u3, m3);
  bool ok4 = fieldNeighbor(p + ivec2(s, -s), x, n, X, Y, u4, m4);
  fieldPair(u1, m1, ok1, u2, m2, ok2, acc);
  fieldPair(u2, m2, ok2, u3, m3, ok3, acc);
  fieldPair(u3, m3, ok3, u4, m4, ok4, acc);
  fieldPair(u4, m4, ok4, u1, m1, ok1, acc);
#endif
  float confidence = acc.z > 0.0 ? min(1.0, length(acc.xy) / acc.z) : 0.0;
  if (!(confidence > fieldUmbilic))
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
  float theta = 0.5 * atan(acc.y, acc.x);
  gl_FragData[0] = vec4(X * cos(theta) + Y * sin(theta), confidence);
}
#endif

// ---- stage 2: smoothing and fill ------------------------------------------------------------
#ifdef FIELD_STAGE_SMOOTH
uniform sampler2D fieldInput; // xyz direction, w confidence (> 0 defined, < 0 filled, 0 none)
uniform int fieldRadius;      // tap distance (pixels)
uniform int fieldFillOnly;    // 1: defined pixels keep their value (fill iterations)

void stylizeFieldMain()
{
  ivec2 t = fieldGridTexel();
  ivec2 p = fieldGridPixel(t);
  vec4 c = texelFetch(fieldInput, t, 0);
  float d0;
  vec3 n;
  if (!fieldSurfaceAt(p, d0, n) || (fieldFillOnly == 1 && c.w != 0.0))
  {
    gl_FragData[0] = c;
    return;
  }
  vec3 X, Y;
  fieldFrame(n, X, Y);
  vec3 x = fieldViewPosition(vec2(p) + 0.5, d0);
  // Doubled angles in this pixel's tangent frame: d and -d count the same.
  vec3 acc = vec3(0.0);
  for (int j = -1; j <= 1; ++j)
  {
    for (int i = -1; i <= 1; ++i)
    {
      ivec2 tq = t + ivec2(i, j) * fieldRadius;
      if (!fieldGridInside(tq))
      {
        continue;
      }
      ivec2 q = fieldGridPixel(tq);
      vec4 e = texelFetch(fieldInput, tq, 0);
      if (e.w == 0.0)
      {
        continue;
      }
      if (i != 0 || j != 0)
      {
        // same surface: a similar normal, and close to this pixel's tangent plane
        vec4 nq = texelFetch(stylizeNormalTexture, q, 0);
        float dq = texelFetch(stylizeLinearDepthTexture, q, 0).r;
        vec3 dp = fieldViewPosition(vec2(q) + 0.5, dq) - x;
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
      acc += vec3(fieldDoubled(v) / l2, 1.0) * w;
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
#ifdef FIELD_STAGE_RESOLVE
uniform sampler2D fieldInput;
uniform int fieldGradientStride; // Sobel tap distance of the lighting-gradient fallback
uniform vec2 fieldScreenDirection; // the last resort: a fixed screen direction

// The smoothed field at pixel p (linear depth d0, normal n): the doubled-angle average of the
// four grid texels around it, bilinear, weighted by their confidence, those on another surface
// (normal or tangent plane apart) left out. With one pixel per texel, the pixel's own texel.
vec4 fieldUpsample(ivec2 p, float d0, vec3 n)
{
  if (fieldScale == 1)
  {
    return texelFetch(fieldInput, p, 0);
  }
  vec3 X, Y;
  fieldFrame(n, X, Y);
  vec3 x = fieldViewPosition(vec2(p) + 0.5, d0);
  vec2 g = (vec2(p + fieldGridOrigin) + 0.5) / float(fieldScale) - 0.5;
  vec2 g0 = floor(g);
  vec2 f = g - g0;
  vec3 acc = vec3(0.0);
  for (int k = 0; k < 4; ++k)
  {
    ivec2 o = ivec2(k & 1, k >> 1);
    ivec2 t = clamp(ivec2(g0) + o, ivec2(0), fieldGridSize - 1);
    vec4 e = texelFetch(fieldInput, t, 0);
    ivec2 q = fieldGridPixel(t);
    vec4 nq = texelFetch(stylizeNormalTexture, q, 0);
    float dq = texelFetch(stylizeLinearDepthTexture, q, 0).r;
    vec3 dp = fieldViewPosition(vec2(q) + 0.5, dq) - x;
    vec2 v = vec2(dot(e.xyz, X), dot(e.xyz, Y));
    float l2 = dot(v, v);
    if (e.w == 0.0 || !(dq > 0.0) || nq.a < 0.5 || dot(nq.xyz, n) < 0.7 ||
      abs(dot(dp, n)) > 0.5 * length(dp) + 1e-30 || !(l2 > 1e-8))
    {
      continue;
    }
    float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y) * abs(e.w) + 1e-6;
    acc += vec3(fieldDoubled(v) / l2, 1.0) * w;
  }
  if (!(acc.z > 0.0) || !(length(acc.xy) > 1e-6 * acc.z))
  {
    return vec4(0.0);
  }
  float theta = 0.5 * atan(acc.y, acc.x);
  return vec4(X * cos(theta) + Y * sin(theta), 1.0);
}

// The stage at a surface pixel p, its linear depth d0 and normal n (stylizeFieldMain()).
void fieldSurfaceStage(ivec2 p, float d0, vec3 n)
{
  vec4 c = fieldUpsample(p, d0, n);
  vec3 e = c.xyz - n * dot(c.xyz, n);
  bool defined = c.w != 0.0 && dot(e, e) > 1e-8;
  vec3 result;
  if (defined)
  {
    e = normalize(e);
#if FIELD_DIRECTION == 0
    result = e;
#elif FIELD_DIRECTION == 1
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
    int s = fieldGradientStride;
    float l[9];
    for (int b = 0; b < 9; ++b)
    {
      ivec2 t = clamp(p + ivec2(b % 3 - 1, b / 3 - 1) * s, ivec2(0), fieldSize - 1);
      l[b] = b == 4 ? 0.0 : stylizeTone(texelFetch(stylizeColorTexture, t, 0).rgb);
    }
    vec2 g = stylizeSobel(l);
    vec2 screen = dot(g, g) > 1e-10 ? normalize(vec2(-g.y, g.x)) : fieldScreenDirection;
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

#if defined(FIELD_STAGE_ESTIMATE) || defined(FIELD_STAGE_RESOLVE)
// The estimate's and the resolve's main: their stage on the surface's pixels, zero elsewhere.
void stylizeFieldMain()
{
  ivec2 p;
  float d0;
  vec3 n;
  if (fieldStageStart(p, d0, n))
  {
    fieldSurfaceStage(p, d0, n);
  }
}
#endif
