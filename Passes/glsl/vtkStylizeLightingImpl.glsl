  // VTK Stylize lighting models: implementation (replaces //VTK::Light::Impl).
  vec3 stylizeP = vertexVC.xyz;
  vec3 stylizeToViewer = cameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : -stylizeP;
  vec3 stylizeN = stylizeShadingNormal(normalVCVSOutput, stylizeFaceN, stylizeToViewer);
  vec3 stylizeV = stylizeSafeNormalize(stylizeToViewer, vec3(0.0, 0.0, 1.0));
  vec3 stylizeRGB;
  if (stylizeModel == 1)
  {
    stylizeRGB = stylizeComic(stylizeN, stylizeP, stylizeV, ambientColor, diffuseColor,
      specularColor, specularPower, ambientIntensity, diffuseIntensity);
  }
  else if (stylizeModel == 2)
  {
    stylizeRGB = stylizePixelArt(stylizeN, stylizeP, stylizeV, ambientColor, diffuseColor,
      specularColor, specularPower);
  }
  else
  {
    stylizeRGB = stylizeStandard(stylizeN, stylizeP, ambientColor, diffuseColor, specularColor,
      specularPower);
  }
  gl_FragData[0] = vec4(stylizeSaturateFinite(stylizeRGB), opacity);
