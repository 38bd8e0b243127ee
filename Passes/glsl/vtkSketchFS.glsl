// VTK Stylize sketch pass (vtkSketchPass): perspective-correct line integral convolution of
// solid noise along the principal direction field (vtkStylizeFieldFS, run by the base's
// RenderDirectionField()), pencil tone. docs/algorithms.md section 3. The pass prepends #defines
// that select what is compiled:
//   SKETCH_STAGE_BLUR_X, SKETCH_STAGE_BLUR_Y   the strided Gaussian blur of the lit luminance
//   SKETCH_STAGE_FINAL     strokes (LIC) and tone into the output
//   SKETCH_NOISE_SCREEN, SKETCH_NOISE_INTERPOLATED, SKETCH_SCREEN_LIC, SKETCH_CROSS,
//   SKETCH_CONTRAST, SKETCH_TINTED,
//   SKETCH_LAYER 0|1|2|3 (sketch, directions, strokes, tone)
// Lengths arrive in pixels of this viewport or in world units, converted on the CPU.

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
      ivec2(0), fieldSize - 1);
    float v = stylizeTone(texelFetch(stylizeColorTexture, q, 0).rgb);
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
uniform vec2 sketchBlurExtent;   // pixels the blur's texels cover (its size times its stride)
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
uniform sampler2D sketchFeatureInk; // SKETCH_FEATURE_LINES: the strokes' ink in [0, 1] (red),
                                    // the iso-lines' halo (green)
uniform float sketchPointPixels;    // pixels per point

// The four pixels around continuous pixel position f (taps, their field entries) and their
// bilinear weights, a weight 0 where the pixel is not on the stroke's surface: no field there,
// or its linear depth farther than tol from the expected depth.
vec4 sketchSurfaceTaps(vec2 f, float expected, float tol, out ivec2 taps[4], out vec4 entries[4])
{
  vec2 g = f - 0.5;
  vec2 fl = floor(g);
  vec2 t = g - fl;
  ivec2 i0 = ivec2(fl);
  vec4 weights = vec4(0.0);
  for (int k = 0; k < 4; ++k)
  {
    ivec2 o = ivec2(k & 1, k >> 1);
    taps[k] = clamp(i0 + o, ivec2(0), fieldSize - 1);
    entries[k] = texelFetch(sketchField, taps[k], 0);
    bool on = entries[k].w > 0.0 && !(abs(entries[k].w - expected) > tol);
    weights[k] = on ? (o.x == 1 ? t.x : 1.0 - t.x) * (o.y == 1 ? t.y : 1.0 - t.y) : 0.0;
  }
  return weights;
}

// The field at continuous pixel position f, bilinear over the taps on the stroke's surface
// (depth within tol of the expected depth), directions flipped to agree with ref. w = 0: none.
vec4 sketchFieldAt(vec2 f, vec3 ref, float expected, float tol)
{
  ivec2 taps[4];
  vec4 e[4];
  vec4 w = sketchSurfaceTaps(f, expected, tol, taps, e);
  vec4 acc = vec4(0.0);
  for (int k = 0; k < 4; ++k)
  {
    if (w[k] > 0.0) // (a tap off the surface is left out, not multiplied by 0)
    {
      acc += w[k] * vec4(dot(e[k].xyz, ref) < 0.0 ? -e[k].xyz : e[k].xyz, e[k].w);
    }
  }
  float wsum = w.x + w.y + w.z + w.w;
  return wsum > 1e-4 ? acc / wsum : vec4(0.0);
}

