// VTK Stylize: a style's picture rendered at a reduced image size (interactive frames), drawn
// over the viewport: the colour filtered linearly, the window depth of the nearest pixel (what
// follows, translucent geometry and volumes, is depth-tested against it).
uniform sampler2D stylizeReducedColor; // linear filtering
uniform sampler2D stylizeReducedDepth; // window depth, read texel by texel

void stylizeUpscale()
{
  ivec2 size = textureSize(stylizeReducedDepth, 0);
  ivec2 texel = clamp(ivec2(texCoord * vec2(size)), ivec2(0), size - 1);
  gl_FragData[0] = texture(stylizeReducedColor, texCoord);
  gl_FragDepth = texelFetch(stylizeReducedDepth, texel, 0).r;
}
