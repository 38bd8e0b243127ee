// Numeric test: the GLSL lighting models equal a CPU reference of the same formulas (GLM, double
// precision) at probe pixels, to within 1/255. The G-buffer (full precision) gives, per pixel,
// the normal and view-space position the shader used and the colour it produced; the CPU
// evaluates the model there from the scene description (material, lights, camera), computed
// independently of the pass's own light packing.
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeTestUtilities.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

using namespace stylizetest;
using glm::dvec3;

namespace
{
struct RefLight
{
  dvec3 Color; // colour * intensity
  bool Positional = false;
  dvec3 Dir; // direction the light shines along, view space, unit
  double Cone = 180.0;
  dvec3 Pos;
  double Exponent = 1.0;
  dvec3 Att{ 1, 0, 0 };
};

struct RefMaterial
{
  dvec3 Ambient, Diffuse, Specular; // intensity-weighted colours, as in VTK's shader
  double SpecPow, Ka, Kd;
};

struct RefParams
{
  int Model = 0;
  double P1 = 0, LevelsNear = 4, LevelsFar = 2, Gain = 1.5, S = 1, M = 1;
  double DepthNear = 0, DepthFar = 1;
  bool HeadlightOnly = false;
};

double SafePow(double x, double e)
{
  if (!(e > 0))
  {
    return 1.0;
  }
  return x > 0 ? std::pow(x, e) : 0.0;
}

// Set when a probe sits on a discontinuity (band edge, terminator, cone edge): skipped.
bool Ambiguous = false;

void Evaluate(const RefLight& l, const dvec3& P, dvec3& incident, double& atten)
{
  atten = 1.0;
  if (!l.Positional)
  {
    incident = l.Dir;
    return;
  }
  dvec3 d = P - l.Pos;
  double dist = glm::length(d);
  incident = dist > 0 ? d / dist : l.Dir;
  double denom = l.Att.x + l.Att.y * dist + l.Att.z * dist * dist;
  atten = denom > 0 ? 1.0 / denom : 0.0;
  if (l.Cone < 90.0)
  {
    double coneDot = glm::dot(incident, l.Dir);
    double c = std::cos(glm::radians(l.Cone));
    Ambiguous = Ambiguous || std::abs(coneDot - c) < 1e-4;
    atten = coneDot >= c ? atten * SafePow(coneDot, l.Exponent) : 0.0;
  }
}

dvec3 Shade(const RefParams& p, const RefMaterial& m, const std::vector<RefLight>& lights,
  const dvec3& N, const dvec3& P, bool parallel)
{
  dvec3 toViewer = parallel ? dvec3(0, 0, 1) : -P;
  dvec3 V = glm::normalize(toViewer);
  if (p.Model == 0)
  {
    if (lights.empty())
    {
      return m.Ambient + m.Diffuse;
    }
    if (p.HeadlightOnly)
    {
      double df = std::max(0.0, N.z);
      double sf = SafePow(df, m.SpecPow);
      return m.Ambient + df * m.Diffuse * lights[0].Color + sf * m.Specular * lights[0].Color;
    }
    dvec3 Vv = glm::normalize(-P); // VTK's own view vector, also in parallel projection
    dvec3 diffuse(0), specular(0);
    for (const auto& l : lights)
    {
      dvec3 inc;
      double att;
      Evaluate(l, P, inc, att);
      double ndl = glm::dot(N, -inc);
      Ambiguous = Ambiguous || std::abs(ndl) < 1e-4;
      double df = std::max(0.0, att * ndl);
      diffuse += df * l.Color;
      double sf = (df > 0 ? 1.0 : 0.0) * att *
        SafePow(std::max(0.0, glm::dot(glm::reflect(inc, N), Vv)), m.SpecPow);
      specular += sf * l.Color;
    }
    return m.Ambient + diffuse * m.Diffuse + specular * m.Specular;
  }
  dvec3 D(0), S(0);
  for (const auto& l : lights)
  {
    dvec3 inc;
    double att;
    Evaluate(l, P, inc, att);
    dvec3 L = -inc;
    double ndl = glm::dot(N, L);
    Ambiguous = Ambiguous || std::abs(ndl) < 1e-4;
    D += l.Color * (att * std::max(0.0, ndl));
    dvec3 H = glm::normalize(L + V);
    S +=
      l.Color * (att * (ndl >= 0 ? 1.0 : 0.0) * SafePow(std::max(0.0, glm::dot(N, H)), m.SpecPow));
  }
  if (p.Model == 2)
  {
    return m.Ambient + std::sqrt(p.S) * D * m.Diffuse + p.M * S * m.Specular;
  }
  // Comic
  double I = std::min(std::max(m.Ka, 0.0), 1.0);
  double La = p.P1 + I - 2 * p.P1 * I;
  dvec3 diffuseBase = m.Kd > 1e-6 ? m.Diffuse / m.Kd : dvec3(0);
  dvec3 ambientBase = m.Ka > 1e-6 ? m.Ambient / m.Ka : diffuseBase;
  double span = p.DepthFar - p.DepthNear;
  double t = span > 0 ? std::min(std::max((-P.z - p.DepthNear) / span, 0.0), 1.0) : 0.0;
  double pd = p.LevelsNear + (p.LevelsFar - p.LevelsNear) * t;
  double pmax = std::max(std::max(p.LevelsNear, p.LevelsFar), 1.0);
  double Dmax = std::max(D.x, std::max(D.y, D.z));
  double x = pd * m.Kd * Dmax;
  Ambiguous = Ambiguous || (x > 0 && std::abs(x - std::round(x)) < 2e-3);
  double q = std::floor(x) / pmax;
  dvec3 tint = Dmax > 0 ? D / Dmax : dvec3(0);
  return La * ambientBase + q * tint * diffuseBase + p.Gain * S * m.Specular;
}

glm::dmat4 ViewMatrix(vtkCamera* cam)
{
  double* p = cam->GetPosition();
  double* f = cam->GetFocalPoint();
  double* u = cam->GetViewUp();
  return glm::lookAt(dvec3(p[0], p[1], p[2]), dvec3(f[0], f[1], f[2]), dvec3(u[0], u[1], u[2]));
}

// Scene lights in world coordinates; converted to view space with the reference view matrix.
struct WorldLight
{
  dvec3 Pos, Focal, Color;
  bool Positional;
  double Cone, Exponent;
  dvec3 Att;
};

/** The set-up's lights added to the renderer ("scene": four scene lights, "none": none). */
std::vector<WorldLight> AddWorldLights(vtkRenderer* ren, const std::string& setup)
{
  std::vector<WorldLight> world;
  if (setup == "scene")
  {
    ren->AutomaticLightCreationOff();
    world.push_back({ { 3, 4, 5 }, { 0, 0, 0 }, { 0.9, 0.8, 0.7 }, false, 30, 1, { 1, 0, 0 } });
    world.push_back({ { -4, 1, 2 }, { 0, 0, 0 }, { 0.3, 0.4, 0.6 }, false, 30, 1, { 1, 0, 0 } });
    world.push_back(
      { { 0, 2.5, 3 }, { 0, 0, 0 }, { 0.8, 0.7, 0.5 }, true, 180, 1, { 0.3, 0.1, 0.05 } });
    world.push_back({ { 0.5, 3, 1.5 }, { 0.3, 0, 0 }, { 1, 1, 0.6 }, true, 20, 3, { 1, 0, 0 } });
    for (const auto& w : world)
    {
      vtkNew<vtkLight> l;
      l->SetLightTypeToSceneLight();
      l->SetPosition(w.Pos.x, w.Pos.y, w.Pos.z);
      l->SetFocalPoint(w.Focal.x, w.Focal.y, w.Focal.z);
      l->SetDiffuseColor(w.Color.x, w.Color.y, w.Color.z);
      l->SetIntensity(1.0);
      l->SetPositional(w.Positional);
      l->SetConeAngle(w.Cone);
      l->SetExponent(w.Exponent);
      l->SetAttenuationValues(w.Att.x, w.Att.y, w.Att.z);
      ren->AddLight(l);
    }
  }
  else if (setup == "none")
  {
    ren->AutomaticLightCreationOff();
  }
  return world;
}

/** The reference's lights in view space (the headlight, or the scene lights through `view`). */
std::vector<RefLight> ReferenceLights(const std::string& setup,
  const std::vector<WorldLight>& world, const glm::dmat4& view, RefParams& params)
{
  std::vector<RefLight> lights;
  if (setup == "headlight")
  {
    RefLight l;
    l.Color = dvec3(1);
    l.Dir = dvec3(0, 0, -1);
    lights.push_back(l);
    params.HeadlightOnly = true;
  }
  for (const auto& w : world)
  {
    RefLight l;
    l.Color = w.Color;
    l.Positional = w.Positional;
    l.Dir = glm::normalize(glm::dmat3(view) * glm::normalize(w.Focal - w.Pos));
    l.Pos = dvec3(view * glm::dvec4(w.Pos, 1.0));
    l.Cone = w.Cone;
    l.Exponent = w.Exponent;
    l.Att = w.Att;
    lights.push_back(l);
  }
  return lights;
}

/**
 * Every 7th surface pixel against the CPU reference (within 1/255 per channel); probes on a
 * discontinuity are skipped. Returns the largest difference.
 */
double CompareWithReference(vtkFloatArray* color, vtkFloatArray* normal, vtkFloatArray* position,
  const RefParams& params, const RefMaterial& m, const std::vector<RefLight>& lights, bool parallel,
  int& probes, int& skipped)
{
  double worst = 0;
  const vtkIdType n = color->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; i += 7)
  {
    double nv[4], pv[4], cv[4];
    normal->GetTuple(i, nv);
    position->GetTuple(i, pv);
    color->GetTuple(i, cv);
    if (nv[3] != 1.0)
    {
      continue;
    }
    Ambiguous = false;
    dvec3 ref =
      Shade(params, m, lights, dvec3(nv[0], nv[1], nv[2]), dvec3(pv[0], pv[1], pv[2]), parallel);
    ref = glm::clamp(ref, 0.0, 1.0);
    if (Ambiguous)
    {
      ++skipped;
      continue;
    }
    ++probes;
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::abs(ref[c] - cv[c]);
      if (d > worst)
      {
        worst = d;
      }
      if (d > 1.0 / 255.0 && stylizetest::Failures < 20)
      {
        STYLIZE_CHECK(d <= 1.0 / 255.0, "pixel %lld channel %d: GPU %.5f CPU %.5f",
          static_cast<long long>(i), c, cv[c], ref[c]);
      }
    }
  }
  return worst;
}

