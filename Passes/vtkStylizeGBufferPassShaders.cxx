// The G-buffer pass's shader hooks (vtkOpenGLRenderPass): the channels each mapper's fragment
// shader writes after lighting, the depth it stores, and their uniforms.
#include "vtkStylizeGBufferPass.h"

#include "vtkMatrix4x4.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProp3D.h"
#include "vtkShaderProgram.h"
#include "vtkStylizeDepthPeeler.h"
#include "vtkStylizeGBufferPassInternals.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkStylizeVolumeSolidCut.h"

#include "vtkStylizeGBufferDirectionFS.h"
#include "vtkStylizeGBufferImpl.h"

#include <cmath>
#include <cstring>
#include <sstream>
#include <string>

namespace
{
const char* const GBufferTag = "//VTK::StylizeGBuffer::Impl";
// The DIRECTION channel's attribute on the helpers of VTK's composite data mapper.
const char* const TangentDeclaration = "in vec3 tangentMC; // the DIRECTION channel's source\n";
// How far behind a volume's cut solid surface it looks solid (in the prop's coordinates, times
// stylizeLooksSolidScale in the view's), and the camera's clipping range (the window depth).
const std::string LooksSolidDeclaration = "in float stylizeLooksSolidVSOutput;\n"
                                          "uniform float stylizeLooksSolidScale;\n"
                                          "uniform vec2 stylizeClippingRange;\n";

/**
 * The channels beyond the colour, in attachment order: the bit that requests each and the name
 * of its line in vtkStylizeGBufferImpl.glsl (gl_FragData[NAME_INDEX] = NAME_VALUE).
 */
struct ChannelEntry
{
  int Bit;
  const char* Name;
};
const ChannelEntry ChannelTable[] = {
  { vtkStylizeGBufferPass::NORMAL, "NORMAL" },
  { vtkStylizeGBufferPass::POSITION, "POSITION" },
  { vtkStylizeGBufferPass::LINEAR_DEPTH, "LINEAR_DEPTH" },
  { vtkStylizeGBufferPass::DIRECTION, "DIRECTION" },
};
}

