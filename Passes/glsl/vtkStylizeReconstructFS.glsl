// VTK Stylize: fills the G-buffer from an image (colour and window depth) instead of geometry,
// for scenes whose lit colour and depth come from another pass (ParaView's IceT compositing
// hands over nothing else). stylizeReconstruct() computes every channel; the caller writes the
// requested ones to gl_FragData (VTK needs literal indices there). STYLIZE_POSITION_WORLD asks
// for world positions instead of view ones.
// STYLIZE_CHANNEL_SOURCE: the processes' own G-buffers (vtkStylizeGBufferPass::ChannelSource,
// composited by depth when there are several) hold the true channels inside stylizeSourceRect;
// where their depth is the image's (the same surface) they replace the reconstruction:
// STYLIZE_SOURCE_NORMAL, _POSITION, _DIRECTION and _LINEAR_DEPTH say which they hold. Needs
// vtkStylizeDepthFS (the source's depth may be logarithmic). The source's linear depth is the
// surface's own where the stored depth is not (a volume's solid surface stores where its material
// looks solid), and -1 on lines and points, as the geometry path writes it.
uniform sampler2D stylizeImageColor;
uniform sampler2D stylizeImageDepth;
uniform mat4 stylizeInverseProjection; // normalized device coordinates -> view coordinates
uniform mat4 stylizeInverseView;       // view coordinates -> world coordinates
uniform vec4 stylizeScreenTransform;   // the G-buffer's x' = sx x + tx, y' = sy y + ty
uniform vec2 stylizeImageSize;         // the image's size in pixels
// rgb: the background the picture stands for (vtkStylizeGBufferPass::ImageBackground), taken as
// the colour where there is no surface; a = 1 when applied this frame, 0 to keep the image's
uniform vec4 stylizeImageBackground;
#ifdef STYLIZE_CHANNEL_SOURCE
uniform sampler2D stylizeSourceDepth;  // stored depth (stylizeWindowDepth() maps it)
uniform vec4 stylizeSourceRect;        // x, y, width, height of the source textures in the image
#ifdef STYLIZE_SOURCE_NORMAL
uniform sampler2D stylizeSourceNormal;
#endif
#ifdef STYLIZE_SOURCE_POSITION
uniform sampler2D stylizeSourcePosition;
#endif
#ifdef STYLIZE_SOURCE_DIRECTION
uniform sampler2D stylizeSourceDirection;
#endif
#ifdef STYLIZE_SOURCE_LINEAR_DEPTH
uniform sampler2D stylizeSourceLinearDepth;
#endif
#endif

// View-space position of the image pixel whose centre is at texture coordinates uv.
vec3 stylizeImageViewPosition(vec2 uv, float depth)
{
  vec4 p = stylizeInverseProjection * vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  return p.xyz / p.w;
}

// Depth of the image pixel (integer coordinates, clamped to the image).
float stylizeImageDepthAt(ivec2 pixel)
{
  ivec2 size = ivec2(stylizeImageSize);
  return texelFetch(stylizeImageDepth, clamp(pixel, ivec2(0), size - 1), 0).r;
}

vec3 stylizeImagePositionAt(ivec2 pixel)
{
  vec2 uv = (vec2(pixel) + 0.5) / stylizeImageSize;
  return stylizeImageViewPosition(uv, stylizeImageDepthAt(pixel));
}

