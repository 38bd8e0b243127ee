  // VTK Stylize lighting models: implementation (replaces //VTK::Light::Impl).
  vec3 stylizeP = vertexVC.xyz;
  vec3 stylizeToViewer = cameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : -stylizeP;
  vec3 stylizeN = stylizeShadingNormal(normalVCVSOutput, stylizeFaceN, stylizeToViewer);
  vec3 stylizeV = stylizeSafeNormalize(stylizeToViewer, vec3(0.0, 0.0, 1.0));
  // One model per program (STYLIZE_MODEL): a uniform branch would run all three per fragment.
#if STYLIZE_MODEL == 1
  vec3 stylizeRGB = stylizeComic(stylizeN, stylizeP, stylizeV, ambientColor, diffuseColor,
    specularColor, specularPower, ambientIntensity, diffuseIntensity);
#elif STYLIZE_MODEL == 2
  vec3 stylizeRGB = stylizePixelArt(stylizeN, stylizeP, stylizeV, ambientColor, diffuseColor,
    specularColor, specularPower);
#else
  vec3 stylizeRGB = stylizeStandard(stylizeN, stylizeP, ambientColor, diffuseColor,
    specularColor, specularPower);
#endif
  gl_FragData[0] = vec4(stylizeSaturateFinite(stylizeRGB), opacity);