//------------------------------------------------------------------------------
vtkMTimeType vtkStylizeGBufferPass::GetShaderStageMTime()
{
  return this->ShaderStageTime.GetMTime();
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::PreReplaceShaderValues(std::string& vertexShader, std::string&,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{
  if (vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    if (this->Channels & DIRECTION)
    {
      // The direction attribute's outer product, in view coordinates (sign-free interpolation),
      // of the unit direction: a zero vector (no direction there) weighs nothing. The helpers of
      // VTK's composite data mapper upload no mapped array, only the standard attributes: there
      // the direction is the point data's tangents (VTK's tangentMC).
      const bool tangents = mapper->IsA("vtkCompositeMapperHelper2") != 0;
      const std::string attribute = tangents ? "tangentMC" : "stylizeDirectionMC";
      const std::string declaration =
        tangents ? std::string(TangentDeclaration) : "in vec3 stylizeDirectionMC;\n";
      vtkShaderProgram::Substitute(vertexShader, "//VTK::System::Dec",
        "//VTK::System::Dec\n" + declaration +
          "uniform mat3 stylizeDirectionMCVC;\n"
          "out vec3 stylizeDirDiagVSOutput;\nout vec3 stylizeDirOffVSOutput;\n",
        false);
      vtkShaderProgram::Substitute(vertexShader, "//VTK::Normal::Impl",
        "//VTK::Normal::Impl\n  vec3 stylizeDirVC = stylizeDirectionMCVC * " + attribute +
          ";\n"
          "  float stylizeDirLength = length(stylizeDirVC);\n"
          "  stylizeDirVC = stylizeDirLength > 0.0 && !isinf(stylizeDirLength) ?\n"
          "    stylizeDirVC / stylizeDirLength : vec3(0.0);\n"
          "  stylizeDirDiagVSOutput = stylizeDirVC * stylizeDirVC;\n"
          "  stylizeDirOffVSOutput = stylizeDirVC.xxy * stylizeDirVC.yzz;\n",
        false);
    }
    // A volume's solid surface cut to where it looks solid (vtkStylizeVolumeSolidCut) stores the
    // depth of where its view ray's opacity reaches one half: opaque geometry in the material in
    // front of that (streamlines through a glowing region) shows through, as in VTK's picture.
    auto* polyMapper = vtkPolyDataMapper::SafeDownCast(mapper);
    vtkPolyData* input = polyMapper ? polyMapper->GetInput() : nullptr;
    if (input && input->GetPointData()->GetArray(vtkStylizeVolumeSolidCut::LooksSolidAt))
    {
      vtkShaderProgram::Substitute(vertexShader, "//VTK::System::Dec",
        "//VTK::System::Dec\nin float stylizeLooksSolid;\nout float stylizeLooksSolidVSOutput;\n",
        false);
      vtkShaderProgram::Substitute(vertexShader, "//VTK::PositionVC::Impl",
        "//VTK::PositionVC::Impl\n  stylizeLooksSolidVSOutput = stylizeLooksSolid;\n", false);
      vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
        "//VTK::System::Dec\n" + LooksSolidDeclaration, false);
    }
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Impl",
      std::string("//VTK::Light::Impl\n  ") + GBufferTag, false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::PostReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  // The mapper declares tangentMC itself when it maps normals from a texture: not twice.
  const std::size_t own = vertexShader.find(TangentDeclaration);
  if (own != std::string::npos && vertexShader.find("in vec3 tangentMC;\n") != std::string::npos)
  {
    vertexShader.erase(own, std::strlen(TangentDeclaration));
  }
  if (fragmentShader.find(GBufferTag) == std::string::npos)
  {
    return true;
  }
  std::string code = this->ChannelCode(vertexShader, geometryShader, fragmentShader);
  const bool surface = fragmentShader.find("normalVCVSOutput") != std::string::npos &&
    fragmentShader.find("vec4 vertexVC =") != std::string::npos;
  // The depth the G-buffer stores: the window depth (VTK's own when its shader writes one) or,
  // after VTK's depth code (//VTK::Depth::Impl), the logarithmic depth that overrides it.
  // (VTK's template names gl_FragDepth in a comment: look for an assignment)
  std::string depth =
    fragmentShader.find("gl_FragDepth =") != std::string::npos ? "gl_FragDepth" : "gl_FragCoord.z";
  // (a volume's cut solid: the window depth where it looks solid, never in front of its own)
  const bool looksSolid =
    surface && fragmentShader.find(LooksSolidDeclaration) != std::string::npos;
  if (looksSolid)
  {
    // (the window depth's change from the fragment to there, added to its own)
    if (fragmentShader.find("uniform int cameraParallel;") == std::string::npos)
    {
      vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
        "//VTK::System::Dec\nuniform int cameraParallel;\n", false);
    }
    // (normalized device z: (f + n) / (f - n) + 2 f n / ((f - n) z) for a perspective view,
    // -(2 z + f + n) / (f - n) for a parallel one; z < 0 the view coordinate)
    code += "  vec3 stylizeRayVC = cameraParallel == 1 ? vec3(0.0, 0.0, -1.0) : "
            "normalize(vertexVC.xyz);\n"
            "  float stylizeSolidVCz = vertexVC.z + stylizeRayVC.z * stylizeLooksSolidScale * "
            "max(stylizeLooksSolidVSOutput, 0.0);\n"
            "  float stylizeNear = stylizeClippingRange.x, stylizeFar = stylizeClippingRange.y;\n"
            "  float stylizeDeeper = cameraParallel == 1 ? -(stylizeSolidVCz - vertexVC.z) / "
            "(stylizeFar - stylizeNear) : stylizeFar * stylizeNear / (stylizeFar - stylizeNear) * "
            "(1.0 / min(stylizeSolidVCz, -1e-30) - 1.0 / min(vertexVC.z, -1e-30));\n"
            "  float stylizeLooksSolidZ = clamp(gl_FragCoord.z + stylizeDeeper, gl_FragCoord.z, "
            "1.0);\n"
            "  gl_FragDepth = stylizeLooksSolidZ;\n";
    depth = "gl_FragDepth";
  }
  if (this->LogarithmicDepth)
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
      "//VTK::System::Dec\nuniform vec2 stylizeLogDepthRange;\n", false);
    const std::string window = looksSolid ? "stylizeLooksSolidZ" : "gl_FragCoord.z";
    const std::string z = surface && !looksSolid
      ? "-vertexVC.z"
      : "(2.0 * stylizeLogDepthRange.x * stylizeLogDepthRange.y / "
        "(stylizeLogDepthRange.y + stylizeLogDepthRange.x - "
        "(2.0 * " +
        window +
        " - 1.0) * (stylizeLogDepthRange.y - "
        "stylizeLogDepthRange.x)))";
    code += "  gl_FragDepth = clamp(log(max(" + z +
      ", stylizeLogDepthRange.x) / stylizeLogDepthRange.x) / log(stylizeLogDepthRange.y / "
      "stylizeLogDepthRange.x), 0.0, 1.0);\n";
    depth = "gl_FragDepth";
  }
  if (this->Internals->Peeler->GetLayerIndex() >= 0)
  {
    // A translucent layer (RenderTranslucentLayer()): only what lies in front of the opaque
    // depth and, when peeling, behind the previous layer's.
    code += this->Internals->Peeler->FragmentCode(fragmentShader, depth);
  }
  vtkShaderProgram::Substitute(fragmentShader, GBufferTag, code);
  return true;
}

