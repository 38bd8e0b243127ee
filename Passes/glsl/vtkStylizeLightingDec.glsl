// VTK Stylize lighting models: declarations (replaces //VTK::Light::Dec).
//
// Lights live in a texture buffer, four RGBA32F texels per enabled vtkLight, in view coordinates:
//   texel 4i+0: colour * intensity (rgb), positional flag (a: 0 or 1)
//   texel 4i+1: direction the light shines along, unit (xyz), cone angle in degrees (a)
//   texel 4i+2: position (xyz), spot exponent (a)
//   texel 4i+3: attenuation constant, linear, quadratic (xyz), unused (a)
// so a program serves 0, 1 or 1000 lights and is never rebuilt when the count changes. Two light
// classes are compiled apart (STYLIZE_HEADLIGHT_ONLY: VTK's single headlight, its shortcut; the
// general program for every other set), each once per model.
uniform samplerBuffer stylizeLights;
uniform int stylizeLightCount;      // number of enabled lights, >= 0
// STYLIZE_MODEL (a #define the pass puts before this text): 0 Standard, 1 Comic, 2 PixelArt.
// Comic (docs/algorithms.md section 2)
uniform float stylizeSubjectFactor; // p1 in [0, 1]
uniform float stylizeLevelsNear;    // gray levels at the near end of the depth range, [0, 100]
uniform float stylizeLevelsFar;     // gray levels at the far end, [0, 100]
uniform float stylizeSpecularGain;  // specular multiplier, [0, 100]
uniform vec2 stylizeDepthRange;     // view depth mapped to 0 and 1 for the level interpolation
// What the lit colour is made of (vtkStylizeLightingPass::ColorModes): 0 the surface's colours
// times the lights', 1 times the lights' luminance, 2 gray (the tone of a white surface), 3 the
// hue of colours from an array times the tone (STYLIZE_DATA_COLORS: this program's colours come
// from one), 4 every colour's hue times the tone. 1 to 4 light with neutral lights.
uniform int stylizeColorMode;
uniform int stylizeEmitted; // 1: the actor's colours are light already (EMITTED_COLORS)
uniform int stylizeSolidColorTones; // 1: in modes 2 to 4 a solid colour's lightness darkens the tone
uniform float stylizeSolidColorWhite; // the luminance from which a solid colour counts as white
// Pixel art (docs/algorithms.md section 1)
uniform float stylizeScattering;    // s in [0, 1]; diffuse scaled by sqrt(s)
uniform float stylizeOcclusion;     // M in [0, 1]; specular occlusion factor

// A light's colour times intensity, or its luminance (Rec. 709) as gray under neutral lights.
vec3 stylizeLightColor(vec3 c)
{
  return stylizeColorMode == 0 ? c : vec3(dot(c, vec3(0.2126, 0.7152, 0.0722)));
}

struct stylizeLight
{
  vec3 color;     // colour times intensity
  vec3 L;         // unit vector from the surface point to the light
  vec3 incident;  // unit vector from the light to the point (VTK's vertLightDirectionVC)
  float atten;    // distance attenuation times spot falloff (1 for directional lights)
};

// Fetches light i and evaluates direction and attenuation at view-space point P exactly as
// VTK 9.1's vtkOpenGLPolyDataMapper does for positional, spot and directional lights.
#ifdef STYLIZE_HEADLIGHT_ONLY
// The light class of VTK's lighting complexity 1: one enabled light, a non-positional headlight
// (this program is built for it; any other set of lights uses the general program below). Its
// colour and direction are uniforms: no buffer fetch per fragment.
uniform vec3 stylizeHeadlightColor;    // colour times intensity
uniform vec3 stylizeHeadlightIncident; // unit vector from the light, view coordinates
#define STYLIZE_LIGHT_COUNT 1
stylizeLight stylizeFetchLight(int i, vec3 P)
{
  stylizeLight l;
  l.color = stylizeLightColor(stylizeHeadlightColor);
  l.incident = stylizeHeadlightIncident;
  l.atten = 1.0;
  l.L = -l.incident;
  return l;
}
#else
#define STYLIZE_LIGHT_COUNT stylizeLightCount
stylizeLight stylizeFetchLight(int i, vec3 P)
{
  vec4 t0 = texelFetch(stylizeLights, 4 * i);
  vec4 t1 = texelFetch(stylizeLights, 4 * i + 1);
  stylizeLight l;
  l.color = stylizeLightColor(t0.rgb);
  l.atten = 1.0;
  if (t0.a < 0.5)
  {
    l.incident = t1.xyz;
  }
  else
  {
    vec4 t2 = texelFetch(stylizeLights, 4 * i + 2);
    vec4 t3 = texelFetch(stylizeLights, 4 * i + 3);
    vec3 d = P - t2.xyz;
    float dist = length(d);
    l.incident = stylizeSafeNormalize(d, t1.xyz);
    float denom = t3.x + t3.y * dist + t3.z * dist * dist;
    l.atten = denom > 0.0 ? 1.0 / denom : 0.0;
    if (t1.w < 90.0)
    {
      float coneDot = dot(l.incident, t1.xyz);
      l.atten = coneDot >= cos(radians(t1.w)) ? l.atten * stylizeSafePow(coneDot, t2.w) : 0.0;
    }
  }
  l.L = -l.incident;
  return l;
}

// VTK's own Phong model, term for term (vtkOpenGLPolyDataMapper::ReplaceShaderLight, 9.1).
#endif

