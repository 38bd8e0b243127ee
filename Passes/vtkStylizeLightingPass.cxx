#include "vtkStylizeLightingPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransform.h"
#include "vtk_glew.h"

#include "vtkStylizeLightingDec.h"
#include "vtkStylizeLightingImpl.h"
#include "vtkStylizeShaderUtilities.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkStylizeLightingPass);
vtkCxxSetObjectMacro(vtkStylizeLightingPass, DelegatePass, vtkRenderPass);

vtkInformationKeyMacro(vtkStylizeLightingPass, SUBJECT_FACTOR, Double);
vtkInformationKeyMacro(vtkStylizeLightingPass, GRAY_LEVELS_NEAR, Double);
vtkInformationKeyMacro(vtkStylizeLightingPass, GRAY_LEVELS_FAR, Double);
vtkInformationKeyMacro(vtkStylizeLightingPass, SPECULAR_GAIN, Double);
vtkInformationKeyMacro(vtkStylizeLightingPass, EMITTED_COLORS, Double);

namespace
{
const char* const ModelNames[] = { "standard", "comic", "pixelart" };
const char* const LightImplTag = "//VTK::StylizeLight::Impl";
const char* const LightDecTag = "//VTK::StylizeLight::Dec";

double Clamp(double v, double lo, double hi)
{
  return std::isfinite(v) ? std::min(std::max(v, lo), hi) : lo;
}

vtkInformation* EnsureKeys(vtkProp* prop)
{
  if (!prop->GetPropertyKeys())
  {
    vtkNew<vtkInformation> info;
    prop->SetPropertyKeys(info);
  }
  return prop->GetPropertyKeys();
}

double ActorValue(
  vtkProp* prop, vtkInformationDoubleKey* key, double fallback, double lo, double hi)
{
  vtkInformation* info = prop ? prop->GetPropertyKeys() : nullptr;
  if (info && info->Has(key))
  {
    return Clamp(info->Get(key), lo, hi);
  }
  return fallback;
}
}

//------------------------------------------------------------------------------
vtkStylizeLightingPass::vtkStylizeLightingPass() = default;

//------------------------------------------------------------------------------
vtkStylizeLightingPass::~vtkStylizeLightingPass()
{
  this->SetDelegatePass(nullptr);
  if (this->LightTexture)
  {
    this->LightTexture->Delete();
  }
  if (this->LightBuffer)
  {
    this->LightBuffer->Delete();
  }
  if (this->CarrierLight)
  {
    this->CarrierLight->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkStylizeLightingPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Model: " << GetModelName(this->Model) << "\n";
  os << indent << "SubjectFactor: " << this->SubjectFactor << "\n";
  os << indent << "GrayLevelsNear: " << this->GrayLevelsNear << "\n";
  os << indent << "GrayLevelsFar: " << this->GrayLevelsFar << "\n";
  os << indent << "SpecularGain: " << this->SpecularGain << "\n";
  os << indent << "ColorMode: " << this->ColorMode << "\n";
  os << indent << "SolidColorTones: " << this->SolidColorTones << "\n";
  os << indent << "SolidColorWhite: " << this->SolidColorWhite << "\n";
  os << indent << "Scattering: " << this->Scattering << "\n";
  os << indent << "SpecularOcclusion: " << this->SpecularOcclusion << "\n";
  os << indent << "NumberOfLights: " << this->NumberOfLights << "\n";
  os << indent << "MaximumNumberOfLights: " << this->MaximumNumberOfLights << "\n";
  os << indent << "DelegatePass: ";
  if (this->DelegatePass)
  {
    os << this->DelegatePass->GetClassName() << "\n";
  }
  else
  {
    os << "(none)\n";
  }
}

//------------------------------------------------------------------------------
const char* vtkStylizeLightingPass::GetModelName(int model)
{
  return (model >= STANDARD && model <= PIXEL_ART) ? ModelNames[model] : nullptr;
}

//------------------------------------------------------------------------------
int vtkStylizeLightingPass::GetModelFromName(const char* name)
{
  if (!name)
  {
    return -1;
  }
  std::string n(name);
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::tolower(c); });
  n.erase(
    std::remove_if(n.begin(), n.end(), [](char c) { return c == '-' || c == '_' || c == ' '; }),
    n.end());
  for (int m = STANDARD; m <= PIXEL_ART; ++m)
  {
    if (n == ModelNames[m])
    {
      return m;
    }
  }
  return n == "pixel" ? PIXEL_ART : -1;
}

