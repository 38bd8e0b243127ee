// VTK Stylize: copies the G-buffer's colour and depth into the output framebuffer.
uniform sampler2D stylizeColorTexture;
uniform sampler2D stylizeDepthTexture;
uniform int stylizeDiscardBackground; // 1 for layered renderers: keep the layer below

void stylizeComposite()
{
  float depth = texture(stylizeDepthTexture, texCoord).r;
  if (stylizeDiscardBackground == 1 && depth >= 1.0)
  {
    discard;
  }
  gl_FragData[0] = texture(stylizeColorTexture, texCoord);
  gl_FragDepth = stylizeWindowDepth(depth);
}

// The volumes a style leaves to VTK, drawn by the processes and composited over each other
// (premultiplied colour in stylizeColorTexture), blended over the output by the caller.
void stylizeCompositeLayer()
{
  gl_FragData[0] = texture(stylizeColorTexture, texCoord);
}