//------------------------------------------------------------------------------
std::string vtkStylizeGBufferPass::ChannelCode(
  std::string& vertexShader, std::string& geometryShader, std::string& fragmentShader)
{
  const bool surface = fragmentShader.find("normalVCVSOutput") != std::string::npos &&
    fragmentShader.find("vec4 vertexVC =") != std::string::npos;
  // The lighting pass (when it shades this shader) defines stylizeN, the normal it used.
  const bool stylizeLit =
    surface && fragmentShader.find("//VTK::StylizeLight::Impl") != std::string::npos;
  const std::string shadingNormal = "stylizeShadingNormal(normalVCVSOutput, stylizeFaceN, "
                                    "cameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : -vertexVC.xyz)";
  // The value each requested channel writes, in the order of ChannelTable.
  std::string values[4];
  if (this->Channels & NORMAL)
  {
    if (!surface)
    {
      values[0] = "vec4(0.0)";
    }
    else if (stylizeLit)
    {
      values[0] = "vec4(stylizeN, 1.0)";
    }
    else
    {
      vtkStylizeShaderUtilities::InjectCommon(fragmentShader);
      values[0] = "vec4(" + shadingNormal + ", 1.0)";
    }
  }
  if (this->Channels & POSITION)
  {
    if (!surface)
    {
      values[1] = "vec4(0.0)";
    }
    else if (this->PositionSpace == OBJECT)
    {
      vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
        "//VTK::System::Dec\nuniform mat4 stylizeVCToMC;\n", false);
      values[1] = "vec4((stylizeVCToMC * vec4(vertexVC.xyz, 1.0)).xyz, 1.0)";
    }
    else
    {
      values[1] = "vec4(vertexVC.xyz, 1.0)";
    }
  }
  if (this->Channels & LINEAR_DEPTH)
  {
    // -1 marks a line or point without a surface normal (the background keeps 0)
    values[2] = surface ? "vec4(-vertexVC.z, 0.0, 0.0, 1.0)" : "vec4(-1.0, 0.0, 0.0, 1.0)";
  }
  if (this->Channels & DIRECTION)
  {
    // (a geometry shader, for wide lines, would not pass the tensor on)
    if (!surface || !geometryShader.empty() ||
      vertexShader.find("stylizeDirDiagVSOutput") == std::string::npos)
    {
      values[3] = "vec4(0.0)";
    }
    else
    {
      vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
        std::string("//VTK::System::Dec\n") + vtkStylizeGBufferDirectionFS, false);
      values[3] = "stylizeTensorDirection(" + (stylizeLit ? "stylizeN" : shadingNormal) + ")";
      if (!stylizeLit)
      {
        vtkStylizeShaderUtilities::InjectCommon(fragmentShader);
      }
    }
  }
  // Keep the template's line for each requested channel, with its literal attachment index.
  std::istringstream lines(vtkStylizeGBufferImpl);
  std::string line, code;
  int index = 1;
  while (std::getline(lines, line))
  {
    bool keep = true;
    for (int c = 0; c < 4; ++c)
    {
      const std::string name = ChannelTable[c].Name;
      if (line.find("[" + name + "_INDEX]") != std::string::npos)
      {
        keep = (this->Channels & ChannelTable[c].Bit) && !values[c].empty();
        if (keep)
        {
          vtkShaderProgram::Substitute(line, name + "_INDEX", std::to_string(index++));
          vtkShaderProgram::Substitute(line, name + "_VALUE", values[c]);
        }
        break;
      }
    }
    if (keep)
    {
      code += line + "\n";
    }
  }
  return code;
}