//------------------------------------------------------------------------------
void vtkStylizeLightingPass::SetActorSubjectFactor(vtkProp* prop, double p1)
{
  if (prop)
  {
    EnsureKeys(prop)->Set(SUBJECT_FACTOR(), Clamp(p1, 0.0, 1.0));
  }
}

//------------------------------------------------------------------------------
void vtkStylizeLightingPass::SetActorGrayLevels(vtkProp* prop, double levelsNear, double levelsFar)
{
  if (prop)
  {
    vtkInformation* info = EnsureKeys(prop);
    info->Set(GRAY_LEVELS_NEAR(), Clamp(levelsNear, 0.0, 100.0));
    info->Set(GRAY_LEVELS_FAR(), Clamp(levelsFar, 0.0, 100.0));
  }
}

//------------------------------------------------------------------------------
void vtkStylizeLightingPass::SetActorSpecularGain(vtkProp* prop, double gain)
{
  if (prop)
  {
    EnsureKeys(prop)->Set(SPECULAR_GAIN(), Clamp(gain, 0.0, 100.0));
  }
}

//------------------------------------------------------------------------------
void vtkStylizeLightingPass::RemoveActorSettings(vtkProp* prop)
{
  vtkInformation* info = prop ? prop->GetPropertyKeys() : nullptr;
  if (info)
  {
    info->Remove(SUBJECT_FACTOR());
    info->Remove(GRAY_LEVELS_NEAR());
    info->Remove(GRAY_LEVELS_FAR());
    info->Remove(SPECULAR_GAIN());
  }
}