int RunCase(int model, const std::string& setup, bool parallel, bool perActor)
{
  auto win = MakeWindow(240, 200);
  vtkNew<vtkRenderer> ren;
  win->AddRenderer(ren);
  ren->SetBackground(0.2, 0.2, 0.2);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetPosition(0.3, -0.2, 0.1);
  actor->SetScale(1.2, 1.0, 0.9);
  vtkProperty* prop = actor->GetProperty();
  prop->SetColor(0.8, 0.5, 0.3);
  prop->SetAmbient(0.2);
  prop->SetDiffuse(0.7);
  prop->SetSpecular(0.5);
  prop->SetSpecularColor(1.0, 0.9, 0.8);
  prop->SetSpecularPower(20);
  ren->AddActor(actor);

  vtkNew<vtkStylizeLightingPass> lighting;
  lighting->SetModel(model);
  lighting->SetSubjectFactor(0.3);
  lighting->SetGrayLevelsNear(5);
  lighting->SetGrayLevelsFar(2);
  lighting->SetSpecularGain(1.7);
  lighting->SetScattering(0.6);
  lighting->SetSpecularOcclusion(0.8);
  RefParams params;
  params.Model = model;
  params.P1 = 0.3;
  params.LevelsNear = 5;
  params.LevelsFar = 2;
  params.Gain = 1.7;
  params.S = 0.6;
  params.M = 0.8;
  if (perActor)
  {
    vtkStylizeLightingPass::SetActorSubjectFactor(actor, 0.9);
    vtkStylizeLightingPass::SetActorGrayLevels(actor, 7, 3);
    vtkStylizeLightingPass::SetActorSpecularGain(actor, 3.0);
    params.P1 = 0.9;
    params.LevelsNear = 7;
    params.LevelsFar = 3;
    params.Gain = 3.0;
  }
  vtkNew<vtkStylizeGBufferPass> gbuffer;
  gbuffer->SetLightingPass(lighting);
  gbuffer->SetChannels(vtkStylizeGBufferPass::NORMAL | vtkStylizeGBufferPass::POSITION);
  gbuffer->SetPrecision(vtkStylizeGBufferPass::FULL);
  ren->SetPass(gbuffer);

  const std::vector<WorldLight> world = AddWorldLights(ren, setup);

  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(1.0, 1.5, 5.0);
  cam->SetFocalPoint(0.2, 0, 0);
  cam->SetViewUp(0, 1, 0);
  cam->SetParallelProjection(parallel);
  cam->SetParallelScale(1.6);
  ren->ResetCameraClippingRange();
  win->Render();

  vtkNew<vtkFloatArray> color, normal, position;
  gbuffer->DownloadChannel(vtkStylizeGBufferPass::COLOR_BUFFER, color);
  gbuffer->DownloadChannel(vtkStylizeGBufferPass::NORMAL_BUFFER, normal);
  gbuffer->DownloadChannel(vtkStylizeGBufferPass::POSITION_BUFFER, position);
  CheckFinite(color, "colour");
  CheckFinite(normal, "normal");
  CheckFinite(position, "position");

  // Reference description of the scene.
  RefMaterial m;
  m.Ka = 0.2;
  m.Kd = 0.7;
  m.Ambient = 0.2 * dvec3(0.8, 0.5, 0.3);
  m.Diffuse = 0.7 * dvec3(0.8, 0.5, 0.3);
  m.Specular = 0.5 * dvec3(1.0, 0.9, 0.8);
  m.SpecPow = 20;
  glm::dmat4 view = ViewMatrix(cam);
  const std::vector<RefLight> lights = ReferenceLights(setup, world, view, params);
  // Visible depth range: the actor's bounds in view space, within the clipping range.
  double b[6], clip[2];
  actor->GetBounds(b);
  cam->GetClippingRange(clip);
  double lo = 1e300, hi = -1e300;
  for (int c = 0; c < 8; ++c)
  {
    glm::dvec4 q = view * glm::dvec4(b[c & 1], b[2 + ((c >> 1) & 1)], b[4 + ((c >> 2) & 1)], 1.0);
    lo = std::min(lo, -q.z);
    hi = std::max(hi, -q.z);
  }
  params.DepthNear = std::max(lo, clip[0]);
  params.DepthFar = std::min(hi, clip[1]);

  int probes = 0, skipped = 0;
  const double worst =
    CompareWithReference(color, normal, position, params, m, lights, parallel, probes, skipped);
  std::printf(
    "model %s, lights %s, %s%s: %d probes (%d on discontinuities skipped), max |GPU-CPU| = "
    "%.2e (%.3f levels of 255)\n",
    vtkStylizeLightingPass::GetModelName(model), setup.c_str(),
    parallel ? "parallel" : "perspective", perActor ? ", per-actor settings" : "", probes, skipped,
    worst, worst * 255);
  STYLIZE_CHECK(probes > 300, "too few probes: %d", probes);
  STYLIZE_CHECK(lighting->GetNumberOfLights() == static_cast<int>(lights.size()),
    "packed %d lights, expected %d", lighting->GetNumberOfLights(),
    static_cast<int>(lights.size()));
  win->Finalize();
  return 0;
}
}

int TestLightingReference(int argc, char* argv[])
{
  Args args = ParseArgs(argc, argv);
  const int model = vtkStylizeLightingPass::GetModelFromName(
    args.Positional.empty() ? "standard" : args.Positional[0].c_str());
  for (const char* setup : { "headlight", "scene", "none" })
  {
    for (bool parallel : { false, true })
    {
      RunCase(model, setup, parallel, false);
    }
  }
  if (model == vtkStylizeLightingPass::COMIC)
  {
    RunCase(model, "scene", false, true);
  }
  return stylizetest::Failures == 0 ? 0 : 1;
}