//------------------------------------------------------------------------------
void vtkStylizeGBufferPass::SetDepthMappingUniforms(vtkShaderProgram* program)
{
  if (program && program->IsUniformUsed("stylizeDepthMapping"))
  {
    const float mapping[3] = { static_cast<float>(this->DepthRange[0]),
      static_cast<float>(this->DepthRange[1]), this->LogarithmicDepth ? 1.0f : 0.0f };
    program->SetUniform3f("stylizeDepthMapping", mapping);
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeGBufferPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  if (!this->FrameBufferObject)
  {
    return true;
  }
  if (vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    this->FrameBufferObject->ActivateDrawBuffers(this->NumberOfAttachments);
  }
  else
  {
    this->FrameBufferObject->ActivateDrawBuffers(1);
  }
  this->Internals->Peeler->SetShaderParameters(program);
  if (program->IsUniformUsed("stylizeLogDepthRange"))
  {
    const float range[2] = { static_cast<float>(this->DepthRange[0]),
      static_cast<float>(this->DepthRange[1]) };
    program->SetUniform2f("stylizeLogDepthRange", range);
  }
  vtkProp3D* prop3D = vtkProp3D::SafeDownCast(prop);
  if (program->IsUniformUsed("stylizeDirectionMCVC"))
  {
    // model -> world -> view, the 3x3 part (directions are vectors), column-major for GLSL
    vtkMatrix4x4* m = this->Internals->Product;
    m->DeepCopy(this->Internals->View);
    if (prop3D)
    {
      vtkMatrix4x4::Multiply4x4(this->Internals->View, prop3D->GetMatrix(), m);
    }
    float columns[9];
    for (int c = 0; c < 3; ++c)
    {
      for (int r = 0; r < 3; ++r)
      {
        columns[c * 3 + r] = static_cast<float>(m->GetElement(r, c));
      }
    }
    program->SetUniformMatrix3x3("stylizeDirectionMCVC", columns);
  }
  if (program->IsUniformUsed("stylizeClippingRange"))
  {
    const float range[2] = { static_cast<float>(this->Internals->ClippingRange[0]),
      static_cast<float>(this->Internals->ClippingRange[1]) };
    program->SetUniform2f("stylizeClippingRange", range);
  }
  if (program->IsUniformUsed("stylizeLooksSolidScale"))
  {
    // the prop's length scale (its matrix's, taken as uniform)
    const double det = prop3D ? std::abs(prop3D->GetMatrix()->Determinant()) : 1.0;
    program->SetUniformf("stylizeLooksSolidScale", static_cast<float>(std::cbrt(det)));
  }
  if (program->IsUniformUsed("stylizeVCToMC"))
  {
    // view -> world (inverse camera view) -> model (inverse prop matrix), in double precision
    vtkMatrix4x4* m = this->Internals->Product;
    m->DeepCopy(this->Internals->InverseView);
    if (prop3D)
    {
      vtkMatrix4x4::Invert(prop3D->GetMatrix(), this->Internals->InverseModel);
      vtkMatrix4x4::Multiply4x4(this->Internals->InverseModel, m, m);
    }
    m->Transpose(); // vtkShaderProgram uploads row-major data as GLSL columns
    program->SetUniformMatrix("stylizeVCToMC", m);
  }
  return true;
}
