// The lighting regression scene: the standard test objects under one light set-up.
#ifndef LightingTestHelpers_h
#define LightingTestHelpers_h

#include "vtkStylizeTestUtilities.h"

namespace stylizetest
{
/**
 * The lighting tests' scene: a w x h window, the test actors on a dark gray-blue background lit
 * by the light set-up, seen from azimuth 25, elevation 20, 12 units away.
 */
inline TestScene MakeLightingScene(const std::string& setup, bool parallel, int w, int h)
{
  TestScene scene;
  scene.Window = MakeWindow(w, h);
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scene.Window->AddRenderer(scene.Renderer);
  scene.Renderer->SetBackground(0.3, 0.32, 0.36);
  AddTestActors(scene.Renderer);
  SetupLights(scene.Renderer, setup);
  PlaceCamera(scene.Renderer, 1.0, 25, 20, 12.0, 0.37, parallel);
  return scene;
}
}

#endif
