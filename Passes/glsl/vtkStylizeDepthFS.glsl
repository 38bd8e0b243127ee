// VTK Stylize: the G-buffer's depth mapping. When the perspective near/far ratio is extreme the
// G-buffer stores a logarithmic depth, log(z / near) / log(far / near), whose relative precision
// is the same at every distance (a standard window depth keeps almost none far away at a 1e7
// ratio). Screen passes convert it back to the window depth VTK expects before writing it.
uniform vec3 stylizeDepthMapping; // near, far, 1 when the stored depth is logarithmic

float stylizeWindowDepth(float stored)
{
  if (stylizeDepthMapping.z < 0.5 || !(stored < 1.0))
  {
    return stored;
  }
  float n = stylizeDepthMapping.x;
  float f = stylizeDepthMapping.y;
  // z / n = exp(stored * log(f / n)); window depth = f / (f - n) * (1 - n / z)
  float nOverZ = exp(-stored * log(f / n));
  return clamp(f / (f - n) * (1.0 - nOverZ), 0.0, 1.0);
}