// The normal from the depth: on each axis the one-sided difference whose neighbour is closer in
// depth (so that silhouettes do not bend the normal), crossed, facing the viewer. Neighbours on
// the background are not used; a pixel without a usable neighbour pair faces the viewer.
vec3 stylizeReconstructNormal(ivec2 pixel, vec3 p, float depth)
{
  vec3 axes[2];
  for (int a = 0; a < 2; ++a)
  {
    ivec2 step = a == 0 ? ivec2(1, 0) : ivec2(0, 1);
    float d0 = stylizeImageDepthAt(pixel - step);
    float d1 = stylizeImageDepthAt(pixel + step);
    bool ok0 = d0 < 1.0;
    bool ok1 = d1 < 1.0;
    bool useNext = ok1 && (!ok0 || abs(d1 - depth) <= abs(depth - d0));
    if (useNext)
    {
      axes[a] = stylizeImagePositionAt(pixel + step) - p;
    }
    else if (ok0)
    {
      axes[a] = p - stylizeImagePositionAt(pixel - step);
    }
    else
    {
      axes[a] = vec3(0.0);
    }
  }
  vec3 n = cross(axes[0], axes[1]);
  float len = length(n);
  if (!(len > 0.0) || isinf(len))
  {
    return vec3(0.0, 0.0, 1.0);
  }
  n /= len;
  // Face the viewer: the normal points against the view ray (towards the camera).
  return dot(n, p) > 0.0 ? -n : n;
}

vec4 stylizeOutColor;
vec4 stylizeOutNormal;
vec4 stylizeOutPosition;
vec4 stylizeOutLinearDepth;
vec4 stylizeOutDirection;

void stylizeReconstruct()
{
  // The G-buffer pixel's normalized device coordinates, back through the screen transform.
  vec2 ndc = (texCoord * 2.0 - 1.0 - stylizeScreenTransform.zw) / stylizeScreenTransform.xy;
  vec2 uv = ndc * 0.5 + 0.5;
  ivec2 pixel = ivec2(floor(uv * stylizeImageSize));
  bool inside = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThan(uv, vec2(1.0)));
  float depth = inside ? stylizeImageDepthAt(pixel) : 1.0;
  bool surface = depth < 1.0;
  vec3 p = surface ? stylizeImagePositionAt(pixel) : vec3(0.0);
  stylizeOutColor = inside ? texelFetch(stylizeImageColor, pixel, 0) : vec4(0.0);
  if (!surface && stylizeImageBackground.a > 0.5)
  {
    stylizeOutColor.rgb = stylizeImageBackground.rgb;
  }
  stylizeOutNormal = surface ? vec4(stylizeReconstructNormal(pixel, p, depth), 1.0) : vec4(0.0);
#ifdef STYLIZE_POSITION_WORLD
  vec3 q = (stylizeInverseView * vec4(p, 1.0)).xyz;
#else
  vec3 q = p;
#endif
  stylizeOutPosition = surface ? vec4(q, 1.0) : vec4(0.0);
  stylizeOutLinearDepth = vec4(surface ? max(-p.z, 0.0) : 0.0, 0.0, 0.0, 0.0);
  stylizeOutDirection = vec4(0.0); // no direction attribute in an image: coherence 0
#ifdef STYLIZE_CHANNEL_SOURCE
  // The source's pixel holds the same surface when its depth is the image's (within what a
  // 24-bit depth buffer between them rounds off).
  ivec2 local = pixel - ivec2(stylizeSourceRect.xy);
  bool inRect = surface && all(greaterThanEqual(local, ivec2(0))) &&
    all(lessThan(local, ivec2(stylizeSourceRect.zw)));
  ivec2 at = clamp(local, ivec2(0), max(ivec2(stylizeSourceRect.zw) - 1, ivec2(0)));
  float sourceDepth = stylizeWindowDepth(texelFetch(stylizeSourceDepth, at, 0).r);
  if (inRect && abs(sourceDepth - depth) <= 1.0e-6)
  {
#ifdef STYLIZE_SOURCE_NORMAL
    stylizeOutNormal = texelFetch(stylizeSourceNormal, at, 0);
#endif
#ifdef STYLIZE_SOURCE_POSITION
    stylizeOutPosition = texelFetch(stylizeSourcePosition, at, 0);
#endif
#ifdef STYLIZE_SOURCE_DIRECTION
    stylizeOutDirection = texelFetch(stylizeSourceDirection, at, 0);
#endif
#ifdef STYLIZE_SOURCE_LINEAR_DEPTH
    stylizeOutLinearDepth = vec4(texelFetch(stylizeSourceLinearDepth, at, 0).r, 0.0, 0.0, 0.0);
#endif
  }
#endif
  gl_FragDepth = depth;
}
