// VTK Stylize G-buffer: the DIRECTION channel. The vertex shader passes the outer product d d^T
// of the vertex attribute stylizeDirectionMC (in view coordinates): interpolating d itself would
// cancel where neighbouring vertices store d and -d, the same unsigned direction.
in vec3 stylizeDirDiagVSOutput; // (dx dx, dy dy, dz dz)
in vec3 stylizeDirOffVSOutput;  // (dx dy, dx dz, dy dz)

// The tensor's principal direction in the tangent plane of unit normal n (view space), and its
// confidence in w: the eigenvalue gap of the interpolated outer products of unit directions,
// 1 where the face's vertices agree, less where they disagree or where some have no direction
// (a zero vector), 0 where none has.
vec4 stylizeTensorDirection(vec3 n)
{
  vec3 d = stylizeDirDiagVSOutput;
  vec3 o = stylizeDirOffVSOutput;
  mat3 t = mat3(d.x, o.x, o.y, o.x, d.y, o.z, o.y, o.z, d.z);
  // A tangent frame that is continuous away from n = +-x.
  vec3 a = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 x = normalize(a - n * dot(a, n));
  vec3 y = cross(n, x);
  vec3 tx = t * x;
  vec3 ty = t * y;
  float sxx = dot(x, tx);
  float sxy = dot(x, ty);
  float syy = dot(y, ty);
  float trace = sxx + syy;
  float gap = sqrt((sxx - syy) * (sxx - syy) + 4.0 * sxy * sxy);
  if (!(trace > 0.0) || !(gap > 1.0e-4) || isinf(trace))
  {
    return vec4(0.0);
  }
  float theta = 0.5 * atan(2.0 * sxy, sxx - syy);
  return vec4(x * cos(theta) + y * sin(theta), clamp(gap, 0.0, 1.0));
}