//------------------------------------------------------------------------------
void vtkStylizeLightingPass::UploadLights(vtkRenderer* ren, vtkOpenGLRenderWindow* renWin)
{
  vtkCamera* cam = ren->GetActiveCamera();
  vtkTransform* viewTF = cam->GetModelViewTransformObject();
  vtkOpenGLRenderer* oglRen = vtkOpenGLRenderer::SafeDownCast(ren);
  vtkTransform* userTF = oglRen ? oglRen->GetUserLightTransform() : nullptr;
  vtkLightCollection* lc = ren->GetLights();

  if (this->MaximumNumberOfLights < 0)
  {
    int maxTexels = 0;
    renWin->GetState()->vtkglGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    this->MaximumNumberOfLights = std::max(maxTexels / 4, 1);
  }

  // Signature of everything the packed data depends on.
  vtkMTimeType signature = std::max(lc->GetMTime(), cam->GetMTime());
  if (userTF)
  {
    signature = std::max(signature, userTF->GetMTime());
  }
  vtkCollectionSimpleIterator sit;
  vtkLight* light;
  for (lc->InitTraversal(sit); (light = lc->GetNextLight(sit));)
  {
    signature = std::max(signature, light->GetMTime());
  }
  if (this->LightTexture && signature == this->LightSignature &&
    this->LightTexture->GetContext() == renWin)
  {
    return;
  }
  this->LightSignature = signature;

  this->LightData.clear();
  int count = 0;
  int headlights = 0;
  bool anyPositional = false;
  bool warned = false;
  for (lc->InitTraversal(sit); (light = lc->GetNextLight(sit));)
  {
    if (!(light->GetSwitch() > 0))
    {
      continue;
    }
    if (count >= this->MaximumNumberOfLights)
    {
      if (!warned)
      {
        vtkWarningMacro("More lights than the OpenGL implementation can hold ("
          << this->MaximumNumberOfLights << "); the rest are ignored.");
        warned = true;
      }
      continue;
    }
    const double* dColor = light->GetDiffuseColor();
    const double intensity = light->GetIntensity();
    double lfp[3], lp[3];
    light->GetTransformedFocalPoint(lfp);
    light->GetTransformedPosition(lp);
    double dir[3] = { lfp[0] - lp[0], lfp[1] - lp[1], lfp[2] - lp[2] };
    if (!(vtkMath::Normalize(dir) > 0.0))
    {
      dir[0] = dir[1] = 0.0;
      dir[2] = -1.0; // a light whose position is its focal point shines along the view axis
    }
    double dirVC[3], posVC[3];
    viewTF->TransformNormal(dir, dirVC);
    viewTF->TransformPoint(lp, posVC);
    if (!light->LightTypeIsSceneLight() && userTF)
    {
      double tmp[3];
      userTF->TransformNormal(dirVC, tmp);
      std::copy(tmp, tmp + 3, dirVC);
      userTF->TransformPoint(posVC, tmp);
      std::copy(tmp, tmp + 3, posVC);
    }
    vtkMath::Normalize(dirVC);
    const double* att = light->GetAttenuationValues();
    const bool positional = light->GetPositional() != 0;
    const float texels[16] = { static_cast<float>(dColor[0] * intensity),
      static_cast<float>(dColor[1] * intensity), static_cast<float>(dColor[2] * intensity),
      positional ? 1.f : 0.f, //
      static_cast<float>(dirVC[0]), static_cast<float>(dirVC[1]), static_cast<float>(dirVC[2]),
      static_cast<float>(light->GetConeAngle()), //
      static_cast<float>(posVC[0]), static_cast<float>(posVC[1]), static_cast<float>(posVC[2]),
      static_cast<float>(light->GetExponent()), //
      static_cast<float>(att[0]), static_cast<float>(att[1]), static_cast<float>(att[2]), 0.f };
    this->LightData.insert(this->LightData.end(), texels, texels + 16);
    headlights += light->LightTypeIsHeadlight() ? 1 : 0;
    anyPositional = anyPositional || positional;
    ++count;
  }
  this->NumberOfLights = count;
  // VTK's lighting complexity 1: exactly one enabled light, a non-positional headlight.
  this->HeadlightOnly = (count == 1 && headlights == 1 && !anyPositional) ? 1 : 0;

  if (this->LightData.empty())
  {
    this->LightData.assign(16, 0.f); // a texture buffer may not be empty; never read
  }
  if (!this->LightBuffer)
  {
    this->LightBuffer = vtkOpenGLBufferObject::New();
    this->LightBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
  }
  if (!this->LightTexture)
  {
    this->LightTexture = vtkTextureObject::New();
  }
  this->LightTexture->SetContext(renWin);
  this->LightBuffer->Upload(this->LightData, vtkOpenGLBufferObject::TextureBuffer);
  const unsigned int texels = static_cast<unsigned int>(this->LightData.size() / 4);
  if (texels != this->LightTextureTexels)
  {
    this->LightTexture->CreateTextureBuffer(texels, 4, VTK_FLOAT, this->LightBuffer);
    this->LightTextureTexels = texels;
  }
}

//------------------------------------------------------------------------------
void vtkStylizeLightingPass::Render(const vtkRenderState* s)
{
  if (!this->DelegatePass)
  {
    vtkNew<vtkRenderStepsPass> steps;
    this->SetDelegatePass(steps);
  }
  this->RenderWithLighting(s, this->DelegatePass);
}

