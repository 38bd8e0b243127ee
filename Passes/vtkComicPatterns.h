/**
 * @namespace vtkComicPatterns
 * @brief   The comic's halftone dots, hatch lines and zones: the numbers and formulas that the
 *          pass's shader and the vector figure share.
 *
 * vtkComicPass draws its pattern in GLSL (glsl/vtkComicFS.glsl); vtkStylizeFigureWriter draws
 * the same pattern as cairo shapes. Both take their constants from here: the pass prepends
 * ShaderDefines() (COMIC_PI, COMIC_DOT_*, COMIC_FIXED_ANGLE_STEP) to the shader's source, and the
 * figure calls the inline functions below, which are the shader's formulas in C++.
 *
 * Lengths are in units of the pattern's cell (the dot spacing, the hatch spacing); tones are
 * luminances in [0, 1], 1 being the paper.
 *
 * @sa vtkComicPass vtkStylizeFigureWriter
 */

#ifndef vtkComicPatterns_h
#define vtkComicPatterns_h
#ifndef __VTK_WRAP__

#include <algorithm> // for std::min, std::max
#include <cmath>     // for std::sqrt
#include <cstdio>    // for std::snprintf
#include <cstdlib>   // for std::strtod
#include <string>    // for std::string

namespace vtkComicPatterns
{
/** Pi, as both sides spell it. */
constexpr double Pi = 3.14159265358979323846;

/** The ink a dot covers of its cell at `tone`. */
inline double DotCoverage(double tone)
{
  return std::min(1.0, std::max(0.0, 1.0 - tone));
}

///@{
/**
 * The halftone dot of a cell: a disc of area equal to the ink's coverage until it touches the
 * cell's sides (coverage DotDiscCoverage, about pi/4, radius DotInscribedRadius), then a disc
 * clipped to the cell whose radius grows linearly with the coverage over the last
 * DotCornerCoverage, to DotCornerRadius (just past the half diagonal: the whole cell is ink).
 */
constexpr double DotDiscCoverage = 0.785398;
constexpr double DotCornerCoverage = 0.214602;
constexpr double DotInscribedRadius = 0.5;
constexpr double DotCornerRadius = 0.7072;
///@}

/** The radius of the dot (cell units) that covers `coverage` of its cell (eq. 10). */
inline double DotRadius(double coverage)
{
  return coverage <= DotDiscCoverage ? std::sqrt(coverage / Pi)
                                     : DotInscribedRadius +
      (DotCornerRadius - DotInscribedRadius) * (coverage - DotDiscCoverage) / DotCornerCoverage;
}

/**
 * The zone weight t of eq. 13-14 (1: dots, 0: hatching): dots above `bright`, hatching below
 * `dark`, blended linearly between; a step at `dark` when the thresholds do not bound a range.
 */
inline double Zone(double tone, double bright, double dark)
{
  if (bright > dark)
  {
    return std::min(1.0, std::max(0.0, (tone - dark) / (bright - dark)));
  }
  return tone < dark ? 0.0 : 1.0;
}

/**
 * The hatch direction's step that the layer FIGURE_INPUTS records where the lines run at the
 * fixed HatchAngle (no normal-dependent or principal step).
 */
constexpr int FixedAngleStep = 255;

/**
 * The screen of a fog's opacity (a translucent layer of emitted colours: its opacity drawn as
 * dots covering that share of each cell, since the comic draws no plain gradient): its angle
 * from the tone's dots, radians (30 degrees, so that the two screens do not beat into moire).
 */
constexpr double FogScreenAngle = Pi / 6.0;

/** Hatch steps over 180 degrees along the principal directions when HatchDirections is 0. */
constexpr int DefaultPrincipalSteps = 8;

/** HatchWidth as a fraction of HatchSpacing, at most 1; 0 (the width follows the tone) for 0. */
inline double HatchWidthFraction(double width, double spacing)
{
  return width > 0 ? std::min(1.0, width / spacing) : 0.0;
}

/**
 * The width of a hatch line (a fraction of the spacing) at `tone`: `fixedWidth` when positive,
 * else the tone's own, such that one direction covers 1 - tone and, `crossed`, two crossed
 * directions of width 1 - sqrt(tone) cover 1 - tone together.
 */
inline double HatchLineWidth(double tone, double fixedWidth, bool crossed)
{
  if (fixedWidth > 0)
  {
    return fixedWidth;
  }
  return crossed ? 1.0 - std::sqrt(std::min(1.0, std::max(0.0, tone)))
                 : std::min(1.0, std::max(0.0, 1.0 - tone));
}

/** The angle (radians) between two hatch directions when there are `steps` over 180 degrees. */
inline double HatchAngleStep(int steps)
{
  return Pi / std::max(1, steps);
}

/** The hatch steps over 180 degrees along the principal directions, from HatchDirections. */
inline int PrincipalSteps(int hatchDirections)
{
  return hatchDirections > 0 ? hatchDirections : DefaultPrincipalSteps;
}

/**
 * The constants as GLSL #defines, one a line, each a float literal that reads back as the
 * constant: the comic shader's source starts with them.
 */
inline std::string ShaderDefines()
{
  auto literal = [](double value)
  {
    char text[32];
    for (int digits = 15; digits <= 17; ++digits)
    {
      std::snprintf(text, sizeof(text), "%.*g", digits, value);
      if (std::strtod(text, nullptr) == value)
      {
        break;
      }
    }
    std::string s = text;
    return s.find_first_of(".e") == std::string::npos ? s + ".0" : s;
  };
  std::string defines;
  auto define = [&](const char* name, double value)
  { defines += std::string("#define ") + name + " " + literal(value) + "\n"; };
  define("COMIC_PI", Pi);
  define("COMIC_DOT_DISC_COVERAGE", DotDiscCoverage);
  define("COMIC_DOT_CORNER_COVERAGE", DotCornerCoverage);
  define("COMIC_DOT_INSCRIBED_RADIUS", DotInscribedRadius);
  define("COMIC_DOT_CORNER_RADIUS", DotCornerRadius);
  define("COMIC_FIXED_ANGLE_STEP", FixedAngleStep);
  define("COMIC_FOG_SCREEN_ANGLE", FogScreenAngle);
  return defines;
}
}

#endif // __VTK_WRAP__
#endif
