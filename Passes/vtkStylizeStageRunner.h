/**
 * @class   vtkStylizeStageRunner
 * @brief   Builds and runs the screen-space stages of a style.
 *
 * A style's stages share one GLSL source; each stage is that source with its own #define, one
 * program per stage, rebuilt only when the frame's defines change. The runner draws a stage's
 * full-screen quad into textures (its framebuffer) or into whatever framebuffer is bound, and
 * times each stage when timing is on (glFinish before and after: for benchmarks only).
 */

#ifndef vtkStylizeStageRunner_h
#define vtkStylizeStageRunner_h

#include "vtkObject.h"
#include "vtkStylizePassesModule.h" // for export macro

#include <chrono>           // for std::chrono
#include <functional>       // for std::function
#include <initializer_list> // for std::initializer_list
#include <memory>           // for std::unique_ptr
#include <string>           // for std::string
#include <vector>           // for std::vector

class vtkFloatArray;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkStylizeScreenQuad;
class vtkStylizeUniforms;
class vtkTextureObject;
class vtkWindow;

class VTKSTYLIZEPASSES_NO_EXPORT vtkStylizeStageRunner : public vtkObject
{
public:
  static vtkStylizeStageRunner* New();
  vtkTypeMacro(vtkStylizeStageRunner, vtkObject);

  /** The uniforms a stage sets (textures, numbers), given the program's binder. */
  using StageUniforms = std::function<void(vtkStylizeUniforms&)>;

  /**
   * The stages: `source` is the GLSL of all of them (after the shared GLSL), `mainCall` the
   * statement main() runs; `defines[i]` selects stage i ("" for none) and `names[i]` names it
   * in timings.
   */
  void SetStages(const std::string& source, const std::string& mainCall,
    const std::vector<std::string>& defines, const std::vector<std::string>& names);

  /** The frame's #defines, before every stage; the programs are rebuilt when they change. */
  void SetDefines(const std::string& defines);

  /** The window of the frame being rendered. */
  void SetWindow(vtkOpenGLRenderWindow* window) { this->Window = window; }
  vtkOpenGLRenderWindow* GetWindow() const { return this->Window; }

  /**
   * Runs `stage` into `targets` (colour attachments 0, 1, ...) over w x h pixels, without
   * blending. With `cullDepth` (a depth texture of w x h), the targets are cleared to zero and
   * an early depth test against it leaves the background's fragments unshaded. Returns false
   * when the stage's program does not build.
   */
  bool Run(int stage, std::initializer_list<vtkTextureObject*> targets, int w, int h,
    const StageUniforms& uniforms, vtkTextureObject* cullDepth = nullptr);

  /** Runs `stage` into the bound framebuffer with the current GL state. */
  bool RunHere(int stage, const StageUniforms& uniforms);

  /**
   * Copies all of texture `tex` into `rect` (x0, y0, x1, y1, window pixels) of the bound draw
   * framebuffer, nearest-neighbour scaled, under the current scissor (glBlitFramebuffer); timed
   * as `name`. False without the stages' framebuffer (no stage ran yet).
   */
  bool BlitHere(vtkTextureObject* tex, const int rect[4], const std::string& name);

  /** The stages' framebuffer (created on first use), for reading a texture back. */
  vtkOpenGLFramebufferObject* GetFramebuffer() const { return this->Framebuffer; }

  /** Reads texture `tex` back into `out`, RGBA floats; false without a framebuffer. */
  bool Download(vtkTextureObject* tex, vtkFloatArray* out);

  /**
   * Makes `fbo` (created on first use) the draw framebuffer, the current bindings saved for
   * RestorePreviousBindingsAndBuffers().
   */
  static vtkOpenGLFramebufferObject* BindFramebuffer(
    vtkOpenGLFramebufferObject*& fbo, vtkOpenGLRenderWindow* window);
  /** Releases and deletes `fbo`. */
  static void FreeFramebuffer(vtkOpenGLFramebufferObject*& fbo, vtkWindow* w);

  ///@{
  /** Whether a program failed to build since the last ResetFailure() (and notes one that did). */
  bool GetFailed() const { return this->Failed; }
  void NoteFailure(bool failed) { this->Failed = this->Failed || failed; }
  void ResetFailure() { this->Failed = false; }
  ///@}

  ///@{
  /** Stage timing: whether on; a timed block's start and end (no cost when off). */
  bool Timing = false;
  void TimeBegin();
  void TimeEnd(const std::string& name);
  void ClearTimes() { this->Times.clear(); }
  int GetNumberOfTimedStages() const { return static_cast<int>(this->Times.size()); }
  const char* GetTimedStageName(int i) const;
  double GetTimedStageMilliseconds(int i) const;
  int GetTimedStageRuns(int i) const;
  ///@}

  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkStylizeStageRunner();
  ~vtkStylizeStageRunner() override;

  /** Makes `stage`'s program current; nullptr (and a failure noted) when it does not build. */
  vtkShaderProgram* Prepare(int stage);

  struct StageTime
  {
    std::string Name;
    double Milliseconds = 0.0;
    int Runs = 0;
  };

  std::string Source;
  std::string MainCall;
  std::vector<std::string> StageDefines;
  std::vector<std::string> StageNames;
  std::string Defines;
  std::vector<std::string> Declarations; // one per stage
  std::vector<std::unique_ptr<vtkStylizeScreenQuad>> Quads;
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  bool Failed = false;
  std::vector<StageTime> Times;
  std::chrono::steady_clock::time_point TimingStart;

private:
  vtkStylizeStageRunner(const vtkStylizeStageRunner&) = delete;
  void operator=(const vtkStylizeStageRunner&) = delete;
};

#endif