//------------------------------------------------------------------------------
void vtkStylizeLightingPass::RenderWithLighting(const vtkRenderState* s, vtkRenderPass* delegate)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!delegate)
  {
    vtkWarningMacro("no delegate pass");
    return;
  }
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin)
  {
    return;
  }

  // VTK creates a headlight when no light is on; do it first so that it is packed too.
  vtkLightCollection* lc = ren->GetLights();
  int enabled = 0;
  vtkCollectionSimpleIterator sit;
  vtkLight* light;
  for (lc->InitTraversal(sit); (light = lc->GetNextLight(sit));)
  {
    enabled += light->GetSwitch() > 0 ? 1 : 0;
  }
  if (!enabled && ren->GetAutomaticLightCreation())
  {
    ren->CreateLight();
    enabled = 1;
  }
  this->UpdateLightGeometry(ren); // camera-following lights to their place for this frame
  this->UploadLights(ren, renWin);
  if (this->Model != this->ShaderModel || this->HeadlightOnly != this->ShaderHeadlightOnly)
  {
    // One program per model and light class (VTK's single headlight, or any other set of
    // lights): the mappers switch programs (GetShaderStageMTime()), each built once and then
    // found in the window's shader cache; the light count never changes the program.
    this->ShaderModel = this->Model;
    this->ShaderHeadlightOnly = this->HeadlightOnly;
    this->ModelTime.Modified();
  }

  // Visible depth range, for the depth-dependent gray levels: the visible props' bounds in view
  // space, limited to the clipping range. Independent of how far the near plane is pushed.
  vtkCamera* cam = ren->GetActiveCamera();
  double clip[2];
  cam->GetClippingRange(clip);
  double bounds[6];
  ren->ComputeVisiblePropBounds(bounds);
  double dmin = clip[0], dmax = clip[1];
  if (vtkMath::AreBoundsInitialized(bounds))
  {
    vtkMatrix4x4* view = cam->GetViewTransformMatrix();
    double lo = VTK_DOUBLE_MAX, hi = -VTK_DOUBLE_MAX;
    for (int c = 0; c < 8; ++c)
    {
      double p[4] = { bounds[c & 1], bounds[2 + ((c >> 1) & 1)], bounds[4 + ((c >> 2) & 1)], 1.0 };
      double q[4];
      view->MultiplyPoint(p, q);
      lo = std::min(lo, -q[2]);
      hi = std::max(hi, -q[2]);
    }
    dmin = std::max(lo, clip[0]);
    dmax = std::min(hi, clip[1]);
    if (!(dmax > dmin))
    {
      dmin = clip[0];
      dmax = clip[1];
    }
  }
  this->DepthRange[0] = dmin;
  this->DepthRange[1] = dmax;

  // The mapper emits normals and view-space positions only when it believes the scene is lit.
  // With no light on, a zero-intensity carrier light keeps them; it is not packed and so it
  // contributes nothing, and it is removed right after the delegate has rendered.
  const bool carrier = (enabled == 0);
  if (carrier)
  {
    if (!this->CarrierLight)
    {
      this->CarrierLight = vtkLight::New();
      this->CarrierLight->SetLightTypeToHeadlight();
      this->CarrierLight->SetIntensity(0.0);
    }
    ren->AddLight(this->CarrierLight);
  }

  this->LightTexture->Activate();
  this->PreRender(s);
  delegate->Render(s);
  this->NumberOfRenderedProps += delegate->GetNumberOfRenderedProps();
  this->PostRender(s);
  this->LightTexture->Deactivate();

  if (carrier)
  {
    ren->RemoveLight(this->CarrierLight);
  }
  vtkOpenGLCheckErrorMacro("failed after vtkStylizeLightingPass::Render");
}

//------------------------------------------------------------------------------
void vtkStylizeLightingPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
  if (this->LightTexture)
  {
    this->LightTexture->ReleaseGraphicsResources(w);
    this->LightTexture->Delete();
    this->LightTexture = nullptr;
  }
  if (this->LightBuffer)
  {
    this->LightBuffer->ReleaseGraphicsResources();
    this->LightBuffer->Delete();
    this->LightBuffer = nullptr;
  }
  this->LightTextureTexels = 0;
  this->LightSignature = 0;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkStylizeLightingPass::GetShaderStageMTime()
{
  return this->ModelTime.GetMTime();
}

//------------------------------------------------------------------------------
bool vtkStylizeLightingPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    return true;
  }
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (actor && actor->GetProperty()->GetInterpolation() == VTK_PBR)
  {
    return true; // keep VTK's physically based lighting
  }
  // Hide the tags from the mapper so it does not generate its per-light code.
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Dec", LightDecTag, false);
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Impl", LightImplTag, false);
  return true;
}

