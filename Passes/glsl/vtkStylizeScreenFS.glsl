// VTK Stylize: helpers shared by the style passes' full-screen shaders.
#ifndef VTK_STYLIZE_SCREEN
#define VTK_STYLIZE_SCREEN

// Triplanar projection of the object-space position stored at pixel p (a = 1 on surfaces) on
// the coordinate plane facing its geometric normal, found from the neighbouring positions.
// Returns `fallback` where there is no surface.
vec2 stylizeTriplanar(sampler2D positions, ivec2 p, ivec2 size, vec2 fallback)
{
  vec4 pos = texelFetch(positions, p, 0);
  ivec2 sx = p.x + 1 < size.x ? ivec2(1, 0) : ivec2(-1, 0);
  ivec2 sy = p.y + 1 < size.y ? ivec2(0, 1) : ivec2(0, -1);
  vec4 px = texelFetch(positions, p + sx, 0);
  vec4 py = texelFetch(positions, p + sy, 0);
  vec3 gn = cross((px.xyz - pos.xyz) * float(sx.x), (py.xyz - pos.xyz) * float(sy.y));
  gn = (px.a > 0.5 && py.a > 0.5) ? abs(gn) : vec3(0.0, 0.0, 1.0);
  vec2 plane = gn.x >= gn.y && gn.x >= gn.z ? pos.yz : (gn.y >= gn.z ? pos.zx : pos.xy);
  return pos.a > 0.5 ? plane : fallback;
}
#endif
