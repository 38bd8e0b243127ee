  // VTK Stylize lighting models: implementation (replaces //VTK::Light::Impl).
  vec3 stylizeP = vertexVC.xyz;
  vec3 stylizeToViewer = cameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : -stylizeP;
  vec3 stylizeN = stylizeShadingNormal(normalVCVSOutput, stylizeFaceN, stylizeToViewer);
  vec3 stylizeV = stylizeSafeNormalize(stylizeToViewer, vec3(0.0, 0.0, 1.0));
  // Colour modes 2 to 4 light a white surface and keep only the colour's hue (stylizeToned); a
  // solid colour keeps its lightness in the tone with stylizeSolidColorTones.
  bool stylizeTone = stylizeColorMode >= 2;
#ifdef STYLIZE_DATA_COLORS
  bool stylizeWhite = stylizeTone;
#else
  bool stylizeWhite = stylizeTone && stylizeSolidColorTones == 0;
#endif
  vec3 stylizeAmbient = stylizeWhite ? vec3(ambientIntensity) : ambientColor;
  vec3 stylizeDiffuse = stylizeWhite ? vec3(diffuseIntensity) : diffuseColor;
  // One model per program (STYLIZE_MODEL): a uniform branch would run all three per fragment.
#if STYLIZE_MODEL == 1
  vec3 stylizeRGB = stylizeComic(stylizeN, stylizeP, stylizeV, stylizeAmbient, stylizeDiffuse,
    specularColor, specularPower, ambientIntensity, diffuseIntensity);
#elif STYLIZE_MODEL == 2
  vec3 stylizeRGB = stylizePixelArt(stylizeN, stylizeP, stylizeV, stylizeAmbient, stylizeDiffuse,
    specularColor, specularPower);
#else
  vec3 stylizeRGB = stylizeStandard(stylizeN, stylizeP, stylizeAmbient, stylizeDiffuse,
    specularColor, specularPower);
#endif
  if (stylizeEmitted == 1)
  {
    stylizeRGB = ambientColor + diffuseColor; // colours that are light already: as they are
  }
  if (stylizeTone)
  {
    stylizeRGB = stylizeToned(stylizeRGB, ambientColor, diffuseColor, ambientIntensity,
      diffuseIntensity, !stylizeWhite && stylizeEmitted == 0);
  }
  gl_FragData[0] = vec4(stylizeSaturateFinite(stylizeRGB), opacity);
