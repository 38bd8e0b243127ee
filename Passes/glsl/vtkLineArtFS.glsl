// VTK Stylize line art (vtkLineArtPass): feature-line strokes in ink over the paper.
// The strokes' ink coverage is computed on the CPU (vtkStylizeFeatureStrokes) and arrives as a
// texture; this stage lays it over the paper or the flat tone. The pass prepends:
//   LINE_ART_STAGE_FINAL  the only stage: paper, tone and ink into the output
//   LINE_ART_SHADES       the lit tone in lineArtToneLevels flat shades (Tone SHADES)
//   LINE_ART_DOTS         the lit tone as the comic's halftone dots (Tone DOTS), with the
//                         comic's dot constants (vtkComicPatterns.h)
//   LINE_ART_LAYER        0 the line art, 1 the paper alone (vector figures)

#ifdef LINE_ART_STAGE_FINAL
uniform sampler2D lineArtInk;     // ink coverage of the strokes in [0, 1], one per pixel
uniform vec3 lineArtInkColor;
uniform vec3 lineArtPaperColor;
uniform int lineArtToneLevels;    // shades, the paper included (>= 2)
uniform float lineArtToneDarkest; // the darkest shade's share of the paper's brightness
uniform float lineArtDotSpacing;  // LINE_ART_DOTS: the dot grid's period, pixels
uniform vec2 lineArtPixelOffset;  // this tile's offset in the full image (pixels)

void lineArtMain()
{
  ivec2 size = textureSize(stylizeColorTexture, 0);
  ivec2 p = clamp(ivec2(texCoord * vec2(size)), ivec2(0), size - 1);
  vec4 image = texelFetch(stylizeColorTexture, p, 0);
  float depth = texelFetch(stylizeDepthTexture, p, 0).r;
  bool background = !(depth < 1.0);
  float ink = clamp(texelFetch(lineArtInk, p, 0).r, 0.0, 1.0);
  vec3 paper = lineArtPaperColor;
  // Lines and points (no linear depth) are the user's own lines: drawn in ink.
  bool surface = texelFetch(stylizeLinearDepthTexture, p, 0).r > 0.0;
#ifdef LINE_ART_DOTS
  // The comic's halftone dots at 45 degrees on the full image's grid (computed everywhere:
  // the derivatives need uniform control flow).
  vec2 dotUV = stylizeRotate((vec2(p) + 0.5 + lineArtPixelOffset) / lineArtDotSpacing,
    vec2(0.70710678, 0.70710678));
  float dotAA = clamp(0.5 * max(fwidth(dotUV.x), fwidth(dotUV.y)), 1e-4, 0.5);
  float lit = dot(stylizeSaturateFinite(image.rgb), vec3(0.2126, 0.7152, 0.0722));
  float dots = stylizeHalftoneDots(dotUV, lit, dotAA);
  paper = mix(lineArtInkColor, paper, surface ? dots : 1.0);
#endif
#ifdef LINE_ART_SHADES
  // Flat shades of the lit luminance: level 0 (darkest) .. levels - 1 (the paper).
  vec3 lit = stylizeSaturateFinite(image.rgb);
  float tone = dot(lit, vec3(0.2126, 0.7152, 0.0722));
  float top = float(lineArtToneLevels - 1);
  float level = min(floor(tone * float(lineArtToneLevels)), top);
  paper *= mix(lineArtToneDarkest, 1.0, level / top);
#endif
  vec3 under = background ? stylizeSaturateFinite(image.rgb) : (surface ? paper : lineArtInkColor);
#if LINE_ART_LAYER == 1
  ink = 0.0;
#endif
  if (stylizeDiscardBackground == 1 && background && ink <= 0.0)
  {
    discard;
  }
  gl_FragData[0] = stylizeOutput(background, mix(under, lineArtInkColor, ink), image.a, ink);
  gl_FragDepth = stylizeWindowDepth(depth);
}
#endif
