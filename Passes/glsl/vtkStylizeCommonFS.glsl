// VTK Stylize: helpers shared by every fragment shader the project injects.
// Guarded so that several passes may inject them into one shader.
#ifndef VTK_STYLIZE_COMMON
#define VTK_STYLIZE_COMMON

// True when x is neither NaN nor +/-Inf (written so that fast-math cannot fold it away).
bool stylizeIsFinite(float x)
{
  return !(isnan(x) || isinf(x)) && (x == x);
}

// pow() that is defined everywhere: pow(x, 0) = 1 (also for x = 0), pow(x <= 0, e > 0) = 0.
float stylizeSafePow(float x, float e)
{
  if (!(e > 0.0))
  {
    return 1.0;
  }
  if (!(x > 0.0))
  {
    return 0.0;
  }
  return pow(x, e);
}

// Normalizes v; returns fallback when v is zero, NaN or infinite. Pre-scaling by the largest
// component keeps vectors of any magnitude (1e-30 .. 1e30) away from underflow and overflow.
vec3 stylizeSafeNormalize(vec3 v, vec3 fallback)
{
  float m = max(abs(v.x), max(abs(v.y), abs(v.z)));
  if (!(m > 0.0) || !stylizeIsFinite(m))
  {
    return fallback;
  }
  v /= m;
  return v * inversesqrt(dot(v, v));
}

// The shading normal: the interpolated normal when it is usable, otherwise the facet normal
// from screen-space derivatives of the view-space position (faceNormal, computed by the caller in
// uniform control flow), otherwise the direction to the viewer.
vec3 stylizeShadingNormal(vec3 n, vec3 faceNormal, vec3 toViewer)
{
  vec3 viewer = stylizeSafeNormalize(toViewer, vec3(0.0, 0.0, 1.0));
  vec3 fn = stylizeSafeNormalize(faceNormal, viewer);
  if (dot(fn, viewer) < 0.0)
  {
    fn = -fn;
  }
  return stylizeSafeNormalize(n, fn);
}

// The light's tone in a lit surface colour: its largest channel. vtkStylizeLightingPass's colour
// modes 2 to 4 (the black-and-white styles' and the tinted ones') make that colour the tone
// times white or a hue at full value, so the tone does not depend on the data's colours.
float stylizeTone(vec3 c)
{
  return max(c.r, max(c.g, c.b));
}

// Replaces NaN by 0 and clamps to [0, 1]: what an 8-bit framebuffer would show, in float.
vec3 stylizeSaturateFinite(vec3 c)
{
  c.r = stylizeIsFinite(c.r) ? c.r : (isinf(c.r) && c.r > 0.0 ? 1.0 : 0.0);
  c.g = stylizeIsFinite(c.g) ? c.g : (isinf(c.g) && c.g > 0.0 ? 1.0 : 0.0);
  c.b = stylizeIsFinite(c.b) ? c.b : (isinf(c.b) && c.b > 0.0 ? 1.0 : 0.0);
  return clamp(c, 0.0, 1.0);
}
#endif