// The noise at continuous pixel position f. Object noise: at the object-space position of the
// nearest pixel (WHITE: the one-pixel pencil), or (SKETCH_NOISE_INTERPOLATED, SPARSE) at the
// position interpolated bilinearly between the neighbouring pixels on the same surface (linear
// depth within tol of expected), so that a point of the surface reads the same noise whatever
// the pixels' positions.
float sketchNoiseAt(vec2 f, float expected, float tol)
{
#ifdef SKETCH_NOISE_SCREEN
  return texture(sketchNoise, vec3((f + fieldPixelOffset) * sketchNoiseScale, 0.5)).r;
#elif !defined(SKETCH_NOISE_INTERPOLATED)
  vec4 pos = texelFetch(stylizePositionTexture, clamp(ivec2(f), ivec2(0), fieldSize - 1), 0);
  return texture(sketchNoise, pos.xyz * sketchNoiseScale).r;
#else
  ivec2 taps[4];
  vec4 entries[4];
  vec4 w = sketchSurfaceTaps(f, expected, tol, taps, entries);
  vec3 acc = vec3(0.0);
  float wsum = 0.0;
  vec4 pos[4];
  bool on[4];
  for (int k = 0; k < 4; ++k)
  {
    pos[k] = texelFetch(stylizePositionTexture, taps[k], 0);
    on[k] = pos[k].a > 0.5 && entries[k].w > 0.0 && !(abs(entries[k].w - expected) > tol);
    if (w[k] > 0.0 && pos[k].a > 0.5)
    {
      acc += w[k] * pos[k].xyz;
      wsum += w[k];
    }
  }
  vec3 p = wsum > 1e-4 ? acc / wsum :
    texelFetch(stylizePositionTexture, clamp(ivec2(f), ivec2(0), fieldSize - 1), 0).xyz;
  // Prefiltered over the pixel's footprint on the surface (the object-space step to the next
  // pixel in x and y, from the taps on the surface): where the surface is seen at a grazing
  // angle the noise's texels are narrower than a pixel across it, and read at a point they would
  // alias as the pixels move over them; the mipmapped noise averages them instead.
  vec3 dx = on[0] && on[1] ? pos[1].xyz - pos[0].xyz
                           : (on[2] && on[3] ? pos[3].xyz - pos[2].xyz : vec3(0.0));
  vec3 dy = on[0] && on[2] ? pos[2].xyz - pos[0].xyz
                           : (on[1] && on[3] ? pos[3].xyz - pos[1].xyz : vec3(0.0));
  return textureGrad(sketchNoise, p * sketchNoiseScale, dx * sketchNoiseScale,
    dy * sketchNoiseScale).r;
#endif
}

// Line integral convolution of the noise through pixel p (view position x0) along dir0 (or, for
// cross-hatching, along n0 x dir). Perspective-correct: each step moves in world space along the
// surface, is projected back to the screen, and snaps to the surface seen there. The starts are
// staggered by the ordered-dither matrix. Returns the stroke value, 0.5 on average.
float sketchStroke(ivec2 p, vec3 x0, vec3 dir0, vec3 n0, bool across)
{
  float pw = fieldPixelWorldAt(-x0.z);
  float stepWorld = sketchStepPixels * pw;
  float tol = 2.0 * stepWorld + 2.0 * pw;
  float o = (float(stylizeBayer(p + ivec2(fieldPixelOffset))) - 0.5) / 64.0;
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
    // (In pixels: normalized device coordinates stretch x and y by the viewport's sides.)
    vec2 d2 = normalize(fieldProjection.xy * d.xy * vec2(fieldSize) + vec2(1e-12, 0.0));
    f = f0 + d2 * along * sketchStepPixels;
#endif
    for (int k = 0; k < sketchSteps; ++k)
    {
#ifndef SKETCH_SCREEN_LIC
      f = fieldProject(pos);
#endif
      if (any(lessThan(f, vec2(0.0))) || any(greaterThanEqual(f, vec2(fieldSize))))
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
      float v = sketchNoiseAt(f, e.w, tol);
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
      vec2 nd2 = fieldProjection.xy * nd.xy * vec2(fieldSize);
      if (dot(nd2, nd2) > 1e-12)
      {
        nd2 = normalize(nd2);
        d2 = dot(nd2, d2) < 0.0 ? -nd2 : nd2;
      }
      d = nd;
      f += d2 * sketchStepPixels;
#else
      pos = fieldViewPosition(f, e.w); // back onto the surface seen at f
      d = dot(nd, nd) > 1e-8 ? normalize(nd) : d;
      pos += d * stepWorld;
#endif
    }
  }
  if (!(wsum > 0.0))
  {
    float start = sketchNoiseAt(f0, -x0.z, tol);
    return 0.5 + (start - sketchNoiseStats.x) * 0.25 * sketchStrokeContrast /
      max(sketchNoiseStats.y, 1e-4);
  }
  // Normalize: the weighted mean of independent samples has deviation sigma sqrt(w2) / w.
  float z = (sum / wsum - sketchNoiseStats.x) /
    max(sketchNoiseStats.y * sqrt(w2sum) / wsum, 1e-4);
  return clamp(0.5 + 0.25 * sketchStrokeContrast * z, 0.0, 1.0);
}

