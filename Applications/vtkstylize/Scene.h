/**
 * vtkstylize: the scene: one actor per part (coloured by the chosen array through a colour map,
 * or solid), the title and the scalar bar, the lights and the camera.
 */
#ifndef vtkstylizeScene_h
#define vtkstylizeScene_h

#include "Options.h"
#include "vtkstylizeInput.h"

#include <map>
#include <string>
#include <vector>

class vtkRenderer;

namespace vtkstylize
{
/** What the annotations show. */
struct SceneAnnotations
{
  std::string Title;
  std::string ScalarBarArray;                   // array shown by the scalar bar, empty for none
  std::map<std::string, double> ConstantArrays; // arrays of one value: a label, not a bar
  std::vector<std::string> Warnings;            // what the caller prints after the image is written
};

/**
 * Adds an actor per part, coloured as Options says, and the annotations. `what` names the input
 * in messages; fails when --color-by names an array no part has.
 */
void AddParts(vtkRenderer* ren, const std::vector<Part>& parts, const Options& opt, bool builtIn,
  SceneAnnotations& info, const std::string& what);

/** Adds `count` lights around the scene's bounds (see --lights). */
void AddLights(vtkRenderer* ren, int count, const double bounds[6]);

/** Points the camera at the scene (azimuth, elevation, zoom, projection). */
void SetUpCamera(vtkRenderer* ren, const Options& opt);
}

#endif
