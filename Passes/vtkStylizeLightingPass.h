/**
 * @class   vtkStylizeLightingPass
 * @brief   Replaces VTK's lighting with a selectable model (Standard, Comic, PixelArt).
 *
 * vtkStylizeLightingPass is a vtkOpenGLRenderPass. For every vtkOpenGLPolyDataMapper its
 * delegate renders, it replaces the `//VTK::Light::Dec` and `//VTK::Light::Impl` parts of the
 * fragment shader with one of three models: Standard (VTK's own Phong model, term for term),
 * Comic (subject ambient term, depth-dependent quantized diffuse, boosted specular;
 * docs/algorithms.md section 2) or PixelArt (scattered diffuse, occluded specular; section 1).
 * It uses the renderer's own vtkLight objects, any number of them with one compiled program.
 * The Comic parameters may be set per actor with information keys (SetActorSubjectFactor()
 * etc.); an actor without a key uses the pass's value.
 * @code
 * vtkNew<vtkStylizeLightingPass> lighting;
 * lighting->SetModelToComic();
 * renderer->SetPass(lighting); // the delegate defaults to a vtkRenderStepsPass
 * vtkStylizeLightingPass::SetActorSubjectFactor(subjectActor, 0.8);
 * @endcode
 *
 * Formulas, special cases (no light, unlit actors, PBR, NaN) and programs: docs/lighting.md.
 *
 * @sa vtkStylizeGBufferPass
 */

#ifndef vtkStylizeLightingPass_h
#define vtkStylizeLightingPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkStylizePassesModule.h" // for export macro
#include "vtkTimeStamp.h"           // for vtkTimeStamp

#include <vector> // for std::vector

class vtkInformationDoubleKey;
class vtkLight;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRenderer;
class vtkTextureObject;