//------------------------------------------------------------------------------
bool vtkStylizeLightingPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  if (fragmentShader.find(LightImplTag) == std::string::npos)
  {
    return true;
  }
  const bool lit = fragmentShader.find("normalVCVSOutput") != std::string::npos &&
    fragmentShader.find("vec4 vertexVC =") != std::string::npos &&
    fragmentShader.find("specularPower") != std::string::npos;
  if (lit)
  {
    vtkStylizeShaderUtilities::InjectCommon(fragmentShader);
    // (the colour comes from an array: point colours, or a colour map's texture or buffer, which
    // VTK 9.1's mapper reads into texColor)
    const bool dataColors = fragmentShader.find("vertexColorVSOutput") != std::string::npos ||
      fragmentShader.find("vec4 texColor =") != std::string::npos;
    vtkShaderProgram::Substitute(fragmentShader, LightDecTag,
      "#define STYLIZE_MODEL " + std::to_string(this->Model) + "\n" +
        (this->HeadlightOnly ? "#define STYLIZE_HEADLIGHT_ONLY\n" : "") +
        (dataColors ? "#define STYLIZE_DATA_COLORS\n" : "") + vtkStylizeLightingDec,
      false);
    vtkShaderProgram::Substitute(fragmentShader, LightImplTag,
      std::string(vtkStylizeLightingImpl) + "\n  //VTK::Light::Impl", false);
  }
  else
  {
    // Unlit primitives (lighting off, lines or points without normals): as VTK renders them.
    vtkShaderProgram::Substitute(fragmentShader, LightDecTag, "", false);
    vtkShaderProgram::Substitute(fragmentShader, LightImplTag,
      "  gl_FragData[0] = vec4(ambientColor + diffuseColor, opacity);\n  //VTK::Light::Impl",
      false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkStylizeLightingPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  if (!program->IsUniformUsed("stylizeColorMode") || !this->LightTexture)
  {
    return true;
  }
  if (program->IsUniformUsed("stylizeLights"))
  {
    program->SetUniformi("stylizeLights", this->LightTexture->GetTextureUnit());
  }
  program->SetUniformi("stylizeLightCount", this->NumberOfLights);
  // (LightData holds at least one light's 16 floats: the colour, then the direction at 4)
  program->SetUniform3f("stylizeHeadlightColor", this->LightData.data());
  program->SetUniform3f("stylizeHeadlightIncident", this->LightData.data() + 4);
  program->SetUniformf("stylizeSubjectFactor",
    static_cast<float>(ActorValue(prop, SUBJECT_FACTOR(), this->SubjectFactor, 0.0, 1.0)));
  program->SetUniformf("stylizeLevelsNear",
    static_cast<float>(ActorValue(prop, GRAY_LEVELS_NEAR(), this->GrayLevelsNear, 0.0, 100.0)));
  program->SetUniformf("stylizeLevelsFar",
    static_cast<float>(ActorValue(prop, GRAY_LEVELS_FAR(), this->GrayLevelsFar, 0.0, 100.0)));
  program->SetUniformi("stylizeColorMode", this->ColorMode);
  program->SetUniformi(
    "stylizeEmitted", ActorValue(prop, EMITTED_COLORS(), 0.0, 0.0, 1.0) >= 0.5 ? 1 : 0);
  program->SetUniformi("stylizeSolidColorTones", this->SolidColorTones ? 1 : 0);
  program->SetUniformf("stylizeSolidColorWhite", static_cast<float>(this->SolidColorWhite));
  program->SetUniformf("stylizeSpecularGain",
    static_cast<float>(ActorValue(prop, SPECULAR_GAIN(), this->SpecularGain, 0.0, 100.0)));
  const float range[2] = { static_cast<float>(this->DepthRange[0]),
    static_cast<float>(this->DepthRange[1]) };
  program->SetUniform2f("stylizeDepthRange", range);
  program->SetUniformf("stylizeScattering", static_cast<float>(this->Scattering));
  program->SetUniformf("stylizeOcclusion", static_cast<float>(this->SpecularOcclusion));
  return true;
}
