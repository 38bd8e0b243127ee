#include "vtkStylizeGBufferClearPass.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkStylizeGBufferPass.h"
#include "vtk_glew.h"

#include <algorithm>

vtkStandardNewMacro(vtkStylizeGBufferClearPass);

//------------------------------------------------------------------------------
void vtkStylizeGBufferClearPass::Render(const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* win = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkOpenGLState* ostate = win->GetState();
  const bool erased = ren->GetRenderWindow()->GetErase() && ren->GetErase();
  const GLfloat zero[4] = { 0.f, 0.f, 0.f, 0.f };
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  float flat[4];
  if (this->Layer)
  {
    // A translucent layer: no surface anywhere yet (alpha 0; the colour of a flat background
    // for the stages that read colour across a silhouette: the one the opaque scene's image
    // stands for where a compositor replaced the renderer's).
    if (this->UseImageBackground)
    {
      std::copy(this->ImageBackground, this->ImageBackground + 3, flat);
    }
    else if (!vtkStylizeGBufferPass::GetFlatBackground(ren, flat))
    {
      std::fill(flat, flat + 3, 0.f);
    }
    flat[3] = 0.f;
    glClearBufferfv(GL_COLOR, 0, flat);
  }
  else if (ren->Transparent() || !erased)
  {
    glClearBufferfv(GL_COLOR, 0, zero);
  }
  else if (vtkStylizeGBufferPass::GetFlatBackground(ren, flat))
  {
    flat[3] = static_cast<float>(ren->GetBackgroundAlpha());
    glClearBufferfv(GL_COLOR, 0, flat);
  }
  if (!erased || this->Layer)
  {
    const GLfloat one = 1.f;
    ostate->vtkglDepthMask(GL_TRUE);
    glClearBufferfv(GL_DEPTH, 0, &one);
  }
  for (unsigned int i = 1; i < this->Attachments; ++i)
  {
    glClearBufferfv(GL_COLOR, static_cast<GLint>(i), zero);
  }
}