class VTKSTYLIZEPASSES_EXPORT vtkStylizeLightingPass : public vtkOpenGLRenderPass
{
public:
  static vtkStylizeLightingPass* New();
  vtkTypeMacro(vtkStylizeLightingPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The lighting models. */
  enum Models
  {
    STANDARD = 0,
    COMIC = 1,
    PIXEL_ART = 2
  };

  ///@{
  /**
   * The lighting model, one of STANDARD, COMIC and PIXEL_ART. Default STANDARD. Each model is
   * compiled into the mappers' shaders alone (a #define, not a uniform branch: with the three
   * models in one program the lighting cost twice VTK's own at one light on llvmpipe), so
   * changing it rebuilds those shaders once; the light count never does (VTK's single headlight
   * has a program of its own per model, built once; docs/lighting.md).
   */
  vtkSetClampMacro(Model, int, STANDARD, PIXEL_ART);
  vtkGetMacro(Model, int);
  void SetModelToStandard() { this->SetModel(STANDARD); }
  void SetModelToComic() { this->SetModel(COMIC); }
  void SetModelToPixelArt() { this->SetModel(PIXEL_ART); }
  ///@}

  /** Name of a model ("standard", "comic", "pixelart"), or nullptr when out of range. */
  static const char* GetModelName(int model);
  /** Model for a name as GetModelName() spells it (case-insensitive), or -1. */
  static int GetModelFromName(const char* name);

  ///@{
  /**
   * The pass that renders the scene. Default: nullptr, in which case a vtkRenderStepsPass is
   * created on first use.
   */
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  virtual void SetDelegatePass(vtkRenderPass* delegatePass);
  ///@}

  ///@{
  /**
   * Comic: subject factor p1 of the ambient term `La = p1 + I - 2 p1 I`, dimensionless, in
   * [0, 1]. 0 gives La = I (ordinary ambient), 1 gives La = 1 - I (the subject responds inversely
   * to ambient light). Default 0.35: with the default gray levels, the lit half of a real mesh
   * reaches white (paper in the comic style), the ambient-only shadow band is hatched, and the
   * halftone follows the Standard model's tone (correlation >= 0.8 on the real-data set,
   * docs/comic.md). Per actor: SUBJECT_FACTOR().
   */
  vtkSetClampMacro(SubjectFactor, double, 0.0, 1.0);
  vtkGetMacro(SubjectFactor, double);
  ///@}

  ///@{
  /**
   * Comic: number of gray levels pd of the quantized diffuse term at the near end (GrayLevelsNear)
   * and the far end (GrayLevelsFar) of the visible depth range, in [0, 100]; pd varies linearly
   * in between. 0 gives black diffuse. Defaults 6 and 6: equal, so that a flat face is one tone
   * whatever its depth (the paper's depth-dependent levels split it). Per actor:
   * GRAY_LEVELS_NEAR(), GRAY_LEVELS_FAR().
   */
  vtkSetClampMacro(GrayLevelsNear, double, 0.0, 100.0);
  vtkGetMacro(GrayLevelsNear, double);
  vtkSetClampMacro(GrayLevelsFar, double, 0.0, 100.0);
  vtkGetMacro(GrayLevelsFar, double);
  ///@}

  ///@{
  /**
   * Comic: gain applied to the Blinn-Phong specular term, dimensionless, in [0, 100].
   * Default 1.5. Per actor: SPECULAR_GAIN().
   */
  vtkSetClampMacro(SpecularGain, double, 0.0, 100.0);
  vtkGetMacro(SpecularGain, double);
  ///@}

  /** What the lit colour is made of (ColorMode). */
  enum ColorModes
  {
    LIT_COLORS = 0,     ///< the surface's colours times the lights' (VTK's lighting)
    NEUTRAL_LIGHTS = 1, ///< the surface's colours times the lights' luminance
    LIGHT_TONE = 2,     ///< gray: the tone of a white surface under neutral lights
    DATA_HUES = 3,      ///< surfaces coloured by an array: their hue times the tone; others gray
    ALL_HUES = 4        ///< every surface: its colour's hue times the tone
  };

  ///@{
  /**
   * What the lit colour is made of: LIT_COLORS (default), NEUTRAL_LIGHTS, LIGHT_TONE, DATA_HUES
   * or ALL_HUES. Values: LIT_COLORS, the surface's colours times the lights' (VTK's lighting);
   * NEUTRAL_LIGHTS, the surface's colours times the lights' luminance: a gray surface stays gray
   * under a coloured light kit (ParaView's); LIGHT_TONE, gray: the tone of a white surface under
   * neutral lights (the property's ambient and diffuse coefficients still apply), so a
   * black-and-white style draws the shading, not the data's colours as grays; DATA_HUES, on
   * surfaces coloured by an array (point or cell scalars through a colour map, or direct
   * colours) the colour's hue and saturation at full value times that tone, other surfaces
   * gray; ALL_HUES, the same on every surface. In the last three the tone comes from the light
   * alone, so a surface coloured by a dark or mid-luminance colour map is not drawn as shadow;
   * the largest channel of the lit colour is the tone. The style passes set it for their
   * lighting pass every frame (vtkStylizeStylePass::ConfigureLightingColors()).
   */
  vtkSetClampMacro(ColorMode, int, LIT_COLORS, ALL_HUES);
  vtkGetMacro(ColorMode, int);
  ///@}

  ///@{
  /**
   * In the colour modes LIGHT_TONE, DATA_HUES and ALL_HUES: whether a solid colour's lightness
   * darkens the tone. On: a dark gray actor is drawn darker than a white one under the same
   * light (the sketch: the pencil renders the material's value; the comic, from a luminance
   * below SolidColorWhite); off (default): every solid colour is lit as white. A colour from an
   * array is lit as white either way: a colour map's lightness is not the surface's. The style
   * passes set it with ColorMode.
   */
  vtkSetMacro(SolidColorTones, bool);
  vtkGetMacro(SolidColorTones, bool);
  vtkBooleanMacro(SolidColorTones, bool);
  ///@}

  ///@{
  /**
   * With SolidColorTones: the luminance (Rec. 709) from which a solid colour is lit as white, in
   * [0.05, 1], default 1. Darker colours scale the tone by their luminance over this value, so 1
   * keeps each colour's own lightness (the sketch) and a lower value draws light colours as white
   * and only dark ones darker (the comic's 0.75: a light gray part stays paper in the light, a
   * dark glyph or part is hatched). The style passes set it with ColorMode.
   */
  vtkSetClampMacro(SolidColorWhite, double, 0.05, 1.0);
  vtkGetMacro(SolidColorWhite, double);
  ///@}

  ///@{
  /**
   * PixelArt: scattering degree s of the lights, in [0, 1]; the diffuse term is scaled by
   * sqrt(s). The paper finds [0.5, 1] useful. Default 1.
   */
  vtkSetClampMacro(Scattering, double, 0.0, 1.0);
  vtkGetMacro(Scattering, double);
  ///@}

  ///@{
  /**
   * PixelArt: specular occlusion factor M, in [0, 1], a constant for the whole scene (the paper's
   * M darkens surfaces blocked by neighbours; a screen-space estimate is left to the style pass).
   * Default 1.
   */
  vtkSetClampMacro(SpecularOcclusion, double, 0.0, 1.0);
  vtkGetMacro(SpecularOcclusion, double);
  ///@}

  ///@{
  /**
   * Per-actor Comic settings, stored in vtkProp::GetPropertyKeys(). Values outside the ranges of
   * the corresponding pass settings are clamped when used.
   */
  static vtkInformationDoubleKey* SUBJECT_FACTOR();
  static vtkInformationDoubleKey* GRAY_LEVELS_NEAR();
  static vtkInformationDoubleKey* GRAY_LEVELS_FAR();
  static vtkInformationDoubleKey* SPECULAR_GAIN();
  ///@}

  /**
   * Per actor, in vtkProp::GetPropertyKeys(): 1 when the actor's colours are light already (a
   * volume's fog as VTK's ray caster shades it, vtkStylizeStylePass::HAZE_FOG): drawn as they
   * are, unlit by the style, their luminance the tone in colour modes 2 to 4. 0 or absent
   * (default): lit by the style.
   */
  static vtkInformationDoubleKey* EMITTED_COLORS();

  ///@{
  /**
   * Set (with clamping) or remove the per-actor Comic settings of a prop. The prop's property
   * keys are created when it has none.
   */
  static void SetActorSubjectFactor(vtkProp* prop, double p1);
  static void SetActorGrayLevels(vtkProp* prop, double levelsNear, double levelsFar);
  static void SetActorSpecularGain(vtkProp* prop, double gain);
  static void RemoveActorSettings(vtkProp* prop);
  ///@}

  /** Number of enabled lights packed for the last frame. */
  vtkGetMacro(NumberOfLights, int);

  /**
   * The largest number of lights the OpenGL implementation can hold (GL_MAX_TEXTURE_BUFFER_SIZE
   * / 4), or -1 before the first render. Lights beyond it are ignored with a warning.
   */
  vtkGetMacro(MaximumNumberOfLights, int);

  /** Renders the delegate with the lighting model. */
  void Render(const vtkRenderState* s) override;

  /**
   * Renders an arbitrary pass with the lighting model: packs the lights, installs the shader
   * hooks on the props of @p s, renders @p delegate and removes the hooks. Used by
   * vtkStylizeGBufferPass and the style passes to light only some of the render steps.
   */
  void RenderWithLighting(const vtkRenderState* s, vtkRenderPass* delegate);

  /** Frees the light buffer and the delegate's resources. */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /** When the mappers' shaders must be rebuilt: the last change of Model. */
  vtkMTimeType GetShaderStageMTime() override;

  ///@{
  /** vtkOpenGLRenderPass shader hooks. */
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  ///@}

protected:
  vtkStylizeLightingPass();
  ~vtkStylizeLightingPass() override;

  /** Packs the renderer's enabled lights in view coordinates and uploads them when changed. */
  void UploadLights(vtkRenderer* ren, vtkOpenGLRenderWindow* renWin);

  vtkRenderPass* DelegatePass = nullptr;
  int Model = STANDARD;
  int ShaderModel = -1;         // the model the mappers' shaders were last built for
  int ShaderHeadlightOnly = -1; // and the light class (1: VTK's single headlight)
  vtkTimeStamp ModelTime;       // when either changed: GetShaderStageMTime()
  double SubjectFactor = 0.35;
  double GrayLevelsNear = 6.0;
  double GrayLevelsFar = 6.0;
  double SpecularGain = 1.5;
  int ColorMode = LIT_COLORS;
  bool SolidColorTones = false;
  double SolidColorWhite = 1.0;
  double Scattering = 1.0;
  double SpecularOcclusion = 1.0;

  int NumberOfLights = 0;
  int MaximumNumberOfLights = -1;
  int HeadlightOnly = 0;
  double DepthRange[2] = { 0.0, 1.0 };

  vtkOpenGLBufferObject* LightBuffer = nullptr;
  vtkTextureObject* LightTexture = nullptr;
  unsigned int LightTextureTexels = 0;
  std::vector<float> LightData;
  vtkMTimeType LightSignature = 0;
  vtkLight* CarrierLight = nullptr;

private:
  vtkStylizeLightingPass(const vtkStylizeLightingPass&) = delete;
  void operator=(const vtkStylizeLightingPass&) = delete;
};

#endif