vec3 stylizeStandard(vec3 N, vec3 P, vec3 ambientC, vec3 diffuseC, vec3 specularC, float specPow)
{
#ifdef STYLIZE_HEADLIGHT_ONLY
  // VTK's shortcut for a single headlight (lighting complexity 1)
  vec3 lc = stylizeLightColor(stylizeHeadlightColor);
  float df = max(0.0, N.z);
  float sf = stylizeSafePow(df, specPow);
  return ambientC + df * diffuseC * lc + sf * specularC * lc;
#else
  if (stylizeLightCount == 0)
  {
    return ambientC + diffuseC; // VTK renders unlit when no light is on
  }
  vec3 V = stylizeSafeNormalize(-P, vec3(0.0, 0.0, 1.0));
  vec3 diffuse = vec3(0.0);
  vec3 specular = vec3(0.0);
  for (int i = 0; i < STYLIZE_LIGHT_COUNT; ++i)
  {
    stylizeLight l = stylizeFetchLight(i, P);
    float df = max(0.0, l.atten * dot(N, l.L));
    diffuse += df * l.color;
    float sf = sign(df) * l.atten * stylizeSafePow(max(0.0, dot(reflect(l.incident, N), V)), specPow);
    specular += sf * l.color;
  }
  return ambientC + diffuse * diffuseC + specular * specularC;
#endif
}

// The comic and pixel-art models' summed light: D the diffuse (Ip att max(0, N.L)), S the
// Blinn-Phong specular (Ip att max(0, N.H)^beta where N.L >= 0).
void stylizeBlinnPhongSums(vec3 N, vec3 P, vec3 V, float specPow, out vec3 D, out vec3 S)
{
  D = vec3(0.0);
  S = vec3(0.0);
  for (int i = 0; i < STYLIZE_LIGHT_COUNT; ++i)
  {
    stylizeLight l = stylizeFetchLight(i, P);
    float ndl = dot(N, l.L);
    D += l.color * (l.atten * max(0.0, ndl));
    vec3 H = stylizeSafeNormalize(l.L + V, N);
    S += l.color * (l.atten * step(0.0, ndl) * stylizeSafePow(max(0.0, dot(N, H)), specPow));
  }
}

// Comic model: La = p1 + I - 2 p1 I; Ld = floor(pd kd D) / pmax with pd interpolated from near to
// far depth and D the summed light (Ip max(0, N.L)); Blinn-Phong specular times a gain.
vec3 stylizeComic(vec3 N, vec3 P, vec3 V, vec3 ambientC, vec3 diffuseC, vec3 specularC,
  float specPow, float ka, float kd)
{
  float I = clamp(ka, 0.0, 1.0);
  float p1 = stylizeSubjectFactor;
  float La = p1 + I - 2.0 * p1 * I;
  vec3 diffuseBase = kd > 1e-6 ? diffuseC / kd : vec3(0.0);
  vec3 ambientBase = ka > 1e-6 ? ambientC / ka : diffuseBase;

  float span = stylizeDepthRange.y - stylizeDepthRange.x;
  float t = span > 0.0 ? clamp((-P.z - stylizeDepthRange.x) / span, 0.0, 1.0) : 0.0;
  float pd = mix(stylizeLevelsNear, stylizeLevelsFar, t);
  float pmax = max(max(stylizeLevelsNear, stylizeLevelsFar), 1.0);

  vec3 D, S;
  stylizeBlinnPhongSums(N, P, V, specPow, D, S);
  float Dmax = max(D.r, max(D.g, D.b));
  float q = floor(pd * kd * Dmax) / pmax;
  vec3 tint = Dmax > 0.0 ? D / Dmax : vec3(0.0);
  return La * ambientBase + q * tint * diffuseBase + stylizeSpecularGain * S * specularC;
}

// Pixel-art model: Ld = sqrt(s) kd I att max(0, N.L); Ls = M ks Ip max(0, N.H)^beta.
// att is VTK's attenuation 1/(a0 + a1 r + a2 r^2): 1/r^2 for (0,0,1), 1 for directional lights.
vec3 stylizePixelArt(vec3 N, vec3 P, vec3 V, vec3 ambientC, vec3 diffuseC, vec3 specularC,
  float specPow)
{
  vec3 D, S;
  stylizeBlinnPhongSums(N, P, V, specPow, D, S);
  return ambientC + sqrt(stylizeScattering) * D * diffuseC + stylizeOcclusion * S * specularC;
}

// The colour of the lit surface for the colour modes 2 to 4: the surface's hue and saturation at
// full value (modes 3 and 4) or white, times the tone (the luminance of `lit`, the surface lit as
// white, or in its solid colour under stylizeSolidColorTones).
vec3 stylizeToned(vec3 lit, vec3 ambientC, vec3 diffuseC, float ka, float kd, bool solid)
{
  float tone = dot(lit, vec3(0.2126, 0.7152, 0.0722));
#ifdef STYLIZE_DATA_COLORS
  bool hue = stylizeColorMode >= 3;
#else
  bool hue = stylizeColorMode == 4;
#endif
  vec3 base = kd > 1e-6 ? diffuseC / kd : (ka > 1e-6 ? ambientC / ka : vec3(1.0));
  float m = max(base.r, max(base.g, base.b));
  vec3 paper = hue && m > 1e-4 ? base / m : vec3(1.0);
  if (solid)
  {
    // lit in its own colour: the tone times min(1, luminance / white) over its luminance
    float l = dot(base, vec3(0.2126, 0.7152, 0.0722));
    tone *= min(1.0 / max(l, 1e-4), 1.0 / max(stylizeSolidColorWhite, 0.05));
  }
  return paper * tone;
}