// The pencil's grain at pixel p, a factor of its ink in [0.3, 1]: the noise, a texel per point
// fixed to the image, thins the ink where it is light (feature lines, lines and points).
float sketchGrain(ivec2 p)
{
  float grain = texture(sketchNoise,
    vec3((vec2(p) + fieldPixelOffset + 0.5) / (sketchPointPixels * 64.0), 0.37)).r;
  float grainZ = (grain - sketchNoiseStats.x) / max(sketchNoiseStats.y, 1e-4);
  return clamp(0.8 + 0.2 * sketchStrokeContrast * grainZ, 0.3, 1.0);
}

void sketchMain()
{
  ivec2 p = fieldPixel();
  vec4 image = texelFetch(stylizeColorTexture, p, 0);
  vec3 colour = image.rgb;
  float depth = texelFetch(stylizeDepthTexture, p, 0).r;
  vec4 field = texelFetch(sketchField, p, 0);
  vec3 n0 = texelFetch(stylizeNormalTexture, p, 0).xyz;
  bool background = !(depth < 1.0);
  bool surface = field.w > 0.0;

  // Tone: the light's (stylizeTone), bright faces lifted to white between t1 and t2, then
  // contrast against the blurred image, o + c (o - b).
  float tone = stylizeTone(colour);
  tone = mix(tone, 1.0, smoothstep(sketchBright.x, sketchBright.y, tone));
#ifdef SKETCH_CONTRAST
  vec2 blurUV = (vec2(p) + 0.5) / sketchBlurExtent;
  float blurred = texture(sketchBlur, blurUV).r;
  tone = clamp(tone + sketchContrast * (tone - blurred), 0.0, 1.0);
#endif
  float dark = 1.0 - tone;

  float stroke = 0.5;
  float value = tone;
  if (surface)
  {
    vec3 x0 = fieldViewPosition(vec2(p) + 0.5, field.w);
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

#ifdef SKETCH_FEATURE_LINES
  // Beside an iso-line the pencil gives way to the paper (the strokes' halo), so that the line
  // reads over dark strokes.
  value = mix(value, 1.0, clamp(texelFetch(sketchFeatureInk, p, 0).g, 0.0, 1.0));
#endif
#ifdef SKETCH_TINTED
  float m = max(colour.r, max(colour.g, colour.b));
  vec3 paper = m > 1e-4 ? colour / m * sketchPaper : sketchPaper;
#else
  vec3 paper = sketchPaper;
#endif
  vec3 result = surface ? mix(sketchPencil, paper, value) : colour;
#if SKETCH_LAYER == 0
  // Lines and points (unlit primitives: linear depth -1, streamlines, wireframes) are drawn in
  // pencil on the paper, with its grain (the noise is bound where strokes are drawn).
  if (!surface && texelFetch(stylizeLinearDepthTexture, p, 0).r < 0.0)
  {
    result = mix(sketchPaper, sketchPencil, sketchGrain(p));
  }
#elif SKETCH_LAYER == 1
  if (surface)
  {
    // the direction's screen angle, modulo 180 degrees, as a hue
    vec2 s = fieldProject(fieldViewPosition(vec2(p) + 0.5, field.w) + field.xyz * 1e-3 *
      fieldPixelWorldAt(field.w)) - (vec2(p) + 0.5);
    float a = atan(s.y, s.x) * 2.0;
    result = 0.5 + 0.5 * vec3(cos(a), cos(a - 2.0943951), cos(a + 2.0943951));
  }
#elif SKETCH_LAYER == 2
  result = surface ? vec3(stroke) : colour;
#elif SKETCH_LAYER == 3
  result = surface ? vec3(tone) : colour;
#endif
  float ink = 0.0;
#ifdef SKETCH_FEATURE_LINES
  // the feature lines in pencil, over the strokes and the background, with the strokes' grain:
  // the noise, a texel per point fixed to the image, thins their ink where it is light
  ink = clamp(texelFetch(sketchFeatureInk, p, 0).r, 0.0, 1.0) * sketchGrain(p);
  result = mix(result, sketchPencil, ink);
#endif
  if (stylizeDiscardBackground == 1 && background && ink <= 0.0)
  {
    discard;
  }
  gl_FragData[0] = stylizeOutput(background, result, image.a, ink);
  gl_FragDepth = stylizeWindowDepth(depth);
}
#endif
