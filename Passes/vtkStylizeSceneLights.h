/**
 * @class   vtkStylizeSceneLights
 * @brief   A deterministic set of white scene lights spread evenly over a sphere around the data.
 *
 * AddLights() replaces a renderer's lights with `count` lights: none for 0, VTK's headlight for
 * 1, and for more, white scene lights on a Fibonacci (golden-angle) sphere around a centre, all
 * aimed at it. Light i sits at height y = 1 - 2 (i + 0.5) / count on the unit sphere (y up), at
 * the angle i * pi (3 - sqrt(5)) around it, scaled by the distance. The lights take turns by
 * kind (Cycle): directional, positional point light, and (DIRECTIONAL_POINT_SPOT) positional
 * spot light (cone 30 degrees, exponent 2). Every light has intensity
 * min(1, totalIntensity / count), so the summed diffuse light stays in range whatever the count.
 *
 * Used by the vtkstylize program (--lights N: totalIntensity 3, directional and point lights)
 * and by the benchmark (totalIntensity 1.5, directional, point and spot lights, so that each
 * kind's shader path is timed); from Python, e.g.
 * @code
 * vtkStylizeSceneLights.AddLights(renderer, 8, (0, 0, 0), 10.0, 3.0,
 *                                 vtkStylizeSceneLights.DIRECTIONAL_POINT, 90.0)
 * @endcode
 */

#ifndef vtkStylizeSceneLights_h
#define vtkStylizeSceneLights_h

#include "vtkObject.h"
#include "vtkStylizePassesModule.h" // for export macro

class vtkRenderer;

class VTKSTYLIZEPASSES_EXPORT vtkStylizeSceneLights : public vtkObject
{
public:
  static vtkStylizeSceneLights* New();
  vtkTypeMacro(vtkStylizeSceneLights, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The kinds of light the sphere's lights take in turn (the value is the cycle's length). */
  enum Cycles
  {
    DIRECTIONAL_POINT = 2,     ///< directional, point, directional, ...
    DIRECTIONAL_POINT_SPOT = 3 ///< directional, point, spot (cone 30 degrees, exponent 2), ...
  };

  /**
   * Replaces the renderer's lights (and turns its automatic light creation off):
   * - count: the number of lights; 0 (or less) none, 1 VTK's headlight, more the sphere's
   *   scene lights. Default none.
   * - center: the point the lights surround and aim at (world coordinates).
   * - distance: the sphere's radius, the distance of each light from center (world units, > 0).
   * - totalIntensity: each light's intensity is min(1, totalIntensity / count); range [0, inf),
   *   default 3 (about a quarter of the lights face a point, so its summed diffuse light stays
   *   below 1).
   * - cycle: DIRECTIONAL_POINT (default) or DIRECTIONAL_POINT_SPOT (Cycles).
   * - pointConeAngle: the cone angle of the point lights, degrees; 90 or more is a point light,
   *   not a spot (VTK's own shaders treat exactly 90 as a spot in one path: 180 avoids that).
   *   Range [90, 180], default 90.
   * The positional lights have attenuation (1, 0, 0): no fall-off with distance.
   */
  static void AddLights(vtkRenderer* renderer, int count, const double center[3], double distance,
    double totalIntensity = 3.0, int cycle = DIRECTIONAL_POINT, double pointConeAngle = 90.0);

protected:
  vtkStylizeSceneLights() = default;
  ~vtkStylizeSceneLights() override = default;

private:
  vtkStylizeSceneLights(const vtkStylizeSceneLights&) = delete;
  void operator=(const vtkStylizeSceneLights&) = delete;
};

#endif
